#ifndef bfemp_contact_friction_mollifier_h
#define bfemp_contact_friction_mollifier_h

// The mollified friction magnitude of BFEMP eq. 36 and the friction
// pseudo-potential's f0 (eq. 37), with the combinations the gradient and
// Hessian of the lagged friction potential need.

namespace bfemp
{
  /**
   * The friction mollifier of eq. 36 for the sliding threshold
   * eps = eps_v dt (a displacement: sliding displacements |u| below it are
   * treated as static),
   * @f[
   *   f_1(y) = -\frac{y^2}{\epsilon^2} + \frac{2y}{\epsilon}, \quad
   *   y \in [0, \epsilon), \qquad f_1(y) = 1, \quad y \ge \epsilon,
   * @f]
   * and its antiderivative f0 (f0' = f1),
   *   f0(y) = -y^3/(3 eps^2) + y^2/eps + eps/3 for y < eps, f0(y) = y beyond,
   * whose constant eps/3 makes f0 continuous at eps, so f0 is C1 (and f1 is
   * C1 too: f1(eps) = 1 and f1'(eps) = 0 from both sides).
   *
   * The lagged friction potential of a contact pair is mu lambda f0(|u|)
   * (eq. 37) with the sliding displacement u in R^{d-1}. Its gradient with
   * respect to u is mu lambda f1(y) u/y and its Hessian
   *   mu lambda [ f1(y)/y I + (f1'(y) y - f1(y))/y^3 u u^T ]
   *   = mu lambda [ f1(y)/y I + (f1'(y) - f1(y)/y) u u^T / y^2 ],
   * y = |u|. The functions below provide f1(y)/y, which tends to 2/eps as
   * y -> 0, and the coefficient of the second term in both forms. Below
   * eps, (f1' y - f1)/y^3 = -1/(eps^2 y) is singular at y = 0 (the product
   * with u u^T, of size y^2, tends to 0), whereas f1' - f1/y = -y/eps^2,
   * the coefficient of the unit-vector form u u^T / y^2, tends to 0 and
   * is well-defined at y = 0.
   */
  class FrictionMollifier
  {
  public:
    /** Throws unless @p sliding_threshold = eps_v dt is positive and
     *  finite. */
    explicit FrictionMollifier(const double sliding_threshold);

    /** eps_v dt. */
    double
    sliding_threshold() const;

    /** f0(y), the antiderivative of f1 with f0(y) = y for y >= eps. */
    double
    f0(const double y) const;

    /** f1(y) of eq. 36. */
    double
    f1(const double y) const;

    /** f1(y)/y: (2 - y/eps)/eps below eps (2/eps at y = 0), 1/y beyond. */
    double
    f1_over_y(const double y) const;

    /**
     * (f1'(y) y - f1(y))/y^3, the derivative of f1(y)/y divided by y:
     * -1/(eps^2 y) below eps, -1/y^3 beyond. Singular at y = 0; only for
     * y > 0 (use f1_derivative_minus_f1_over_y() where y may vanish).
     */
    double
    f1_over_y_derivative_over_y(const double y) const;

    /**
     * f1'(y) - f1(y)/y = (f1'(y) y - f1(y))/y, the coefficient of
     * u u^T / |u|^2 in the Hessian: -y/eps^2 below eps (0 at y = 0),
     * -1/y beyond.
     */
    double
    f1_derivative_minus_f1_over_y(const double y) const;

  private:
    double epsilon;
    double inverse_epsilon;
  };
} // namespace bfemp

#endif
