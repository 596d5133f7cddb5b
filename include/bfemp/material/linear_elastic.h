#ifndef bfemp_material_linear_elastic_h
#define bfemp_material_linear_elastic_h

#include <bfemp/material/material.h>

namespace bfemp
{
  /**
   * Small-strain linear elasticity written on F:
   * @f[
   *   \varepsilon = \tfrac12 (F + F^T) - I, \qquad
   *   \psi = \mu\, \varepsilon : \varepsilon
   *          + \frac{\lambda}{2} (\mathrm{tr}\,\varepsilon)^2, \qquad
   *   P = 2 \mu \varepsilon + \lambda\, \mathrm{tr}(\varepsilon) I.
   * @f]
   * It is not frame invariant (a rigid rotation produces stress); it is the
   * reference the nonlinear models reduce to at F = I and is useful for
   * verification against linear analytical solutions.
   */
  template <int dim>
  class LinearElastic : public Material<dim>
  {
  public:
    explicit LinearElastic(const ElasticModuli &moduli);

    /** psi = mu eps:eps + lambda/2 tr(eps)^2. */
    double
    energy_density(const Tensor<2, dim> &F) const override;

    /** P = 2 mu eps + lambda tr(eps) I. */
    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override;

    /**
     * The constant tangent
     * dP_ij/dF_kl = mu (delta_ik delta_jl + delta_il delta_jk)
     *               + lambda delta_ij delta_kl.
     */
    Tensor<4, dim>
    first_piola_kirchhoff_derivative(const Tensor<2, dim> &F) const override;

    /** "linear elastic". */
    std::string
    name() const override;

  private:
    /** The tangent does not depend on F, so it is built once. */
    Tensor<4, dim> tangent;
  };
} // namespace bfemp

#endif
