#ifndef bfemp_solver_cg_amg_solver_h
#define bfemp_solver_cg_amg_solver_h

#include <bfemp/solver/linear_solver.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace bfemp
{
  /**
   * Conjugate gradients preconditioned with Trilinos ML algebraic multigrid
   * ("Linear solver = CG AMG"). CG needs only an SPD matrix, which projected
   * Newton guarantees, and AMG keeps the iteration count nearly independent
   * of the grid size; memory grows linearly with the unknowns, unlike the
   * fill-in of a direct factorization, so this is the solver for large 3D
   * grids. The Newton step is only as accurate as the CG tolerance, which
   * the Newton convergence test must allow for.
   *
   * The matrix is copied into a serial Trilinos matrix (on MPI_COMM_SELF:
   * the Newton system is not distributed). Its graph is built again only
   * when the sparsity pattern changes (compared by content, see
   * LinearSolver::record_sparsity_pattern()); otherwise only the values are
   * replaced. The AMG hierarchy depends on the values and is rebuilt in
   * every factorize().
   */
  class CgAmgSolver : public LinearSolver
  {
  public:
    /**
     * CG stops when the residual norm is below @p relative_tolerance times
     * the norm of the right-hand side and fails after @p max_iterations
     * iterations.
     */
    CgAmgSolver(const double       relative_tolerance = 1e-10,
                const unsigned int max_iterations     = 10000);

    /**
     * The near-null space for ML's aggregation: one mask per vector
     * component marking its unknowns, as DoFTools::extract_constant_modes()
     * returns (the unknowns of one node must be numbered consecutively).
     * Without it (the default) ML treats the unknowns as a scalar field,
     * which works but converges more slowly for vector problems. Applies
     * from the next factorize().
     */
    void
    set_constant_modes(
      const std::vector<std::vector<bool>> &constant_modes) override;

    /** Copies @p matrix to Trilinos and builds the AMG preconditioner. */
    void
    factorize(const SparseMatrix<double> &matrix) override;

    /**
     * Runs CG from a zero initial guess; throws a SimulationError if it does
     * not reach the tolerance within the maximum number of iterations.
     */
    void
    solve(const Vector<double> &rhs, Vector<double> &solution) override;

    /** "CG AMG". */
    std::string
    name() const override;

    /** How many times the Trilinos matrix graph was built. */
    unsigned int
    n_symbolic_analyses() const override;

    /** The number of CG iterations of the last solve(). */
    unsigned int
    last_n_iterations() const;

  private:
    const double       relative_tolerance;
    const unsigned int max_iterations;

    std::vector<std::vector<bool>> constant_modes;

    TrilinosWrappers::SparseMatrix    matrix;
    TrilinosWrappers::PreconditionAMG preconditioner;

    unsigned int n_analyses         = 0;
    unsigned int n_iterations       = 0;
    bool         preconditioner_set = false;
  };
} // namespace bfemp

#endif
