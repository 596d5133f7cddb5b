// Seed 002 Section 8.1.4 at the seed's size: the 3D heterogeneous cube
// (prm/cmpm/heterogeneous_cube_3d{,_full_newton,_fine}.prm: 80 coarse
// elements, 64,000 particles, four soft elliptic columns, 5 steps of 0.01 s
// under 5000 N/m^2 pulling the top up), first Newton step against full
// Newton in the local problem, both against BSMPM-fine; checked as the
// reduced 2D test (cmpm_heterogeneous_cube_check.h) with max r_u below 0.15
// (seed: 0.040, 0.031).

#include "../experiments/cmpm_heterogeneous_cube_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  cmpm_heterogeneous_cube_check::check<3>(0.15);
}
