// BFEMP Section 6.6, buckling of stacked semi-rings (reduced): an FEM
// outer semi-ring (radii 12 .. 14) is pressed down at 1 m/s by a plate
// (here a sticky level set that grips the ring's nodes, see the prm
// header); it presses on an MPM inner semi-ring (radii 10 .. 11.99); the
// feet of both are held. Runs prm/experiments/6_6_buckling/
// buckling_reduced.prm (dx = 0.5, 1104 particles, 491 FEM vertices,
// h = 2e-2 s, 325 steps to t = 6.5 s) with mu = 0, 0.2, 0.5 between the
// rings.
//
// The paper: mu = 0 buckles first, mu = 0.2 later, mu = 0.5 not at all.
// Buckling detection: buckling_check.h. Checked:
//  - each run reaches t = 6.5 s, one bodies.csv row per step;
//  - contact between the rings in each run (the load path);
//  - mu = 0 buckles, at a plate displacement in [4, 6] m (measured 5.10 m;
//    5.11 m at h = 1e-2; 5.63 m at the paper's resolution: the band allows
//    for the discretization);
//  - mu = 0.2 buckles later than mu = 0 by at least 0.3 m (measured
//    6.00 m, 0.9 m later; 6.05 m at h = 1e-2);
//  - mu = 0.5 does not buckle within the run (its centre of mass moves at
//    most 0.8 m/s down; 0.85 m/s up to 8 m at h = 1e-2).
// Run time: about 100 s of CPU on the loaded 2-core machine (76 s user,
// 24 s system), most of it in the friction runs.

#include "buckling_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  const std::string prm =
    BFEMP_SOURCE_DIR "/prm/experiments/6_6_buckling/buckling_reduced.prm";
  const double end_time = 6.5, dt = 2e-2;
  const double u0 =
    buckling_check::buckling_displacement(prm, "mu_0", 0., end_time, dt);
  const double u02 =
    buckling_check::buckling_displacement(prm, "mu_0_2", 0.2, end_time, dt);
  const double u05 =
    buckling_check::buckling_displacement(prm, "mu_0_5", 0.5, end_time, dt);
  buckling_check::check_ordering(u0, u02, u05, {4., 6.});
}
