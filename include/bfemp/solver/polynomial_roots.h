#ifndef bfemp_solver_polynomial_roots_h
#define bfemp_solver_polynomial_roots_h

#include <array>

namespace bfemp
{
  /**
   * Coefficients c0, c1, c2, c3 of p(t) = c0 + c1 t + c2 t^2 + c3 t^3. A
   * polynomial of lower degree leaves the higher coefficients unused.
   */
  using PolynomialCoefficients = std::array<double, 4>;

  /** p(t) by Horner's rule, using the coefficients up to @p degree. */
  double
  evaluate_polynomial(const PolynomialCoefficients &coefficients,
                      const unsigned int            degree,
                      const double                  t);

  /**
   * The smallest real root t > 0 of the polynomial of degree @p degree <= 3
   * with @p coefficients (entries above @p degree are ignored), or +infinity
   * if it has none. This is the kernel of the line search's step bound: the
   * largest step that keeps det F > 0 is the first positive zero of
   * det(A + t B), a polynomial of degree dim in t (see
   * determinant_step_bound()).
   *
   * Why not the closed-form formulas: they lose the small root of a
   * quadratic to cancellation, Cardano's formula is ill-conditioned near
   * multiple roots, and both break when the leading coefficient is tiny but
   * nonzero. Instead the positive half-line is cut at the positive critical
   * points (zeros of p', from the cancellation-free quadratic formula) and
   * at a strict upper bound of all root magnitudes (Fujiwara's bound, times
   * 1.5). On each piece p is monotone, so it has at most one root there,
   * and it has one exactly when p changes sign between the ends; the pieces
   * are searched from left to right and the root is found by Newton's
   * method safeguarded by bisection (geometric bisection when the bracket
   * spans orders of magnitude, so roots like 1e-12 next to 1 converge
   * quickly). Hence:
   * - no sign change in (0, infinity) is missed, and no point where p keeps
   *   its sign is returned, except:
   * - a critical point where p touches zero (a double root; a local extremum
   *   whose value is within the rounding error of evaluating p there) also
   *   counts: det F reaches zero there, so the step must stop before it;
   * - leading coefficients that are exactly zero lower the degree; tiny
   *   nonzero ones are kept, so the (large) root they create is still found
   *   correctly and the small roots are those of the lower-degree part;
   * - the coefficients are first scaled by a power of two (exactly), so the
   *   result does not depend on their overall magnitude (1e-30 or 1e30);
   * - a root at t = 0 (c0 = 0) is divided out, as it is not positive;
   * - the zero polynomial (every t is a root) gives 0.
   *
   * The result is accurate to a few units in the last place for simple
   * roots and to about sqrt(machine epsilon) relative for double roots.
   * Throws if a coefficient is not finite.
   */
  double
  smallest_positive_root(const PolynomialCoefficients &coefficients,
                         const unsigned int            degree);
} // namespace bfemp

#endif
