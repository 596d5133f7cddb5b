// BFEMP Section 6.4, critical value of the friction coefficient: the
// reduced scene prm/experiments/6_4_slope/slope_reduced.prm (the full
// scene's box, slope, support plate and numerics; settled 0.1 s instead of
// 2 s, released for 0.2 s instead of 1 s) for mu = 0, 0.1, 0.1999, 0.2.
//
// Checked, from bodies.csv (mpm0_com_velocity_x is the velocity along the
// slope: the scene is the rotated frame, flat slope and tilted gravity):
// - settling: from 0.08 s to the release |v| < 1e-9 m/s = 1e-4 eps_v (the
//   box is static; measured 5e-15 m/s for mu = 0, 7e-15 for mu = 0.1 and
//   ~1e-11 for mu >= 0.1999, where the static-friction zone of the
//   mollifier lets the settling decay more slowly);
// - sliding (mu = 0, 0.1, 0.1999): the least-squares slope of v(t) over the
//   release window (from 0.01 s after the release) matches
//   a = g (sin theta - mu cos theta) to 1e-4 relative, the paper's 0.01 %
//   (measured ~1e-9; for mu = 0.1999 a is 2000 times smaller than for
//   mu = 0);
// - sticking (mu = 0.2 = tan theta): |v| after the release stays below
//   1.5 eps_v (the mollifier of eq. 36 provides static friction only while
//   sliding at ~eps_v; measured 0.99994 eps_v, as the paper reports "around
//   eps_v") and the fitted acceleration is below 1e-5 of g sin theta.

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double g       = 5.1;
  constexpr double tangent = 0.2;
  constexpr double release = 0.1;
  constexpr double eps_v   = 1e-5;

  const double sin_theta = tangent / std::sqrt(1. + tangent * tangent);
  const double cos_theta = 1. / std::sqrt(1. + tangent * tangent);

  /** Least-squares slope of y(t) over t > t0. */
  double
  fitted_slope(const std::vector<double> &t,
               const std::vector<double> &y,
               const double               t0)
  {
    double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
    for (unsigned int i = 0; i < t.size(); ++i)
      if (t[i] > t0)
        {
          const double s = t[i] - t0;
          n += 1;
          st += s;
          sy += y[i];
          stt += s * s;
          sty += s * y[i];
        }
    return (n * sty - st * sy) / (n * stt - st * st);
  }

  void
  check(const double mu, const std::string &tag)
  {
    const std::string name = "slope_mu_" + tag;
    write(name + ".prm",
          "include " BFEMP_SOURCE_DIR
          "/prm/experiments/6_4_slope/slope_reduced.prm\n"
          "subsection run\n  set name = " +
            name +
            "\n  set quiet = true\nend\n"
            "subsection output\n  set directory = results\n"
            "  set write particles = false\n  set write grid = false\nend\n"
            "subsection contact\n  set friction coefficients = 0, 0: " +
            rounded(mu, 6) + "; 0, 1: 0\nend\n");
    const Outcome<2> outcome = run<2>(name + ".prm");
    bfemp_tests::check(outcome.error.empty(), name + " ran: " + outcome.error);

    const auto c = bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                             {"time", "mpm0_com_velocity_x"});
    const std::vector<double> &t = c[0], &v = c[1];

    double settled = 0., after = 0.;
    for (unsigned int i = 0; i < t.size(); ++i)
      if (t[i] >= 0.08 && t[i] <= release + 1e-9)
        settled = std::max(settled, std::abs(v[i]));
      else if (t[i] > release + 1e-9)
        after = std::max(after, std::abs(v[i]));
    bfemp_tests::check(settled < 1e-9,
                       "mu = " + rounded(mu, 4) +
                         ": static before the release, |v| < 1e-9 m/s");

    const double exact = std::max(0., g * (sin_theta - mu * cos_theta));
    const double a     = fitted_slope(t, v, release + 0.01);
    if (exact > 0.)
      {
        const double error = std::abs(a - exact) / exact;
        deallog << "mu = " << rounded(mu, 4) << ": a = " << rounded(a, 6)
                << " m/s^2, g (sin - mu cos) = " << rounded(exact, 6)
                << std::endl;
        bfemp_tests::check(error < 1e-4,
                           "  relative error of the acceleration < 1e-4");
      }
    else
      {
        deallog << "mu = " << rounded(mu, 4)
                << ": max |v| after release = " << rounded(after / eps_v, 3)
                << " eps_v" << std::endl;
        bfemp_tests::check(after < 1.5 * eps_v, "  sticks: |v| < 1.5 eps_v");
        bfemp_tests::check(std::abs(a) < 1e-5 * g * sin_theta,
                           "  acceleration < 1e-5 g sin(theta)");
      }
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  check(0., "0");
  check(0.1, "0_1");
  check(0.1999, "0_1999");
  check(0.2, "0_2");
}
