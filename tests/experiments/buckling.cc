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
// Buckling is detected as the first row in which the inner ring's centre
// of mass moves down faster than the plate, mpm0_com_velocity_y < -1 m/s
// (bodies.csv). Before buckling the inner ring is squeezed between its
// held feet and the outer ring, so its centre of mass moves slower than
// the plate (0.2 .. 0.9 m/s); when its flattened top snaps through it
// leaves the outer ring and falls faster than the plate (up to 2.7 m/s).
// The rendered runs (doc/experiments/buckling.md) show the snap at that
// moment. Checked:
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

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  const std::string file =
    BFEMP_SOURCE_DIR "/prm/experiments/6_6_buckling/buckling_reduced.prm";
  constexpr double end_time    = 6.5;
  constexpr double dt          = 2e-2;
  constexpr double plate_speed = 1.;

  /** Runs the reduced scene with @p mu between the rings; returns the
   *  plate displacement at buckling, or -1 if the ring did not buckle. */
  double
  buckling_displacement(const std::string &name, const double mu)
  {
    std::ostringstream prm;
    prm << "include " << file << "\nsubsection run\n  set name = " << name
        << "\n  set quiet = true\nend\n"
           "subsection output\n  set directory = results\n"
           "  set interval = "
        << end_time
        << "\n  set diagnostics interval = 1\n"
           "  set write particles = false\n  set write grid = false\nend\n"
           "subsection contact\n  set friction coefficients = 0, 0: "
        << mu << "\nend\n";
    write(name + ".prm", prm.str());
    const std::string error = implicit_scene::run<2>(name + ".prm").error;
    if (!error.empty())
      deallog << name << ": " << error << std::endl;
    bfemp_tests::check(error.empty(), name + ": the run reached the end");

    const auto b = bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                             {"time", "mpm0_com_velocity_y"});
    bfemp_tests::check(b[0].size() ==
                         static_cast<std::size_t>(std::round(end_time / dt)) +
                           1,
                       name + ": one bodies.csv row per step");
    const auto contact = columns(name, {"contact_particles"});
    bfemp_tests::check(max_of(contact[0]) > 0,
                       name + ": the outer ring presses on the inner ring");

    double fastest = 0.;
    for (std::size_t k = 0; k < b[0].size(); ++k)
      {
        fastest = std::min(fastest, b[1][k]);
        if (b[1][k] < -plate_speed)
          {
            deallog << name << ": buckles at plate displacement "
                    << rounded(plate_speed * b[0][k], 3) << " m" << std::endl;
            return plate_speed * b[0][k];
          }
      }
    deallog << name << ": no buckling up to "
            << rounded(plate_speed * end_time, 2)
            << " m (fastest downward centre-of-mass speed "
            << rounded(-fastest, 1) << " m/s)" << std::endl;
    return -1.;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  const double u0  = buckling_displacement("mu_0", 0.);
  const double u02 = buckling_displacement("mu_0_2", 0.2);
  const double u05 = buckling_displacement("mu_0_5", 0.5);

  bfemp_tests::check(u0 >= 4. && u0 <= 6.,
                     "mu = 0 buckles at a plate displacement in [4, 6] m");
  bfemp_tests::check(u02 > 0. && u02 >= u0 + 0.3,
                     "mu = 0.2 buckles, at least 0.3 m later than mu = 0");
  bfemp_tests::check(u05 < 0., "mu = 0.5 does not buckle within the run");
}
