// Checks FrictionMollifier (BFEMP eq. 36 and the f0 of eq. 37) for sliding
// thresholds eps_v dt from 1e-7 to 1:
// - f0' = f1 by central differences, below and above eps;
// - f0(0) = eps/3, f0 and f1 continuous at eps, f1(0) = 0, f1(eps) = 1,
//   f1 nondecreasing in [0, 1], f1'(eps) = 0 from the left (the one-sided
//   slope (f1(eps) - f1(eps - h))/h equals h/eps^2) and from the right;
// - f1(y)/y against the quotient and its limit 2/eps at y = 0;
// - (f1' y - f1)/y^3 and f1' - f1/y against central differences of f1(y)/y,
//   down to y = 1e-6 eps, and f1' - f1/y = 0 at y = 0;
// - the Hessian of f0(|u|) assembled from them, f1/y I + (f1' - f1/y)
//   u u^T/|u|^2, against central differences of the gradient f1/y u, for u
//   in R^1 and R^2 (the sliding spaces of 2D and 3D), including u = 0.

#include <bfemp/contact/friction_mollifier.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#include "tests.h"

using namespace bfemp;

namespace
{

  /** The larger of two errors, a NaN counting as the largest (std::max
   *  would drop a NaN in its second argument and hide a failure). */
  double
  worse(const double a, const double b)
  {
    if (std::isnan(a))
      return a;
    return (std::isnan(b) || b > a) ? b : a;
  }

  double
  worse(const std::initializer_list<double> errors)
  {
    double result = 0.;
    for (const double e : errors)
      result = worse(result, e);
    return result;
  }


  std::string
  to_string(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }

  /** The gradient of f0(|u|) in R^n, f1(|u|)/|u| u (0 at u = 0). */
  template <int n>
  std::array<double, n>
  gradient(const FrictionMollifier &m, const std::array<double, n> &u)
  {
    double y = 0.;
    for (const double c : u)
      y += c * c;
    y = std::sqrt(y);
    std::array<double, n> g;
    for (unsigned int i = 0; i < n; ++i)
      g[i] = m.f1_over_y(y) * u[i];
    return g;
  }

  /** The Hessian of f0(|u|) from f1/y and f1' - f1/y. */
  template <int n>
  std::array<std::array<double, n>, n>
  hessian(const FrictionMollifier &m, const std::array<double, n> &u)
  {
    double y = 0.;
    for (const double c : u)
      y += c * c;
    y = std::sqrt(y);
    std::array<std::array<double, n>, n> H;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        H[i][j] =
          (i == j ? m.f1_over_y(y) : 0.) +
          (y > 0. ? m.f1_derivative_minus_f1_over_y(y) * u[i] * u[j] / (y * y)
                  : 0.);
    return H;
  }

  /** max |H - central differences of the gradient| / max(|H|, f1(y)/y). */
  template <int n>
  double
  hessian_error(const FrictionMollifier &m, const std::array<double, n> &u)
  {
    const double eps = m.sliding_threshold();
    double       y   = 0.;
    for (const double c : u)
      y += c * c;
    y = std::sqrt(y);
    const double h =
      y > 0. ? 1e-4 * std::min({eps, std::abs(y - eps), y}) : 1e-8 * eps;

    // Relative to f1(y)/y at least: in 1D the Hessian f1'(y) vanishes
    // at and beyond eps.
    const auto H     = hessian<n>(m, u);
    double     scale = m.f1_over_y(y), error = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        scale = std::max(scale, std::abs(H[i][j]));
    for (unsigned int j = 0; j < n; ++j)
      {
        std::array<double, n> plus = u, minus = u;
        plus[j] += h;
        minus[j] -= h;
        const auto g_plus  = gradient<n>(m, plus);
        const auto g_minus = gradient<n>(m, minus);
        for (unsigned int i = 0; i < n; ++i)
          error =
            worse(error,
                  std::abs((g_plus[i] - g_minus[i]) / (2. * h) - H[i][j]) /
                    scale);
      }
    return error;
  }



