#ifndef bfemp_solver_umfpack_solver_h
#define bfemp_solver_umfpack_solver_h

#include <bfemp/solver/linear_solver.h>

#include <deal.II/lac/sparse_direct.h>

namespace bfemp
{
  /**
   * Sparse LU factorization through deal.II's SparseDirectUMFPACK ("Linear
   * solver = UMFPACK"). It ignores the symmetry of the Newton matrix, so it
   * costs about twice CHOLMOD's memory and time, and deal.II's wrapper redoes
   * the symbolic analysis in every factorize(). Its pivoting makes it the
   * robust reference: it also factorizes symmetric indefinite matrices, which
   * helps when diagnosing a failed tangent projection.
   */
  class UmfpackSolver : public LinearSolver
  {
  public:
    /**
     * Factorizes @p matrix; throws a SimulationError if UMFPACK reports a
     * singular matrix or another failure.
     */
    void
    factorize(const SparseMatrix<double> &matrix) override;

    void
    solve(const Vector<double> &rhs, Vector<double> &solution) override;

    /** "UMFPACK". */
    std::string
    name() const override;

    /** The number of factorizations: each one includes a symbolic analysis. */
    unsigned int
    n_symbolic_analyses() const override;

  private:
    SparseDirectUMFPACK umfpack;

    unsigned int n_analyses = 0;

    /** Whether the last factorize() succeeded. */
    bool factorized = false;
  };
} // namespace bfemp

#endif
