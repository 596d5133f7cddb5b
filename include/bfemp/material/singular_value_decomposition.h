#ifndef bfemp_material_singular_value_decomposition_h
#define bfemp_material_singular_value_decomposition_h

#include <bfemp/material/tangent_projection.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * The rotation-variant ("signed") singular value decomposition
   * F = U diag(sigma) V^T of Irving, Teran and Fedkiw (2004, "Invertible
   * finite elements for robust simulation of large deformation"): U and V
   * are proper rotations (det U = det V = 1), |sigma_0| >= ... >=
   * |sigma_(dim-1)|, all sigma_i >= 0 except the last, which carries the sign
   * of det F. An inverted F thus differs from a non-inverted one only in the
   * sign of its smallest singular value, which is what lets an isotropic
   * energy be written as a smooth function psi(sigma) through inversion
   * (and is the convention of the polar decomposition in FixedCorotated).
   */
  template <int dim>
  struct SingularValueDecomposition
  {
    /** Left singular vectors u_i = U e_i, a proper rotation. */
    Tensor<2, dim> U;
    /** Signed singular values, by decreasing magnitude. */
    Tensor<1, dim> sigma;
    /** Right singular vectors v_i = V e_i, a proper rotation. */
    Tensor<2, dim> V;
  };

  /**
   * The signed SVD of @p F by one-sided (Hestenes) Jacobi: plane rotations
   * applied from the right make the columns of F V mutually orthogonal, so
   * F V = U diag(sigma). Working on F itself keeps the small singular values
   * of strongly compressed states accurate to epsilon sigma_max, where going
   * through the eigenvalues of F^T F would give epsilon sigma_max^2 /
   * sigma_min. Repeated singular values need no special case: the columns
   * are then already orthogonal in the degenerate subspace. In 2D one
   * rotation is exact; in 3D the sweeps converge quadratically (typically
   * four or five sweeps, including the one that finds nothing left to
   * rotate). The left vectors of the two largest singular values are the
   * normalised columns; the last one is their cross product (2D: the
   * perpendicular), so that det U = 1 by construction and sigma_(dim-1) =
   * u_(dim-1) . F v_(dim-1) comes out with the sign of det F. Any F is
   * accepted, including singular ones (missing directions are completed
   * orthonormally).
   */
  template <int dim>
  SingularValueDecomposition<dim>
  signed_singular_value_decomposition(const Tensor<2, dim> &F);

  /**
   * The PSD projection of the tangent d^2 psi / dF dF of an isotropic energy
   * psi(F) = Psi(sigma), from its analytic eigen-system in the signed SVD
   * basis (Smith, de Goes, Kim 2019, "Analytic eigensystems for isotropic
   * distortion energies"; Teran, Sifakis, Irving, Fedkiw 2005, "Robust
   * quasistatic finite elements and flesh simulation"). With
   * D_i = u_i v_i^T and, for i < j, the "twist" and "flip" matrices
   * T_ij = (u_i v_j^T - u_j v_i^T) / sqrt(2),
   * L_ij = (u_i v_j^T + u_j v_i^T) / sqrt(2), the dim^2 matrices D_i, T_ij,
   * L_ij are an orthonormal basis in which the tangent is block diagonal:
   *  - on span{D_i}: the dim x dim Hessian H_ij = d^2 Psi / dsigma_i dsigma_j
   *    (@p singular_value_hessian), whose eigenvectors e_k give the "scaling"
   *    eigenvectors sum_i (e_k)_i D_i;
   *  - T_ij with eigenvalue (Psi_i + Psi_j) / (sigma_i + sigma_j)
   *    (@p twist_eigenvalues[i][j]);
   *  - L_ij with eigenvalue (Psi_i - Psi_j) / (sigma_i - sigma_j)
   *    (@p flip_eigenvalues[i][j]),
   * where Psi_i = dPsi / dsigma_i. The caller passes the ratios in a form
   * simplified for its energy, so that they stay exact for
   * sigma_i -> sigma_j; only the entries i != j of the twist and flip
   * tensors are read. Where H is positive definite (the common case) the
   * scaling block is assembled from the Cholesky factor of H instead of its
   * eigenvectors, which is cheaper and gives the same (unprojected) block.
   * The result sum_m max(lambda_m, 0) q_m q_m^T (or, with @p filter
   * absolute, sum_m |lambda_m| q_m q_m^T) uses index order (i, j, k, l)
   * of dP_ij / dF_kl, as Material::first_piola_kirchhoff_derivative(), and is
   * exactly symmetric.
   */
  template <int dim>
  Tensor<4, dim>
  project_isotropic_tangent(
    const SingularValueDecomposition<dim> &svd,
    const SymmetricTensor<2, dim>         &singular_value_hessian,
    const SymmetricTensor<2, dim>         &twist_eigenvalues,
    const SymmetricTensor<2, dim>         &flip_eigenvalues,
    const EigenvalueFilter                 filter = EigenvalueFilter::clamp);
} // namespace bfemp

#endif
