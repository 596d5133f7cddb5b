// Seed 002 Section 8.1.4 reduced: the 2D analogue of the heterogeneous cube
// (prm/cmpm/heterogeneous_cube_2d{,_full_newton,_fine}.prm: a unit square,
// rho 10, nu 0.3, E 1e5 with four soft elliptic inclusions of E 1e2, bottom
// fixed, 5000 N/m^2 pulling its top face up, 5 backward Euler steps of
// 0.01 s) on cMPM with the first Newton step in the local problem (the
// seed's default), on cMPM with the full Newton local solve, and on
// BSMPM-fine, the reference (the same particles, the matching clamp). The
// seed finds the two local solves close (r_u 0.040 and 0.031 at
// t = 0.05 s) and the first step much cheaper (2.96 s against 392 s per
// step). Checked by cmpm_heterogeneous_cube_check.h, max r_u below 0.15.
// About 5 s.

#include "cmpm_heterogeneous_cube_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  cmpm_heterogeneous_cube_check::check<2>(0.15);
}
