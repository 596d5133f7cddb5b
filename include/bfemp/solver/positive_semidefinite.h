#ifndef bfemp_solver_positive_semidefinite_h
#define bfemp_solver_positive_semidefinite_h

#include <bfemp/material/tangent_projection.h>

#include <deal.II/lac/full_matrix.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * Replaces the symmetric matrix by its nearest positive semi-definite
   * matrix in the Frobenius norm: negative eigenvalues set to 0 (projected
   * Newton, BFEMP Section 5). For the local Hessians of contact stencils,
   * whose size varies with the primitives near a particle.
   */
  void
  project_to_positive_semidefinite(FullMatrix<double> &matrix);

  /**
   * Replaces the negative eigenvalues of the symmetric matrix as @p filter
   * says (clamp: project_to_positive_semidefinite(); absolute: their
   * absolute values; none: no change).
   */
  void
  filter_eigenvalues(FullMatrix<double> &matrix, const EigenvalueFilter filter);
} // namespace bfemp

#endif
