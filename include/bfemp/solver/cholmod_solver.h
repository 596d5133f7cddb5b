#ifndef bfemp_solver_cholmod_solver_h
#define bfemp_solver_cholmod_solver_h

#include <bfemp/solver/linear_solver.h>

#include <memory>

namespace bfemp
{
  /**
   * Supernodal Cholesky factorization H = L L^T of SuiteSparse CHOLMOD: the
   * default and fastest direct solver for the SPD Newton systems ("Linear
   * solver = CHOLMOD"). It exploits the symmetry that UMFPACK's LU ignores,
   * so it needs about half the memory and flops, and dense supernodes run
   * through BLAS.
   *
   * CHOLMOD receives the upper triangle of H in compressed-column form
   * (stype = 1); because H is symmetric, that is deal.II's lower triangle
   * read row by row, so no transposition is needed.
   *
   * The fill-reducing ordering and symbolic factorization (cholmod_analyze)
   * depend only on the sparsity pattern. They are computed again only when
   * the pattern's structure differs from the last one (compared by content,
   * see LinearSolver::record_sparsity_pattern()); otherwise factorize() only
   * copies the new values and redoes the numeric factorization.
   *
   * The CHOLMOD objects live behind a pointer to an implementation so that
   * users of this header do not need the SuiteSparse headers; they are freed
   * in the destructor.
   */
  class CholmodSolver : public LinearSolver
  {
  public:
    CholmodSolver();

    ~CholmodSolver() override;

    /**
     * Factorizes @p matrix, reusing the symbolic analysis while the pattern is
     * unchanged. Throws a SimulationError if @p matrix is not positive
     * definite (or not finite); solve() is then unavailable until a
     * factorize() succeeds.
     */
    void
    factorize(const SparseMatrix<double> &matrix) override;

    /** As factorize(), but false instead of the error if not definite. */
    bool
    factorize_if_positive_definite(const SparseMatrix<double> &matrix) override;

    void
    solve(const Vector<double> &rhs, Vector<double> &solution) override;

    /** "CHOLMOD". */
    std::string
    name() const override;

    unsigned int
    n_symbolic_analyses() const override;

  private:
    /** The CHOLMOD workspace, matrix, factor and solve buffers. */
    struct Data;

    std::unique_ptr<Data> data;

    unsigned int n_analyses = 0;

    /** Whether the last factorize() succeeded. */
    bool factorized = false;

    /** The pivot at which the last failed factorization broke down. */
    std::size_t failed_pivot = 0;
  };
} // namespace bfemp

#endif
