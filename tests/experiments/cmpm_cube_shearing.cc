// Seed 002 Section 8.1.1 reduced: the 2D analogue of the sheared cube
// (prm/cmpm/cube_shearing_2d{,_bsmpm,_linear}.prm: a unit square, rho 1e3,
// E 1e5, nu 0.4, bottom fixed, 3600 N/m^2 of shear along -x on the top
// face, 21 backward Euler steps of 0.01 s) on cMPM (6 x 6 coarse elements),
// quadratic B-spline MPM (BSMPM) and linear-kernel MPM on the 30 x 30 fine
// cells, the same 3600 particles. doc/experiments/cmpm_stress_line.py takes
// the von Mises stress along the row of particles at mid-height and its
// roughness R (RMS second difference over the mean). As the seed's Fig. 19
// shows, once particles have crossed cells (t = 0.15 and 0.21 s; the top
// has moved by more than a cell) the linear kernel's stress oscillates
// from particle to particle (R above 0.05) while BSMPM and cMPM stay smooth
// (R below 0.025), checked by cmpm_cube_shearing_check.h. About 5 s.

#include "cmpm_cube_shearing_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  cmpm_cube_shearing_check::check<2>();
}
