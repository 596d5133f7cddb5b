// Seed 002 Section 8.1.2 reduced: the 2D analogue of the heterogeneous
// bending beam (prm/cmpm/bending_beam_2d.prm, a 20 x 2 m beam with 40 soft
// elliptic inclusions, E 1e2 in E 1e5, clamped at both ends, gravity 25,
// 24 backward Euler steps to 0.6 s) on cMPM, BSMPM-fine and BSMPM-coarse,
// checked by cmpm_bending_beam_check.h: max r_u of cMPM below 0.03 and below
// half of BSMPM-coarse's, cMPM cheaper per step than BSMPM-fine. About 1 min.

#include "cmpm_bending_beam_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  cmpm_bending_beam_check::check<2>(0.03);
}
