#include <bfemp/solver/polynomial_roots.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace bfemp
{
  namespace
  {
    constexpr double epsilon  = std::numeric_limits<double>::epsilon();
    constexpr double infinity = std::numeric_limits<double>::infinity();

    /**
     * Rounding errors of Horner's rule at t are bounded by a small multiple
     * of epsilon times sum |c_i| |t|^i; this is that sum.
     */
    double
    magnitude(const PolynomialCoefficients &c,
              const unsigned int            degree,
              const double                  t)
    {
      double result = std::abs(c[degree]);
      for (unsigned int i = degree; i-- > 0;)
        result = result * std::abs(t) + std::abs(c[i]);
      return result;
    }



    void
    evaluate_with_derivative(const PolynomialCoefficients &c,
                             const unsigned int            degree,
                             const double                  t,
                             double                       &value,
                             double                       &derivative)
    {
      value      = c[degree];
      derivative = 0.;
      for (unsigned int i = degree; i-- > 0;)
        {
          derivative = derivative * t + value;
          value      = value * t + c[i];
        }
    }



    /**
     * The real roots, ascending, of c0 + c1 t + c2 t^2 with c2 != 0 (none if
     * the discriminant is negative). The root of larger magnitude comes from
     * q = -(c1 + sign(c1) sqrt(D))/2, where no cancellation occurs, and the
     * other one from Vieta's c0/q rather than from the cancelling formula.
     * The coefficients are scaled by a power of two first so the
     * discriminant neither overflows nor underflows for extreme inputs.
     */
    unsigned int
    quadratic_real_roots(double                 c0,
                         double                 c1,
                         double                 c2,
                         std::array<double, 2> &roots)
    {
      const int exponent =
        std::ilogb(std::max({std::abs(c0), std::abs(c1), std::abs(c2)}));
      c0 = std::scalbn(c0, -exponent);
      c1 = std::scalbn(c1, -exponent);
      c2 = std::scalbn(c2, -exponent);

      const double discriminant = c1 * c1 - 4. * c2 * c0;
      if (discriminant < 0.)
        return 0;
      const double q = -0.5 * (c1 + std::copysign(std::sqrt(discriminant), c1));
      if (q == 0.) // c1 = 0 and c0 = 0: a double root at 0
        {
          roots = {{0., 0.}};
          return 2;
        }
      roots = {{q / c2, c0 / q}};
      if (roots[1] < roots[0])
        std::swap(roots[0], roots[1]);
      return 2;
    }



    /** The next trial point of the bisection of [lo, hi], 0 < lo < hi. */
    double
    bisection_point(const double lo, const double hi)
    {
      // A bracket over orders of magnitude is halved in the exponent, so a
      // root near 1e-12 in [1e-15, 10] takes a few steps, not forty.
      if (lo > 0. && hi > 4. * lo)
        return std::sqrt(lo) * std::sqrt(hi);
      return lo + 0.5 * (hi - lo);
    }



    /**
     * The root in (lo, hi) of a polynomial that is monotone there and has
     * values of opposite signs @p p_lo, @p p_hi at the ends. Newton's method,
     * with a bisection step whenever the Newton step leaves the bracket or
     * does not halve the step before the last one (so the bracket shrinks at
     * least geometrically); each evaluation also tightens the bracket.
     */
    double
    bracketed_root(const PolynomialCoefficients &c,
                   const unsigned int            degree,
                   double                        lo,
                   double                        hi,
                   double                        p_lo,
                   double                        p_hi)
    {
      const bool positive_at_lo = p_lo > 0.;

      // Start from the Newton step off the lower end when it lands in the
      // bracket: for a root much closer to lo than to hi it is already close.
      double x = bisection_point(lo, hi);
      {
        double value, derivative;
        evaluate_with_derivative(c, degree, lo, value, derivative);
        const double newton = lo - value / derivative;
        if (newton > lo && newton < hi)
          x = newton;
      }

      double step_before_last = hi - lo;
      double last_step        = hi - lo;
      for (unsigned int iteration = 0; iteration < 400; ++iteration)
        {
          double value, derivative;
          evaluate_with_derivative(c, degree, x, value, derivative);
          if (value == 0.)
            return x;
          if ((value > 0.) == positive_at_lo)
            {
              lo   = x;
              p_lo = value;
            }
          else
            {
              hi   = x;
              p_hi = value;
            }
          if (hi - lo <= 2. * epsilon * hi)
            break;

          const double newton = x - value / derivative;
          double       next;
          if (derivative != 0. && newton > lo && newton < hi &&
              std::abs(newton - x) <= 0.5 * step_before_last)
            next = newton;
          else
            next = bisection_point(lo, hi);
          if (next <= lo || next >= hi)
            break;

          step_before_last = last_step;
          last_step        = std::abs(next - x);
          if (last_step <= epsilon * x)
            return next;
          x = next;
        }
      return std::abs(p_lo) <= std::abs(p_hi) ? lo : hi;
    }
  } // namespace



  double
  evaluate_polynomial(const PolynomialCoefficients &coefficients,
                      const unsigned int            degree,
                      const double                  t)
  {
    AssertIndexRange(degree, 4);
    double result = coefficients[degree];
    for (unsigned int i = degree; i-- > 0;)
      result = result * t + coefficients[i];
    return result;
  }



  double
  smallest_positive_root(const PolynomialCoefficients &coefficients,
                         const unsigned int            degree)
  {
    AssertThrow(degree <= 3,
                dealii::ExcMessage("smallest_positive_root: degree " +
                                   std::to_string(degree) +
                                   " is not supported (at most 3)"));
    for (unsigned int i = 0; i <= degree; ++i)
      AssertThrow(std::isfinite(coefficients[i]),
                  dealii::ExcMessage("smallest_positive_root: coefficient c" +
                                     std::to_string(i) + " is not finite"));

    // Exactly vanishing leading coefficients lower the degree.
    unsigned int n = degree;
    while (n > 0 && coefficients[n] == 0.)
      --n;
    if (n == 0 && coefficients[0] == 0.)
      return 0.;

    // Divide out roots at t = 0 (they are not positive): c[n] != 0, so this
    // stops at the latest at the leading term.
    unsigned int shift = 0;
    while (coefficients[shift] == 0.)
      ++shift;
    PolynomialCoefficients c = {{0., 0., 0., 0.}};
    n -= shift;
    for (unsigned int i = 0; i <= n; ++i)
      c[i] = coefficients[i + shift];
    if (n == 0)
      return infinity;

    // Scale by a power of two (exact) so the largest coefficient is in
    // [1, 2): no overflow or underflow for coefficients like 1e-300.
    double largest = 0.;
    for (unsigned int i = 0; i <= n; ++i)
      largest = std::max(largest, std::abs(c[i]));
    const int exponent = std::ilogb(largest);
    for (unsigned int i = 0; i <= n; ++i)
      c[i] = std::scalbn(c[i], -exponent);

    if (n == 1)
      {
        const double t = -c[0] / c[1];
        return t > 0. ? t : infinity;
      }

    // Fujiwara's bounds on the root magnitudes |z|: above by
    // 2 max_i |c_i/c_n|^(1/(n-i)), below by the same bound for the reversed
    // polynomial (roots 1/z), each widened by 1.5 so they are strict. No
    // root lies in (0, lower] or beyond upper.
    double upper_ratio = 0., lower_ratio = 0.;
    for (unsigned int i = 0; i < n; ++i)
      upper_ratio =
        std::max(upper_ratio, std::pow(std::abs(c[i] / c[n]), 1. / (n - i)));
    for (unsigned int i = 1; i <= n; ++i)
      lower_ratio =
        std::max(lower_ratio, std::pow(std::abs(c[i] / c[0]), 1. / i));
    double upper = 3. * upper_ratio;
    if (!(upper < std::numeric_limits<double>::max()))
      upper = std::numeric_limits<double>::max();
    const double lower =
      std::isfinite(lower_ratio) ? 1. / (3. * lower_ratio) : 0.;

    // The positive critical points (zeros of p') between the bounds cut
    // (lower, upper) into pieces on which p is monotone.
    std::array<double, 3> ends;
    unsigned int          n_ends = 0;
    {
      std::array<double, 2> critical   = {{0., 0.}};
      unsigned int          n_critical = 0;
      if (n == 2)
        {
          critical[0] = -c[1] / (2. * c[2]);
          n_critical  = 1;
        }
      else
        n_critical = quadratic_real_roots(c[1], 2. * c[2], 3. * c[3], critical);
      for (unsigned int k = 0; k < n_critical; ++k)
        if (critical[k] > lower && critical[k] < upper &&
            (n_ends == 0 || critical[k] > ends[n_ends - 1]))
          ends[n_ends++] = critical[k];
    }
    ends[n_ends++] = upper;

    double a   = lower;
    double p_a = evaluate_polynomial(c, n, a);
    if (p_a == 0.) // only if rounding put a root at the bound
      return a;
    for (unsigned int k = 0; k < n_ends; ++k)
      {
        const double b   = ends[k];
        const double p_b = evaluate_polynomial(c, n, b);
        if (p_b == 0.)
          return b;
        if ((p_a > 0.) != (p_b > 0.))
          return bracketed_root(c, n, a, b, p_a, p_b);
        // p touches zero at a critical point: a multiple root, as far as
        // the rounding error of evaluating p there can tell.
        const bool critical = k + 1 < n_ends;
        if (critical &&
            std::abs(p_b) <= 8. * (n + 1) * epsilon * magnitude(c, n, b))
          return b;
        a   = b;
        p_a = p_b;
      }
    return infinity;
  }
} // namespace bfemp
