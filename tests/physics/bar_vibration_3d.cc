// Period of the first axial mode of a free-free elastic bar in 3D (a bar one
// cell thick in y and z, nu = 0): explicit USL, APIC, quadratic B-splines,
// CFL 0.5. The relative error of the measured period against T = 2 L / c
// must fall under refinement, at second order. See bar_vibration.h.

#include "bar_vibration.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  bar_vibration::convergence_study<3>({8, 16, 32});
}
