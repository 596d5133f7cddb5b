#include <bfemp/base/blas_threads.h>
#include <bfemp/base/input_error.h>
#include <bfemp/solver/cholmod_solver.h>

#include <algorithm>
#include <cholmod.h>
#include <cmath>
#include <string>

namespace bfemp
{
  /**
   * The CHOLMOD objects (long-integer interface, so that the factor of a
   * large 3D problem cannot overflow 32-bit indices). Every pointer is
   * owned and freed by the destructor, in the reverse order of creation;
   * cholmod_l_finish() comes last as it releases the workspace the other
   * objects were allocated through.
   */
  struct CholmodSolver::Data
  {
    Data()
    {
      cholmod_l_start(&common);
      common.supernodal = CHOLMOD_SUPERNODAL;
      // No printing from inside CHOLMOD: every failure is turned into a
      // SimulationError with a message of our own.
      common.print         = 0;
      common.error_handler = nullptr;
    }

    ~Data()
    {
      free_solve_buffers();
      free_matrix_and_factor();
      cholmod_l_finish(&common);
    }

    Data(const Data &) = delete;

    Data &
    operator=(const Data &) = delete;

    void
    free_matrix_and_factor()
    {
      if (factor != nullptr)
        cholmod_l_free_factor(&factor, &common);
      if (matrix != nullptr)
        cholmod_l_free_sparse(&matrix, &common);
    }

    void
    free_solve_buffers()
    {
      for (cholmod_dense **dense :
           {&rhs, &solution, &workspace_y, &workspace_e})
        if (*dense != nullptr)
          cholmod_l_free_dense(dense, &common);
    }

    cholmod_common common;

    /** The upper triangle of H, compressed by columns, stype = 1. */
    cholmod_sparse *matrix = nullptr;

    /** Symbolic analysis and, after factorize, the numeric factor L. */
    cholmod_factor *factor = nullptr;

    /** Right-hand side, solution and workspace of cholmod_l_solve2(). They
     *  are kept between solves so that a solve allocates nothing. */
    cholmod_dense *rhs         = nullptr;
    cholmod_dense *solution    = nullptr;
    cholmod_dense *workspace_y = nullptr;
    cholmod_dense *workspace_e = nullptr;
  };



  namespace
  {
    /** The position of the diagonal in CHOLMOD's column @p row: last, as
     *  the rows above it are sorted ascending. */
    SuiteSparse_long
    diagonal_position(const cholmod_sparse &matrix, const std::size_t row)
    {
      return static_cast<const SuiteSparse_long *>(matrix.p)[row + 1] - 1;
    }
  } // namespace



  CholmodSolver::CholmodSolver()
    : data(std::make_unique<Data>())
  {}



  CholmodSolver::~CholmodSolver() = default;



  void
  CholmodSolver::factorize(const SparseMatrix<double> &matrix)
  {
    if (!factorize_if_positive_definite(matrix))
      throw SimulationError(
        "CHOLMOD: the Newton matrix is not positive definite (the Cholesky "
        "factorization broke down at pivot " +
        std::to_string(failed_pivot) + " of " + std::to_string(matrix.m()) +
        "); projected Newton needs an SPD matrix: check the tangent "
        "projection and the mass term");
  }



