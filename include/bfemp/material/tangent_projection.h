#ifndef bfemp_material_tangent_projection_h
#define bfemp_material_tangent_projection_h

#include <deal.II/base/tensor.h>

#include <array>

namespace bfemp
{
  using namespace dealii;

  /**
   * What replaces the negative eigenvalues of a local Hessian (a material
   * tangent dP/dF, a contact stencil's Hessian) so that it is positive
   * semi-definite, or none of that.
   */
  enum class EigenvalueFilter
  {
    /** The exact matrix, possibly indefinite. */
    none,
    /**
     * Negative eigenvalues set to 0: the nearest PSD matrix in the Frobenius
     * norm, the projected Newton of BFEMP Section 5.
     */
    clamp,
    /**
     * Negative eigenvalues replaced by their absolute values (Chen et al.,
     * "Trust-region eigenvalue filtering for projected Newton", SIGGRAPH
     * Asia 2024): the direction of negative curvature keeps a curvature of
     * the same size instead of none, which a clamped model overshoots along.
     */
    absolute
  };

  /** The eigenvalue lambda after @p filter (clamp or absolute). */
  inline double
  filtered_eigenvalue(const double lambda, const EigenvalueFilter filter)
  {
    if (lambda >= 0. || filter == EigenvalueFilter::none)
      return lambda;
    return filter == EigenvalueFilter::absolute ? -lambda : 0.;
  }

  /**
   * Projection of a material tangent dP/dF onto the positive semi-definite
   * cone, the building block of projected Newton (BFEMP Section 5): each
   * quadrature point's tangent is projected before the chain rule, so every
   * assembled Hessian is PSD by construction.
   *
   * dP/dF is read as the symmetric dim^2 x dim^2 matrix A_(ij),(kl) =
   * d^2 psi / dF_ij dF_kl. Its eigen-decomposition A = sum_m lambda_m q_m
   * q_m^T is computed by cyclic Jacobi rotations (allocation free, accurate
   * for these 4 x 4 and 9 x 9 matrices), and the projection keeps
   * sum_m max(lambda_m, 0) q_m q_m^T: the PSD matrix nearest to A in the
   * Frobenius norm.
   */
  template <int dim>
  class TangentProjection
  {
  public:
    static constexpr unsigned int n = dim * dim;

    /** Eigen-decomposes the symmetric part of @p tangent. */
    explicit TangentProjection(const Tensor<4, dim> &tangent);

    /** The projected tangent sum_m max(lambda_m, 0) q_m q_m^T. */
    Tensor<4, dim>
    projected() const;

    /**
     * sum_m f(lambda_m) q_m q_m^T with f the @p filter's
     * (filtered_eigenvalue()).
     */
    Tensor<4, dim>
    filtered(const EigenvalueFilter filter) const;

    /** Eigenvalues in ascending order. */
    const std::array<double, n> &
    eigenvalues() const;

  private:
    void
    diagonalize();

    void
    sort_eigenpairs();

    /** Working matrix, diagonal after diagonalize(). */
    double a[n][n];
    /** Columns are the eigenvectors. */
    double q[n][n];

    std::array<double, n> lambda;
  };

  /** Shorthand: the PSD projection of a tangent dP/dF. */
  template <int dim>
  Tensor<4, dim>
  project_to_positive_semidefinite(const Tensor<4, dim> &tangent);
} // namespace bfemp

#endif
