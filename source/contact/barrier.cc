#include <bfemp/contact/barrier.h>

#include <cmath>
#include <limits>

namespace bfemp
{
  namespace
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();

    /**
     * ln x for x = d/dhat in (0, 1), given also x - 1. Near x = 1, log(x)
     * would lose all digits of the small result to the rounding of x, while
     * log1p(x - 1) with an accurate x - 1 keeps them; below 1/2, x - 1 is
     * no longer exact but x is, and log(x) is accurate.
     */
    double
    log_ratio(const double x, const double x_minus_one)
    {
      return x < 0.5 ? std::log(x) : std::log1p(x_minus_one);
    }
  } // namespace



  BarrierDerivatives
  barrier_of_squared_distance(const double s,
                              const double dhat,
                              const double kappa)
  {
    if (s >= dhat * dhat)
      return {0., 0., 0.};
    if (!(s > 0.))
      return {infinity, -infinity, infinity};

    const double d = std::sqrt(s);
    const double x = d / dhat;
    // d - dhat is exact for d in [dhat/2, dhat] (Sterbenz), so x - 1 has a
    // relative error of one rounding where it matters.
    const double x_minus_one = (d - dhat) / dhat;
    const double ln_x        = log_ratio(x, x_minus_one);

    BarrierDerivatives result;
    result.value = -kappa * x_minus_one * x_minus_one * ln_x;
    result.first =
      -kappa * x_minus_one * (2. * x * ln_x + x_minus_one) / (2. * s);
    // x^2 - 1 = (x - 1)(x + 1); dividing by s twice avoids the underflow
    // of s^2 for tiny s.
    result.second =
      -kappa * ((x * ln_x + x_minus_one * (x + 1.)) / (2. * s)) / s;
    return result;
  }



  double
  barrier(const double d, const double dhat, const double kappa)
  {
    if (d >= dhat)
      return 0.;
    if (!(d > 0.))
      return infinity;
    const double x_minus_one = (d - dhat) / dhat;
    return -kappa * x_minus_one * x_minus_one *
           log_ratio(d / dhat, x_minus_one);
  }
} // namespace bfemp
