// BFEMP Section 6.3, Brazilian disk / plane Hertz contact, reduced: runs
// prm/experiments/6_3_hertz/hertz_reduced.prm (the paper's disk, plates and
// contact parameters at dx = 0.05 with 2 x 2 particles per cell, the top
// plate at 1 m/s for 12 steps) with linear elasticity and with neo-Hookean
// and checks, at the end of the run (hertz_check.h): no penetration,
// growing and balanced plate forces, the second particle row at the bottom
// plate (a = its half-chord, 0.259; the first row's is 0.1375: F_Hertz
// differs by 3.6x between them) with F within [0.6, 1.2] F_Hertz(a); and
// linear and neo-Hookean forces within 10 % (a / R = 0.26: moderate
// strains, the two models still close).

#include "hertz_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  hertz_check::compare_models(BFEMP_SOURCE_DIR
                              "/prm/experiments/6_3_hertz/hertz_reduced.prm",
                              13,
                              0.259,
                              0.1);
}
