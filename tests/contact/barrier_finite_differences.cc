// Checks the barrier of contact/barrier.h, BFEMP eq. 27 written in the
// squared distance s = d^2, for dhat from 1e-5 to 1e-1:
// - value, db/ds and d^2b/ds^2 against a long double evaluation of the
//   d-form of eq. 27 and its d-derivatives (chain rule
//   b_s = b'(d)/(2d), b_ss = (b''(d) - b'(d)/d)/(4 d^2)), away from dhat
//   and close to it (where the accuracy is limited to ~ epsilon/(1 - d/dhat)
//   by the rounding of s);
// - the derivatives against central differences in s;
// - zero at and beyond dhat^2, +infinity at s <= 0;
// - C2 continuity at dhat: value, first and second derivative vanish like
//   (1 - s/dhat^2)^3, ^2 and ^1 with the leading coefficients of the Taylor
//   expansion;
// - b > 0, b_s < 0, b_ss > 0 and strict decrease on a dense sample of
//   (0, dhat^2);
// - barrier(d) against the reference and against the s-form at s = d^2.

#include <bfemp/contact/barrier.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

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


  const double kappa    = 1e4;
  const double infinity = std::numeric_limits<double>::infinity();

  struct Reference
  {
    long double value, first, second;
  };

  /** eq. 27 in d, in long double, with its derivatives turned into
   *  s-derivatives by the chain rule. */
  Reference
  reference(const double s, const double dhat_)
  {
    const long double d    = std::sqrt(static_cast<long double>(s));
    const long double dhat = dhat_, k = kappa;
    const long double x = d / dhat, ln_x = std::log(x);
    const long double b = -k * (x - 1) * (x - 1) * ln_x;
    const long double b_d =
      -k * (2 * (x - 1) * ln_x / dhat + (x - 1) * (x - 1) / d);
    const long double b_dd =
      -k * (2 * ln_x / (dhat * dhat) + 4 * (x - 1) / (dhat * d) -
            (x - 1) * (x - 1) / (d * d));
    return {b, b_d / (2 * d), (b_dd - b_d / d) / (4 * d * d)};
  }

  double
  relative_error(const double computed, const long double expected)
  {
    return static_cast<double>(std::abs((computed - expected) / expected));
  }

  std::string
  to_string(const double x)
  {
    std::ostringstream s;
    s << x;
    return s.str();
  }



  void
  check_dhat(const double dhat)
  {
    const std::string name  = "dhat = " + to_string(dhat);
    const double      dhat2 = dhat * dhat;

    // Against the d-form, away from dhat: 1e-13 relative.
    {
      double error = 0.;
      for (const double r :
           {1e-20, 1e-12, 1e-6, 1e-3, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99})
        {
          const double             s = r * dhat2;
          const BarrierDerivatives b =
            barrier_of_squared_distance(s, dhat, kappa);
          const Reference e = reference(s, dhat);
          error             = worse({error,
                                     relative_error(b.value, e.value),
                                     relative_error(b.first, e.first),
                                     relative_error(b.second, e.second)});
        }
      bfemp_tests::check_below(error,
                               1e-13,
                               name + ": value, b_s, b_ss match eq. 27 in d "
                                      "for s/dhat^2 in [1e-20, 0.99]: largest "
                                      "relative error");
    }

    // Close to dhat: relative 1e-14/(1 - s/dhat^2).
    {
      double worst = 0.;
      for (const double delta : {1e-3, 1e-5, 1e-7})
        {
          const double             s = (1. - delta) * dhat2;
          const BarrierDerivatives b =
            barrier_of_squared_distance(s, dhat, kappa);
          const Reference e     = reference(s, dhat);
          const double    error = worse({relative_error(b.value, e.value),
                                         relative_error(b.first, e.first),
                                         relative_error(b.second, e.second)});
          worst                 = worse(worst, error * delta);
        }
      bfemp_tests::check_below(worst,
                               1e-14,
                               name + ": value, b_s, b_ss match eq. 27 in d "
                                      "for s/dhat^2 = 1 - delta, delta = "
                                      "1e-3, 1e-5, 1e-7: largest relative "
                                      "error times delta");
    }

    // Central differences in s, step 1e-4 min(s, dhat^2 - s).
    {
      double error = 0.;
      for (const double r : {1e-6, 1e-3, 0.1, 0.5, 0.9, 0.999})
        {
          const double             s = r * dhat2;
          const double             h = 1e-4 * std::min(s, dhat2 - s);
          const BarrierDerivatives b =
            barrier_of_squared_distance(s, dhat, kappa);
          const BarrierDerivatives plus =
            barrier_of_squared_distance(s + h, dhat, kappa);
          const BarrierDerivatives minus =
            barrier_of_squared_distance(s - h, dhat, kappa);
          error =
            worse({error,
                   std::abs((plus.value - minus.value) / (2. * h) - b.first) /
                     std::abs(b.first),
                   std::abs((plus.first - minus.first) / (2. * h) - b.second) /
                     std::abs(b.second)});
        }
      bfemp_tests::check_below(error,
                               1e-6,
                               name + ": b_s and b_ss match central "
                                      "differences: largest relative error");
    }

    // Zero at and beyond dhat, infinite at and below 0.
    {
      double largest = 0.;
      for (const double s :
           {dhat2, std::nextafter(dhat2, infinity), 1.5 * dhat2, 100. * dhat2})
        {
          const BarrierDerivatives b =
            barrier_of_squared_distance(s, dhat, kappa);
          largest = worse({largest,
                           std::abs(b.value),
                           std::abs(b.first),
                           std::abs(b.second)});
        }
      bfemp_tests::check_below(largest,
                               0.,
                               name + ": zero for s >= dhat^2: largest of "
                                      "|b|, |b_s|, |b_ss| at 4 points");
      unsigned int n_wrong = 0;
      for (const double s : {0., -1e-30, -dhat2})
        {
          const BarrierDerivatives b =
            barrier_of_squared_distance(s, dhat, kappa);
          n_wrong += (b.value != infinity) + (b.first != -infinity) +
                     (b.second != infinity);
        }
      bfemp_tests::check(n_wrong == 0,
                         name +
                           ": value +inf, b_s -inf, b_ss +inf for s <= 0: " +
                           std::to_string(n_wrong) +
                           " of 9 values at 3 points not infinite");
    }

    // C2 at dhat: with delta = 1 - s/dhat^2,
    // b = kappa delta^3/8 (1 + O(delta)), b_s = -3 kappa delta^2/(8 dhat^2)
    // (1 + O(delta)), b_ss = 3 kappa delta/(4 dhat^4) (1 + O(delta)).
    {
      double worst = 0.;
      for (const double delta : {1e-3, 1e-4, 1e-5})
        {
          const BarrierDerivatives b =
            barrier_of_squared_distance((1. - delta) * dhat2, dhat, kappa);
          const double value  = kappa * delta * delta * delta / 8.;
          const double first  = -3. * kappa * delta * delta / (8. * dhat2);
          const double second = 3. * kappa * delta / (4. * dhat2 * dhat2);
          worst               = worse({worst,
                                       std::abs(b.value / value - 1.) / delta,
                                       std::abs(b.first / first - 1.) / delta,
                                       std::abs(b.second / second - 1.) / delta});
        }
      bfemp_tests::check_below(worst,
                               3.,
                               name + ": C2 at dhat: value, b_s, b_ss vanish "
                                      "like delta^3, delta^2, delta with the "
                                      "Taylor coefficients: largest relative "
                                      "error / delta");
    }

    // Sign pattern and strict decrease on s/dhat^2 = k/1000.
    {
      unsigned int n_wrong  = 0;
      double       previous = infinity;
      for (unsigned int k = 1; k < 1000; ++k)
        {
          const BarrierDerivatives b =
            barrier_of_squared_distance(k * 1e-3 * dhat2, dhat, kappa);
          n_wrong += !(b.value > 0. && b.value < previous && b.first < 0. &&
                       b.second > 0. && std::isfinite(b.value));
          previous = b.value;
        }
      bfemp_tests::check(n_wrong == 0,
                         name +
                           ": b > 0, b_s < 0, b_ss > 0, strictly "
                           "decreasing on s/dhat^2 = 0.001, ..., 0.999: "
                           "violated at " +
                           std::to_string(n_wrong) + " of 999 points");
    }

    // barrier(d): against the reference and the s-form.
    {
      double error = 0.;
      for (const double x : {1e-6, 0.01, 0.5, 0.9})
        {
          const double d = x * dhat;
          error          = worse(
            {error,
                      relative_error(barrier(d, dhat, kappa),
                            reference(d * d, dhat).value),
                      std::abs(barrier(d, dhat, kappa) /
                        barrier_of_squared_distance(d * d, dhat, kappa).value -
                      1.)});
        }
      const double beyond = worse(std::abs(barrier(dhat, dhat, kappa)),
                                  std::abs(barrier(2. * dhat, dhat, kappa)));
      bfemp_tests::check(
        error <= 1e-13 && beyond == 0. && barrier(0., dhat, kappa) == infinity,
        name +
          ": barrier(d) matches eq. 27 and the s-form at "
          "s = d^2: largest relative error " +
          bfemp_tests::measured(error, 1e-13) +
          "; 0 for d >= dhat: largest |b| " +
          bfemp_tests::measured(beyond, 0.) + "; +inf at 0: b(0) = " +
          bfemp_tests::format("%.1e", barrier(0., dhat, kappa)));
    }
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  for (const double dhat : {1e-5, 1e-4, 1e-3, 1e-2, 1e-1})
    check_dhat(dhat);
}