  bool
  CholmodSolver::factorize_if_positive_definite(
    const SparseMatrix<double> &matrix)
  {
    AssertThrow(matrix.m() == matrix.n(),
                ExcMessage("CHOLMOD: the Newton matrix must be square"));
    factorized                     = false;
    const std::size_t      n       = matrix.m();
    const SparsityPattern &pattern = matrix.get_sparsity_pattern();

    // Also rebuild if an earlier attempt failed half-way through.
    if (record_sparsity_pattern(pattern) || data->factor == nullptr)
      {
        // New structure: the upper triangle of H by columns is deal.II's
        // lower triangle by rows (H is symmetric). deal.II stores the
        // diagonal first in each row and the other columns ascending, so
        // column i of CHOLMOD's matrix lists the columns j < i of deal.II's
        // row i in order, followed by the diagonal.
        data->free_solve_buffers();
        data->free_matrix_and_factor();

        std::size_t n_entries = 0;
        for (std::size_t row = 0; row < n; ++row)
          for (auto entry = pattern.begin(row); entry != pattern.end(row);
               ++entry)
            n_entries += (entry->column() <= row);

        data->matrix = cholmod_l_allocate_sparse(n,
                                                 n,
                                                 n_entries,
                                                 /*sorted*/ 1,
                                                 /*packed*/ 1,
                                                 /*stype*/ 1,
                                                 CHOLMOD_REAL,
                                                 &data->common);
        if (data->matrix == nullptr)
          throw SimulationError("CHOLMOD: could not allocate the matrix (" +
                                std::to_string(n_entries) + " entries)");

        auto *column_starts = static_cast<SuiteSparse_long *>(data->matrix->p);
        auto *row_indices   = static_cast<SuiteSparse_long *>(data->matrix->i);
        SuiteSparse_long k  = 0;
        for (std::size_t row = 0; row < n; ++row)
          {
            column_starts[row] = k;
            bool has_diagonal  = false;
            for (auto entry = pattern.begin(row); entry != pattern.end(row);
                 ++entry)
              if (entry->column() < row)
                row_indices[k++] = entry->column();
              else if (entry->column() == row)
                has_diagonal = true;
            if (!has_diagonal)
              throw SimulationError("CHOLMOD: row " + std::to_string(row) +
                                    " of the Newton matrix has no diagonal "
                                    "entry");
            row_indices[k++] = row;
          }
        column_starts[n] = k;

        data->factor = cholmod_l_analyze(data->matrix, &data->common);
        if (data->factor == nullptr)
          throw SimulationError(
            "CHOLMOD: the symbolic analysis failed (CHOLMOD status " +
            std::to_string(data->common.status) + ")");
        ++n_analyses;
      }

    // Values, in the order in which the structure was built above.
    auto *values = static_cast<double *>(data->matrix->x);
    for (std::size_t row = 0; row < n; ++row)
      {
        SuiteSparse_long k =
          static_cast<const SuiteSparse_long *>(data->matrix->p)[row];
        for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
          if (entry->column() <= row)
            {
              if (!std::isfinite(entry->value()))
                throw SimulationError(
                  "CHOLMOD: the Newton matrix has a non-finite entry in row " +
                  std::to_string(row) + ", column " +
                  std::to_string(entry->column()));
              if (entry->column() == row)
                values[diagonal_position(*data->matrix, row)] = entry->value();
              else
                values[k++] = entry->value();
            }
      }

    {
      // CHOLMOD's flop count of the analysis decides the BLAS threads
      const BlasThreads::Scope blas(data->common.fl);
      cholmod_l_factorize(data->matrix, data->factor, &data->common);
    }
    if (data->common.status == CHOLMOD_NOT_POSDEF ||
        (data->common.status == CHOLMOD_OK &&
         static_cast<std::size_t>(data->factor->minor) < n))
      {
        failed_pivot = data->factor->minor;
        return false;
      }
    if (data->common.status != CHOLMOD_OK)
      throw SimulationError(
        "CHOLMOD: the numeric factorization failed (CHOLMOD status " +
        std::to_string(data->common.status) + ")");
    factorized = true;
    return true;
  }



  void
  CholmodSolver::solve(const Vector<double> &rhs, Vector<double> &solution)
  {
    AssertThrow(factorized,
                ExcMessage("CHOLMOD: solve() needs a successful factorize()"));
    const std::size_t n = data->matrix->nrow;
    AssertDimension(rhs.size(), n);

    if (data->rhs == nullptr)
      {
        data->rhs =
          cholmod_l_allocate_dense(n, 1, n, CHOLMOD_REAL, &data->common);
        if (data->rhs == nullptr)
          throw SimulationError(
            "CHOLMOD: could not allocate the right-hand side");
      }
    std::copy(rhs.begin(), rhs.end(), static_cast<double *>(data->rhs->x));

    // a forward and a backward solve: 4 flops per entry of L
    const BlasThreads::Scope blas(4. * data->common.lnz, true);
    const int                ok = cholmod_l_solve2(CHOLMOD_A,
                                    data->factor,
                                    data->rhs,
                                    nullptr,
                                    &data->solution,
                                    nullptr,
                                    &data->workspace_y,
                                    &data->workspace_e,
                                    &data->common);
    if (!ok || data->common.status != CHOLMOD_OK)
      throw SimulationError(
        "CHOLMOD: the triangular solves failed (CHOLMOD status " +
        std::to_string(data->common.status) + ")");

    solution.reinit(n, /*omit_zeroing_entries*/ true);
    const auto *x = static_cast<const double *>(data->solution->x);
    std::copy(x, x + n, solution.begin());
    if (!std::isfinite(solution.l2_norm()))
      throw SimulationError(
        "CHOLMOD: the solution is not finite (is the right-hand side "
        "finite?)");
  }



  std::string
  CholmodSolver::name() const
  {
    return "CHOLMOD";
  }



  unsigned int
  CholmodSolver::n_symbolic_analyses() const
  {
    return n_analyses;
  }
} // namespace bfemp
