#ifndef bfemp_solver_linear_solver_h
#define bfemp_solver_linear_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * A solver for the linear system H p = -g of one projected Newton iteration
   * (BFEMP Section 5). H is symmetric positive definite by construction (the
   * tangents are projected onto the PSD cone and a positive mass term is
   * added), and is stored as a deal.II SparseMatrix whose SparsityPattern
   * holds both triangles.
   *
   * The work is split in two so that the Newton loop can factorize once and
   * solve several right-hand sides (a line search does not change H), and so
   * that implementations can keep pattern-dependent work (the fill-reducing
   * ordering and symbolic factorization, the Trilinos graph) between
   * iterations and time steps: the grid's active nodes, hence the pattern,
   * change far less often than the values.
   *
   * Failures of the solve itself (a matrix that is not positive definite, CG
   * that does not converge) throw a SimulationError naming the solver.
   */
  class LinearSolver
  {
  public:
    LinearSolver() = default;

    /** Solvers own factorizations or external handles: never copied. */
    LinearSolver(const LinearSolver &) = delete;

    LinearSolver &
    operator=(const LinearSolver &) = delete;

    virtual ~LinearSolver() = default;

    /**
     * Factorizes (direct solvers) or builds the preconditioner (iterative
     * solvers) for the symmetric positive definite @p matrix. The solver keeps
     * what it needs: @p matrix may change or go away afterwards.
     */
    virtual void
    factorize(const SparseMatrix<double> &matrix) = 0;

    /**
     * factorize() for a symmetric @p matrix that may be indefinite (the
     * exact Hessian): returns false, with nothing factorized, where the
     * solver finds it is not positive definite. Solvers that cannot tell
     * (LU, CG) factorize and return true; their caller must check that the
     * direction descends.
     */
    virtual bool
    factorize_if_positive_definite(const SparseMatrix<double> &matrix);

    /**
     * Solves matrix * solution = rhs with the matrix of the last successful
     * factorize(). @p solution is resized as needed; its content on entry is
     * ignored.
     */
    virtual void
    solve(const Vector<double> &rhs, Vector<double> &solution) = 0;

    /** The name of the solver as in the prm entry, for messages. */
    /**
     * The near-null space of the matrices to come, one mask per vector
     * component (its unknowns). Direct solvers do not need it; the default
     * ignores it. Applies from the next factorize().
     */
    virtual void
    set_constant_modes(const std::vector<std::vector<bool>> &)
    {}

    virtual std::string
    name() const = 0;

    /**
     * How many times the symbolic analysis (ordering, elimination tree,
     * matrix graph) was computed: a statistic that shows whether the work
     * done once per sparsity pattern is reused. 0 for solvers without a
     * separate symbolic phase.
     */
    virtual unsigned int
    n_symbolic_analyses() const;

  protected:
    /**
     * Records the structure of @p pattern (sizes and every column index) and
     * returns whether it differs from the structure recorded by the previous
     * call; true on the first call. The content is compared, not the
     * address: the Newton solver may rebuild an identical pattern in a new
     * object, or reuse one object for a different pattern. The comparison is
     * O(nnz), negligible next to a factorization.
     */
    bool
    record_sparsity_pattern(const SparsityPattern &pattern);

  private:
    /** Whether a pattern was recorded at all. */
    bool pattern_recorded = false;

    /** The recorded pattern's number of columns. */
    SparsityPattern::size_type recorded_n_cols = 0;

    /** Offsets of each row's columns in recorded_columns (n_rows + 1). */
    std::vector<std::size_t> recorded_row_starts;

    /** The column indices in deal.II's storage order, row by row. */
    std::vector<SparsityPattern::size_type> recorded_columns;
  };



  /** The linear solvers, selected by the prm entry "Linear solver". */
  enum class LinearSolverType
  {
    /** Supernodal Cholesky of SuiteSparse CHOLMOD: "CHOLMOD". */
    cholmod,
    /** deal.II's SparseDirectUMFPACK (LU): "UMFPACK". */
    umfpack,
    /** Conjugate gradients with Trilinos ML algebraic multigrid: "CG AMG". */
    cg_amg
  };

  /**
   * The LinearSolverType of a prm name "CHOLMOD", "UMFPACK" or "CG AMG";
   * throws an InputError listing the allowed names for anything else.
   */
  LinearSolverType
  linear_solver_type_from_string(const std::string &name);

  /** The prm name of @p type, the inverse of the function above. */
  std::string
  linear_solver_name(const LinearSolverType type);

  /** "CHOLMOD|UMFPACK|CG AMG", for a Patterns::Selection. */
  std::string
  pattern_of_linear_solvers();

  /**
   * A new solver of the given @p type. The CG parameters only matter for
   * LinearSolverType::cg_amg: CG stops when the residual is below
   * @p cg_relative_tolerance times the norm of the right-hand side, and fails
   * (SimulationError) after @p cg_max_iterations iterations.
   */
  std::unique_ptr<LinearSolver>
  create_linear_solver(const LinearSolverType type,
                       const double           cg_relative_tolerance = 1e-10,
                       const unsigned int     cg_max_iterations     = 10000);
} // namespace bfemp

#endif