  void
  check_threshold(const double eps)
  {
    const FrictionMollifier m(eps);
    const std::string       name = "eps_v dt = " + to_string(eps);

    // f0' = f1.
    {
      double error = 0.;
      for (const double r : {0.01, 0.1, 0.5, 0.9, 0.99, 1.01, 2., 10.})
        {
          const double y = r * eps;
          const double h = 1e-6 * eps;
          error =
            worse(error,
                  std::abs((m.f0(y + h) - m.f0(y - h)) / (2. * h) - m.f1(y)) /
                    m.f1(y));
        }
      bfemp_tests::check_below(error,
                               1e-8,
                               name + ": f0' = f1 (central differences): "
                                      "largest relative error");
    }

    // Values at 0 and eps, continuity, f1'(eps) = 0, monotonicity.
    {
      const double below        = std::nextafter(eps, 0.);
      const double h            = 1e-4 * eps;
      const double left_slope   = (m.f1(eps) - m.f1(eps - h)) / h;
      const double right_slope  = (m.f1(eps + h) - m.f1(eps)) / h;
      unsigned int n_decreasing = 0;
      for (unsigned int k = 0; k < 1000; ++k)
        n_decreasing += !(m.f1((k + 1) * 1e-3 * eps) >= m.f1(k * 1e-3 * eps));
      // The exact identities (bound 0) as one largest deviation.
      const double exact   = worse({std::abs(m.f1(0.)),
                                    std::abs(m.f1(eps) - 1.),
                                    std::abs(m.f0(eps) - eps) / eps});
      const double f0_at_0 = std::abs(m.f0(0.) - eps / 3.) / eps;
      const double f0_jump = std::abs(m.f0(below) - m.f0(eps)) / eps;
      const double f1_jump = std::abs(m.f1(below) - 1.);
      bfemp_tests::check(
        f0_at_0 <= 1e-15 && exact <= 0. && f0_jump <= 4e-16 && f1_jump <= 1e-15,
        name +
          ": f0(0) = eps/3, f1(0) = 0, f0 and f1 continuous at eps: "
          "|f0(0) - eps/3| / eps " +
          bfemp_tests::measured(f0_at_0, 1e-15) +
          ", largest of |f1(0)|, |f1(eps) - 1|, |f0(eps) - eps| / eps " +
          bfemp_tests::measured(exact, 0.) + ", |f0(eps^-) - f0(eps)| / eps " +
          bfemp_tests::measured(f0_jump, 4e-16) + ", |f1(eps^-) - 1| " +
          bfemp_tests::measured(f1_jump, 1e-15));
      const double left_error = std::abs(left_slope / (h / (eps * eps)) - 1.);
      bfemp_tests::check(left_error <= 1e-6 && right_slope == 0.,
                         name +
                           ": f1'(eps) = 0 from both sides: left slope "
                           "over h / (h/eps^2) - 1 " +
                           bfemp_tests::measured(left_error, 1e-6) +
                           ", right slope " +
                           bfemp_tests::measured(std::abs(right_slope), 0.));
      bfemp_tests::check(n_decreasing == 0 && m.f1(0.5 * eps) > 0. &&
                           m.f1(0.999 * eps) < 1.,
                         name + ": f1 nondecreasing in [0, 1]: decreases in " +
                           std::to_string(n_decreasing) +
                           " of 1000 steps, f1(eps/2) " +
                           bfemp_tests::format("%.1e", m.f1(0.5 * eps)) +
                           ", 1 - f1(0.999 eps) " +
                           bfemp_tests::format("%.1e", 1. - m.f1(0.999 * eps)));
    }

    // f1(y)/y.
    {
      double error = 0.;
      for (const double r : {1e-12, 1e-6, 0.1, 0.5, 0.999, 1., 2., 10.})
        {
          const double y = r * eps;
          error = worse(error, std::abs(m.f1_over_y(y) * y / m.f1(y) - 1.));
        }
      const double limit = worse(std::abs(m.f1_over_y(0.) * eps / 2. - 1.),
                                 std::abs(m.f1_over_y(1e-300) * eps / 2. - 1.));
      bfemp_tests::check(error <= 1e-14 && limit <= 1e-15,
                         name +
                           ": f1(y)/y matches the quotient and tends to "
                           "2/eps at y = 0: largest relative error " +
                           bfemp_tests::measured(error, 1e-14) +
                           ", at y = 0 and 1e-300 " +
                           bfemp_tests::measured(limit, 1e-15));
    }

    // (f1' y - f1)/y^3 and f1' - f1/y against central differences of f1/y.
    {
      double error = 0.;
      for (const double r : {1e-6, 1e-3, 0.1, 0.5, 0.9, 1.1, 2., 10.})
        {
          const double y = r * eps;
          // f1/y is linear below eps: any step inside [0, eps) is exact.
          const double h =
            y < eps ? 0.5 * std::min(y, eps - y) : 1e-4 * std::min(y, y - eps);
          const double fd =
            (m.f1_over_y(y + h) - m.f1_over_y(y - h)) / (2. * h);
          error = worse(
            {error,
             std::abs(m.f1_over_y_derivative_over_y(y) / (fd / y) - 1.),
             std::abs(m.f1_derivative_minus_f1_over_y(y) / (fd * y) - 1.)});
        }
      const double at_0        = std::abs(m.f1_derivative_minus_f1_over_y(0.));
      const double slope_error = std::abs(
        m.f1_derivative_minus_f1_over_y(1e-10 * eps) * eps / -1e-10 - 1.);
      bfemp_tests::check(
        error <= 1e-6 && at_0 == 0. && slope_error <= 1e-14,
        name +
          ": (f1' y - f1)/y^3 and f1' - f1/y match central differences "
          "of f1/y for y/eps in [1e-6, 10]: largest relative error " +
          bfemp_tests::measured(error, 1e-6) +
          "; f1' - f1/y vanishes linearly at 0: value at 0 " +
          bfemp_tests::measured(at_0, 0.) +
          ", relative error of the slope at 1e-10 eps " +
          bfemp_tests::measured(slope_error, 1e-14));
    }

    // The Hessian of f0(|u|).
    {
      double error = 0.;
      for (const double r : {0., 1e-8, 0.3, 0.999, 1.001, 5.})
        {
          error = worse(error, hessian_error<1>(m, {{-r * eps}}));
          error = worse(error,
                        hessian_error<2>(m, {{0.6 * r * eps, -0.8 * r * eps}}));
        }
      bfemp_tests::check_below(error,
                               1e-6,
                               name + ": Hessian of f0(|u|) in 1D and 2D "
                                      "matches central differences of its "
                                      "gradient for |u|/eps in {0, 1e-8, 0.3, "
                                      "0.999, 1.001, 5}: largest relative "
                                      "error");
    }
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  for (const double eps : {1e-7, 1e-3, 1.})
    check_threshold(eps);

  bool thrown = false;
  try
    {
      FrictionMollifier m(0.);
    }
  catch (const dealii::ExceptionBase &)
    {
      thrown = true;
    }
  bfemp_tests::check(thrown, "a zero sliding threshold is rejected");
}
