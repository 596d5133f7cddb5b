#ifndef bfemp_solver_positive_semidefinite_h
#define bfemp_solver_positive_semidefinite_h

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
} // namespace bfemp

#endif
