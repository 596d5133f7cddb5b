#ifndef bfemp_material_neo_hookean_h
#define bfemp_material_neo_hookean_h

#include <bfemp/material/material.h>

namespace bfemp
{
  /**
   * Compressible neo-Hookean solid, the model of the BFEMP paper (eq. 7):
   * @f[
   *   \psi(F) = \frac{\mu}{2}\left(\mathrm{tr}(F^T F) - d\right)
   *             - \mu \ln J + \frac{\lambda}{2} (\ln J)^2,
   *   \qquad J = \det F,
   * @f]
   * with d = dim, so that
   * @f[
   *   P = \mu (F - F^{-T}) + \lambda \ln J \, F^{-T}.
   * @f]
   *
   * The energy is only defined for J > 0. energy_density() returns
   * +infinity for J <= 0, so that a line search that evaluates the energy at
   * an inverted trial state rejects it (the "line search filter" of the
   * paper, Remark 1) instead of failing on a NaN. The stress and its
   * derivative require J > 0; this is checked in debug mode only.
   */
  template <int dim>
  class NeoHookean : public Material<dim>
  {
  public:
    explicit NeoHookean(const ElasticModuli &moduli);

    /** psi(F) of eq. 7; +infinity if det F <= 0. */
    double
    energy_density(const Tensor<2, dim> &F) const override;

    /** P = mu (F - F^-T) + lambda ln J F^-T; requires det F > 0. */
    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override;

    /**
     * dP_ij/dF_kl = mu delta_ik delta_jl + lambda F^-T_ij F^-T_kl
     *               + (mu - lambda ln J) F^-T_il F^-T_kj,
     * using d(F^-T)_ij/dF_kl = -F^-T_il F^-T_kj; requires det F > 0.
     */
    Tensor<4, dim>
    first_piola_kirchhoff_derivative(const Tensor<2, dim> &F) const override;

    /**
     * The PSD projection of dP/dF from the analytic eigen-system (see
     * project_isotropic_tangent()) of eq. 7 written in the singular values
     * sigma_i of F, with J = prod sigma_i:
     * @f[
     *   \Psi = \frac{\mu}{2}\Big(\sum_i \sigma_i^2 - d\Big) - \mu \ln J
     *          + \frac{\lambda}{2} (\ln J)^2, \qquad
     *   \Psi_i = \mu \sigma_i + \frac{\lambda \ln J - \mu}{\sigma_i},
     * @f]
     * @f[
     *   \frac{\partial^2 \Psi}{\partial \sigma_i^2}
     *     = \mu + \frac{\mu + \lambda (1 - \ln J)}{\sigma_i^2}, \qquad
     *   \frac{\partial^2 \Psi}{\partial \sigma_i \partial \sigma_j}
     *     = \frac{\lambda}{\sigma_i \sigma_j} \ (i \ne j),
     * @f]
     * and, for each pair i < j, the twist and flip eigenvalues, in which the
     * difference quotient cancels exactly (no division by sigma_i -
     * sigma_j, so repeated singular values need no limit):
     * @f[
     *   \frac{\Psi_i + \Psi_j}{\sigma_i + \sigma_j}
     *     = \mu + \frac{\lambda \ln J - \mu}{\sigma_i \sigma_j}, \qquad
     *   \frac{\Psi_i - \Psi_j}{\sigma_i - \sigma_j}
     *     = \mu + \frac{\mu - \lambda \ln J}{\sigma_i \sigma_j}.
     * @f]
     * Equal to the numerical projection of the base class (to round-off),
     * at a fraction of its cost. Requires det F > 0 (debug-mode check).
     */
    Tensor<4, dim>
    filtered_first_piola_kirchhoff_derivative(
      const Tensor<2, dim>  &F,
      const EigenvalueFilter filter) const override;

    /** "neo-Hookean". */
    std::string
    name() const override;
  };
} // namespace bfemp

#endif
