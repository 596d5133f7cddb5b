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

    /**
     * The PSD projection of the constant tangent, computed once in the
     * constructor. Read as a dim^2 x dim^2 matrix, the tangent is
     * mu (I + T) + lambda vec(I) vec(I)^T, with T the transposition; its
     * eigenvalues are 0 on the skew tensors (multiplicity
     * dim (dim - 1) / 2), 2 mu on the symmetric traceless tensors and
     * 2 mu + dim lambda on the identity. It is therefore PSD iff mu >= 0
     * and lambda + 2 mu / dim >= 0, the d-dimensional bulk modulus. For
     * moduli from E > 0 and -1 < nu < 1/2 (ElasticModuli::
     * from_young_poisson(), the range the prm file allows) that always
     * holds: mu = E / (2 (1 + nu)) > 0; in 3D lambda + 2 mu / 3 =
     * E / (3 (1 - 2 nu)) > 0; in 2D plane strain lambda + mu =
     * E / (2 (1 + nu) (1 - 2 nu)) > 0, even though lambda itself is
     * negative for nu < 0. The tangent is then returned unchanged. Only
     * moduli set directly outside that range get the clamped spectral
     * projection max(2 mu, 0) (sym - vec(I) vec(I)^T / dim)
     * + max(2 mu + dim lambda, 0) vec(I) vec(I)^T / dim.
     */
    Tensor<4, dim>
    filtered_first_piola_kirchhoff_derivative(
      const Tensor<2, dim>  &F,
      const EigenvalueFilter filter) const override;

    /** "linear elastic". */
    std::string
    name() const override;

  private:
    /** The tangent does not depend on F, so it is built once. */
    Tensor<4, dim> tangent;

    /** Its PSD projection, equal to #tangent for admissible moduli. */
    Tensor<4, dim> projected_tangent;

    /** With |eigenvalues|, equal to #tangent for admissible moduli. */
    Tensor<4, dim> absolute_tangent;
  };
} // namespace bfemp

#endif
