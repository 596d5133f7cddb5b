// Seed 002 Section 8.1.1 at the seed's size: the 3D sheared cube
// (prm/cmpm/cube_shearing_3d{,_bsmpm,_linear}.prm: 216 coarse elements,
// 30^3 fine cells, 216,000 particles, 21 steps of 0.01 s) on cMPM, BSMPM and
// linear-kernel MPM, checked as the reduced 2D test
// (cmpm_cube_shearing_check.h): after cell crossing the linear kernel's
// stress along the line oscillates, BSMPM's and cMPM's stay smooth.

#include "../experiments/cmpm_cube_shearing_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  cmpm_cube_shearing_check::check<3>();
}
