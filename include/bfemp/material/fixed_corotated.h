#ifndef bfemp_material_fixed_corotated_h
#define bfemp_material_fixed_corotated_h

#include <bfemp/material/material.h>

namespace bfemp
{
  /**
   * Fixed corotated elasticity (Stomakhin, Howes, Schroeder, Teran, 2012,
   * "Energetically consistent invertible elasticity"):
   * @f[
   *   \psi(F) = \mu \| F - R \|_F^2 + \frac{\lambda}{2} (J - 1)^2, \qquad
   *   P = 2 \mu (F - R) + \lambda (J - 1) J F^{-T},
   * @f]
   * where R is the rotation closest to F, i.e. the rotation of the polar
   * decomposition F = R S (for det F < 0, the proper rotation for which S
   * has one negative eigenvalue, as in the paper's sign-fixed SVD). Unlike
   * neo-Hookean, psi stays finite through inversion, but R, and therefore
   * all three functions, need det F != 0.
   *
   * The tangent uses dR = R W, with W skew: differentiating F = R S gives
   * R^T dF - dF^T R = W S + S W, which in 3D is the linear system
   * (tr(S) I - S) w = axial(R^T dF - dF^T R) for the axial vector w of W and
   * in 2D the scalar equation tr(S) w = (R^T dF - dF^T R)_10. The system is
   * singular only where R is not differentiable (two signed singular values
   * summing to zero, possible only for inverted F).
   */
  template <int dim>
  class FixedCorotated : public Material<dim>
  {
  public:
    explicit FixedCorotated(const ElasticModuli &moduli);

    /** psi = mu ||F - R||^2 + lambda/2 (J - 1)^2. */
    double
    energy_density(const Tensor<2, dim> &F) const override;

    /** P = 2 mu (F - R) + lambda (J - 1) J F^-T. */
    Tensor<2, dim>
    first_piola_kirchhoff(const Tensor<2, dim> &F) const override;

    /**
     * dP/dF = 2 mu (I - dR/dF) + lambda cof(F) x cof(F)
     *         + lambda (J - 1) d cof(F)/dF, with cof(F) = J F^-T and dR/dF as
     * described in the class documentation.
     */
    Tensor<4, dim>
    first_piola_kirchhoff_derivative(const Tensor<2, dim> &F) const override;

    /**
     * The PSD projection of dP/dF from the analytic eigen-system (see
     * project_isotropic_tangent()). In the signed singular values (R = U
     * V^T is the rotation of the class documentation, so inversion only
     * flips the sign of the smallest sigma_i) the energy is
     * @f[
     *   \Psi = \mu \sum_i (\sigma_i - 1)^2 + \frac{\lambda}{2} (J - 1)^2,
     *   \qquad J = \prod_i \sigma_i, \qquad
     *   \Psi_i = 2 \mu (\sigma_i - 1) + \lambda (J - 1) J_i,
     * @f]
     * with J_i = prod_{k != i} sigma_k, so that
     * @f[
     *   \frac{\partial^2 \Psi}{\partial \sigma_i^2} = 2 \mu + \lambda J_i^2,
     *   \qquad
     *   \frac{\partial^2 \Psi}{\partial \sigma_i \partial \sigma_j}
     *     = \lambda \left(J_i J_j + (J - 1) J_{ij}\right) \ (i \ne j),
     * @f]
     * with J_ij = prod_{k != i, j} sigma_k (1 in 2D). Since J_i - J_j =
     * (sigma_j - sigma_i) J_ij and J_i + J_j = (sigma_i + sigma_j) J_ij, the
     * twist and flip eigenvalues of the pair i < j are
     * @f[
     *   \frac{\Psi_i + \Psi_j}{\sigma_i + \sigma_j}
     *     = 2 \mu + \lambda (J - 1) J_{ij}
     *       - \frac{4 \mu}{\sigma_i + \sigma_j}, \qquad
     *   \frac{\Psi_i - \Psi_j}{\sigma_i - \sigma_j}
     *     = 2 \mu - \lambda (J - 1) J_{ij},
     * @f]
     * exact for repeated singular values. The twist eigenvalue is singular
     * where sigma_i + sigma_j = 0, the set (inverted F only) on which R,
     * and so the tangent itself, is not differentiable.
     */
    Tensor<4, dim>
    filtered_first_piola_kirchhoff_derivative(
      const Tensor<2, dim>  &F,
      const EigenvalueFilter filter) const override;

    /** "fixed corotated". */
    std::string
    name() const override;
  };
} // namespace bfemp

#endif
