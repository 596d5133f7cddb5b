#ifndef bfemp_contact_barrier_h
#define bfemp_contact_barrier_h

// The smoothly clamped log barrier of the contact potential, BFEMP eq. 27,
// as a function of the squared distance, so that it composes with the
// squared distances of distance.h.

namespace bfemp
{
  /**
   * The barrier b and its first and second derivatives with respect to the
   * squared distance s = d^2.
   */
  struct BarrierDerivatives
  {
    double value;
    double first;
    double second;
  };

  /**
   * The barrier of eq. 27,
   * @f[
   *   b(d, \hat d) = -\kappa (d/\hat d - 1)^2 \ln(d/\hat d),
   *   \quad 0 < d < \hat d,
   * @f]
   * and 0 for d >= dhat, evaluated at d = sqrt(s), with db/ds and
   * d^2b/ds^2.
   *
   * Why s = d^2 and not d: the distances (distance.h) are computed as d^2,
   * whose derivatives with respect to the coordinates are polynomial or
   * rational and bounded at d = 0, while those of d = sqrt(d^2) involve
   * 1/d. The contact energy of a pair is then exactly the paper's b(d),
   * not a modified barrier in d^2 (as IPC's b(d^2, dhat^2) would be), with
   * the chain rule
   *   grad b = b_s grad s,  Hess b = b_ss grad s grad s^T + b_s Hess s.
   * With x = d/dhat,
   *   b_s  = -kappa (x - 1)(2 x ln x + x - 1) / (2 s),
   *   b_ss = -kappa (x ln x + x^2 - 1) / (2 s^2).
   * For 0 < x < 1 the factors of each have equal signs, so these forms do
   * not cancel: b > 0, b_s < 0 and b_ss > 0 (b is decreasing and convex in
   * s, so the term b_ss grad s grad s^T is positive semi-definite). At
   * s = dhat^2 the value and both derivatives vanish (b is C2 in s, and in
   * d, across dhat). Near dhat, b ~ kappa (1 - s/dhat^2)^3 / 8, so the
   * rounding of s alone changes b by a relative 3 epsilon/(1 - s/dhat^2)
   * (likewise for b_s, b_ss); x - 1 is formed as (d - dhat)/dhat (an exact
   * difference there) and ln x as log1p(x - 1), so no cancellation adds to
   * that (the test measures below 1e-14/(1 - s/dhat^2)). For tiny s, ln x
   * comes from log(d/dhat) directly, and b_ss divides by s twice rather
   * than by s^2, which would underflow.
   *
   * s >= dhat^2 gives zeros; s <= 0 (contact, or a crossing) gives
   * value = +infinity, first = -infinity, second = +infinity.
   * @p kappa is the barrier stiffness (Pa, eq. 27).
   */
  BarrierDerivatives
  barrier_of_squared_distance(const double s,
                              const double dhat,
                              const double kappa);

  /**
   * b(d, dhat) of eq. 27 in terms of the distance d itself: 0 for
   * d >= dhat, +infinity for d <= 0.
   */
  double
  barrier(const double d, const double dhat, const double kappa);
} // namespace bfemp

#endif
