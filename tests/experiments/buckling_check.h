#ifndef bfemp_tests_experiments_buckling_check_h
#define bfemp_tests_experiments_buckling_check_h

// BFEMP Section 6.6 (buckling of stacked semi-rings), shared by the reduced
// test (tests/experiments/buckling) and the full-resolution one
// (tests/validation/buckling_full).
//
// Buckling is detected as the first row in which the inner ring's centre
// of mass moves down faster than the plate, mpm0_com_velocity_y < -1 m/s
// (bodies.csv). Before buckling the inner ring is squeezed between its
// held feet and the outer ring, so its centre of mass moves slower than
// the plate (0.2 .. 0.9 m/s); when its flattened top snaps through it
// leaves the outer ring and falls faster than the plate (up to 2.7 m/s).
// The rendered runs (doc/experiments/buckling.md) show the snap at that
// moment.

#include <sstream>
#include <string>

#include "../implicit/implicit_scene.h"

namespace buckling_check
{
  using namespace dealii;

  constexpr double plate_speed = 1.;

  /**
   * Runs @p base_prm (a buckling scene with fixed steps @p dt to
   * @p end_time) as results/<name> with friction coefficient @p mu between
   * the rings; checks that it reaches the end with one bodies.csv row per
   * step and that the rings touch; returns the plate displacement at
   * buckling, or -1 if the inner ring did not buckle.
   */
  inline double
  buckling_displacement(const std::string &base_prm,
                        const std::string &name,
                        const double       mu,
                        const double       end_time,
                        const double       dt)
  {
    std::ostringstream prm;
    prm << "include " << base_prm << "\nsubsection run\n  set name = " << name
        << "\n  set quiet = true\nend\n"
           "subsection output\n  set directory = results\n"
           "  set interval = "
        << end_time
        << "\n  set diagnostics interval = 1\n"
           "  set write particles = false\n  set write grid = false\nend\n"
           "subsection contact\n  set friction coefficients = 0, 0: "
        << mu << "\nend\n";
    implicit_scene::write(name + ".prm", prm.str());
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
    const auto contact = implicit_scene::columns(name, {"contact_particles"});
    bfemp_tests::check(implicit_scene::max_of(contact[0]) > 0,
                       name + ": the outer ring presses on the inner ring");

    double fastest = 0.;
    for (std::size_t k = 0; k < b[0].size(); ++k)
      {
        fastest = std::min(fastest, b[1][k]);
        if (b[1][k] < -plate_speed)
          {
            deallog << name << ": buckles at plate displacement "
                    << implicit_scene::rounded(plate_speed * b[0][k], 3) << " m"
                    << std::endl;
            return plate_speed * b[0][k];
          }
      }
    deallog << name << ": no buckling up to "
            << implicit_scene::rounded(plate_speed * end_time, 2)
            << " m (fastest downward centre-of-mass speed "
            << implicit_scene::rounded(-fastest, 1) << " m/s)" << std::endl;
    return -1.;
  }

  /**
   * The paper's ordering: mu = 0 buckles within @p band_mu_0 of plate
   * travel, mu = 0.2 buckles at least 0.3 m later, mu = 0.5 does not buckle
   * within the run.
   */
  inline void
  check_ordering(const double                     u0,
                 const double                     u02,
                 const double                     u05,
                 const std::pair<double, double> &band_mu_0)
  {
    bfemp_tests::check(u0 >= band_mu_0.first && u0 <= band_mu_0.second,
                       "mu = 0 buckles at a plate displacement in [" +
                         implicit_scene::rounded(band_mu_0.first, 2) + ", " +
                         implicit_scene::rounded(band_mu_0.second, 2) + "] m");
    bfemp_tests::check(u02 > 0. && u02 >= u0 + 0.3,
                       "mu = 0.2 buckles, at least 0.3 m later than mu = 0");
    bfemp_tests::check(u05 < 0., "mu = 0.5 does not buckle within the run");
  }
} // namespace buckling_check

#endif
