// Seed 002 Section 8.2.1 reduced: the 2D analogue of the static
// three-material beam (prm/cmpm/three_material_beam_2d{,_fine}.prm: 8 x 1 m,
// fixed at both ends, 1000 N/m^2 on its top face, linear elastic, E 5e5 /
// 2e4 / 1e5 Pa in the middle inclusions, the outer ones and the matrix;
// cMPM on 32 x 4 coarse elements with the seed's L = H/3 and 10 x 10 local
// fine mesh) against the FE_Q(2) benchmark on the knot spans, checked by
// cmpm_three_material_beam_check.h: r_u of cMPM below 0.005 (seed, 3D:
// 0.003), r_sigma below 0.12 (seed: 0.048); and the seed's "Diagonal"
// baselines (multilinear coarse elements with diagonal blocks) ordered as in
// its Table 4. About 25 s.

#include "cmpm_three_material_beam_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  cmpm_three_material_beam_check::check<2>(0.005, 0.12, true, true);
}
