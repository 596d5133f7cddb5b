#ifndef bfemp_tests_experiments_hertz_check_h
#define bfemp_tests_experiments_hertz_check_h

// BFEMP Section 6.3 (Brazilian disk / plane Hertz contact), shared by the
// reduced test (tests/experiments/hertz) and the full-resolution one
// (tests/validation/hertz_full). A disk (R = 1, E = 1e10, nu = 0.3) between
// two FEM plates that approach each other; checked at the end of a run:
//  - no particle inside a plate in any row, every contact distance > 0;
//  - the contact force on the bottom plate grows in every step (the plate
//    only compresses) and equals the force on the top plate to 1 % (the
//    disk is in quasi-static equilibrium: no gravity, negligible inertia);
//  - the contact half-width a (half the horizontal range of the particles
//    within dhat of the bottom plate, as in the paper) is the expected
//    particle row's half-chord, and F there is within [0.6, 1.2]
//    F_Hertz(a), F_Hertz = pi E a^2 / (4 (1 - nu^2) R). The band is wide
//    because a is quantized by the particle rows: between two rows the
//    contact edge lies anywhere between their half-chords (see
//    doc/experiments/hertz.md, where the full runs show the points at the
//    row jumps).

#include <limits>
#include <string>

#include "../implicit/implicit_scene.h"

namespace hertz_check
{
  using namespace dealii;

  constexpr double youngs  = 1e10;
  constexpr double poisson = 0.3;
  constexpr double radius  = 1.;
  constexpr double dhat    = 1e-4;

  inline double
  hertz_force(const double a)
  {
    return numbers::PI * youngs * a * a /
           (4. * (1. - poisson * poisson) * radius);
  }

  /**
   * Runs @p base_prm as results/hertz_<tag> with the disk's material
   * @p model, checks it as described above (@p n_rows diagnostics rows,
   * half-width @p expected_a at the end) and returns the contact force on
   * the bottom plate at the end.
   */
  inline double
  check_model(const std::string &base_prm,
              const std::string &model,
              const std::string &tag,
              const std::size_t  n_rows,
              const double       expected_a)
  {
    const std::string name   = "hertz_" + tag;
    const std::string prefix = model + ": ";
    implicit_scene::write(
      name + ".prm",
      "include " + base_prm + "\nsubsection run\n  set name = " + name +
        "\n  set quiet = true\nend\n"
        "subsection body 0\n  subsection material\n    set model = " +
        model +
        "\n  end\nend\n"
        "subsection output\n  set directory = results\n"
        "  set write particles = false\n  set write grid = false\nend\n");
    double     half_width = 0.;
    const auto outcome =
      implicit_scene::run<2>(name + ".prm", {}, [&](auto &simulation) {
        const auto &plate     = *simulation.fem_bodies()[0];
        double      plate_top = -std::numeric_limits<double>::infinity();
        for (const auto &x : plate.positions())
          plate_top = std::max(plate_top, x[1]);
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (const auto &particle : simulation.particles().handler())
          if (particle.get_location()[1] - plate_top < dhat)
            {
              low  = std::min(low, particle.get_location()[0]);
              high = std::max(high, particle.get_location()[0]);
            }
        half_width = high > low ? 0.5 * (high - low) : 0.;
      });
    deallog << model << std::endl;
    if (!outcome.error.empty())
      deallog << "error: " << outcome.error << std::endl;
    bfemp_tests::check(outcome.error.empty(),
                       prefix + "the run reached the end time");

    const auto        c = implicit_scene::columns(name,
                                           {"particles_in_fem",
                                                   "min_distance",
                                                   "contact_force_m0_f0_y",
                                                   "contact_force_m0_f1_y"});
    const std::size_t n = c[0].size();
    bfemp_tests::check(n == n_rows, prefix + "one row per step");
    bool   inside = false, growing = true;
    double min_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < n; ++k)
      {
        inside       = inside || c[0][k] > 0.;
        min_distance = std::min(min_distance, c[1][k]);
        growing      = growing && -c[2][k] > (k > 1 ? -c[2][k - 1] : 0.);
      }
    bfemp_tests::check(!inside && min_distance > 0.,
                       prefix + "no particle inside a plate, distances > 0");
    bfemp_tests::check(growing, prefix + "the force on the bottom plate grows");
    const double force = -c[2][n - 1];
    bfemp_tests::check(std::abs(c[3][n - 1] - force) < 0.01 * force,
                       prefix + "equal and opposite plate forces (1 %)");

    const double ratio = force / hertz_force(half_width);
    deallog << "  a = " << implicit_scene::rounded(half_width, 3)
            << ", F / F_Hertz(a) = " << implicit_scene::rounded(ratio, 2)
            << std::endl;
    bfemp_tests::check(std::abs(half_width - expected_a) < 0.005,
                       prefix + "the expected particle row touches (a = " +
                         implicit_scene::rounded(expected_a, 3) + ")");
    bfemp_tests::check(ratio >= 0.6 && ratio <= 1.2,
                       prefix + "F within [0.6, 1.2] F_Hertz(a)");
    return force;
  }

  /**
   * Runs @p base_prm with linear elasticity and with neo-Hookean, checks
   * each with check_model() and checks that their final forces agree to
   * the fraction @p agreement.
   */
  inline void
  compare_models(const std::string &base_prm,
                 const std::size_t  n_rows,
                 const double       expected_a,
                 const double       agreement)
  {
    const double linear =
      check_model(base_prm, "linear elastic", "linear", n_rows, expected_a);
    const double neo_hookean =
      check_model(base_prm, "neo-Hookean", "neohookean", n_rows, expected_a);
    deallog << "F_neo-Hookean / F_linear = "
            << implicit_scene::rounded(neo_hookean / linear, 3) << std::endl;
    bfemp_tests::check(std::abs(neo_hookean / linear - 1.) < agreement,
                       "linear and neo-Hookean forces agree to " +
                         implicit_scene::rounded(100. * agreement, 2) + " %");
  }
} // namespace hertz_check

#endif
