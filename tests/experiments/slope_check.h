#ifndef bfemp_tests_experiments_slope_check_h
#define bfemp_tests_experiments_slope_check_h

// BFEMP Section 6.4 (critical friction on a slope), the checks shared by
// the reduced test (tests/experiments/slope) and the full-resolution one
// (tests/validation/slope_full). The scene is the rotated frame: a flat
// slope and tilted gravity, so mpm0_com_velocity_x in bodies.csv is the
// velocity along the slope.
//
// - settling: over the last 0.02 s before the release |v| < 1e-9 m/s
//   = 1e-4 eps_v (the box is static);
// - sliding (mu < tan theta): the least-squares slope of v(t) from 0.01 s
//   after the release matches a = g (sin theta - mu cos theta), eq. (40),
//   to 1e-4 relative, the paper's 0.01 %;
// - sticking (mu = tan theta): |v| after the release stays below 1.5 eps_v
//   (the mollifier of eq. 36 gives static friction only while sliding at
//   about eps_v; the paper reports "around eps_v") and the fitted
//   acceleration is below 1e-5 of g sin theta.

#include <string>
#include <vector>

#include "../contact_physics/slope_scene.h"

namespace slope_check
{
  using namespace dealii;

  using implicit_scene::fitted_slope;
  using slope_scene::cos_theta;
  using slope_scene::g;
  using slope_scene::sin_theta;
  constexpr double eps_v = 1e-5;

  /**
   * Runs @p base_prm (a slope scene) as results/<name> with friction
   * coefficient @p mu between box and slope, released at @p release, and
   * checks it as described above.
   */
  inline void
  check(const std::string &base_prm,
        const std::string &name,
        const double       mu,
        const double       release)
  {
    implicit_scene::write(
      name + ".prm",
      "include " + base_prm + "\nsubsection run\n  set name = " + name +
        "\n  set quiet = true\nend\n"
        "subsection output\n  set directory = results\n"
        "  set write particles = false\n  set write grid = false\nend\n"
        "subsection contact\n  set friction coefficients = 0, 0: " +
        implicit_scene::rounded(mu, 6) + "; 0, 1: 0\nend\n");
    const implicit_scene::Outcome<2> outcome =
      implicit_scene::run<2>(name + ".prm");
    bfemp_tests::check(outcome.error.empty(), name + " ran: " + outcome.error);

    const auto c = bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                             {"time", "mpm0_com_velocity_x"});
    const std::vector<double> &t = c[0], &v = c[1];

    double settled = 0., after = 0.;
    for (unsigned int i = 0; i < t.size(); ++i)
      if (t[i] >= release - 0.02 && t[i] <= release + 1e-9)
        settled = std::max(settled, std::abs(v[i]));
      else if (t[i] > release + 1e-9)
        after = std::max(after, std::abs(v[i]));
    const std::string label = "mu = " + implicit_scene::rounded(mu, 4);
    bfemp_tests::check(settled < 1e-9,
                       label + ": static before the release, |v| < 1e-9 m/s");

    const double exact = std::max(0., g * (sin_theta() - mu * cos_theta()));
    const double a     = fitted_slope(t, v, release + 0.01);
    if (exact > 0.)
      {
        deallog << label << ": a = " << implicit_scene::rounded(a, 6)
                << " m/s^2, g (sin - mu cos) = "
                << implicit_scene::rounded(exact, 6) << std::endl;
        bfemp_tests::check(std::abs(a - exact) / exact < 1e-4,
                           "  relative error of the acceleration < 1e-4");
      }
    else
      {
        deallog << label << ": max |v| after release = "
                << implicit_scene::rounded(after / eps_v, 3) << " eps_v"
                << std::endl;
        bfemp_tests::check(after < 1.5 * eps_v, "  sticks: |v| < 1.5 eps_v");
        bfemp_tests::check(std::abs(a) < 1e-5 * g * sin_theta(),
                           "  acceleration < 1e-5 g sin(theta)");
      }
  }
} // namespace slope_check

#endif
