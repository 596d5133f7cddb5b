#include <bfemp/base/input_error.h>
#include <bfemp/solver/cg_amg_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <cmath>
#include <sstream>

namespace bfemp
{
  CgAmgSolver::CgAmgSolver(const double       relative_tolerance,
                           const unsigned int max_iterations)
    : relative_tolerance(relative_tolerance)
    , max_iterations(max_iterations)
  {
    AssertThrow(relative_tolerance > 0. && max_iterations > 0,
                ExcMessage("CG AMG: the relative tolerance and the maximum "
                           "number of iterations must be positive"));
  }



  void
  CgAmgSolver::set_constant_modes(
    const std::vector<std::vector<bool>> &constant_modes)
  {
    this->constant_modes = constant_modes;
  }



  void
  CgAmgSolver::factorize(const SparseMatrix<double> &dealii_matrix)
  {
    AssertThrow(dealii_matrix.m() == dealii_matrix.n(),
                ExcMessage("CG AMG: the Newton matrix must be square"));
    preconditioner_set             = false;
    const SparsityPattern &pattern = dealii_matrix.get_sparsity_pattern();

    // Graph (the "symbolic" part) only for a new pattern: the Trilinos
    // graph then holds exactly deal.II's entries, so set() below always
    // finds the entries it replaces.
    if (record_sparsity_pattern(pattern) || matrix.m() != pattern.n_rows())
      {
        const IndexSet all = complete_index_set(pattern.n_rows());
        matrix.reinit(all, all, pattern, MPI_COMM_SELF);
        ++n_analyses;
      }

    std::vector<TrilinosWrappers::SparseMatrix::size_type> columns;
    std::vector<double>                                    values;
    for (unsigned int row = 0; row < dealii_matrix.m(); ++row)
      {
        columns.clear();
        values.clear();
        for (auto entry = dealii_matrix.begin(row);
             entry != dealii_matrix.end(row);
             ++entry)
          {
            if (!std::isfinite(entry->value()))
              throw SimulationError(
                "CG AMG: the Newton matrix has a non-finite entry in row " +
                std::to_string(row) + ", column " +
                std::to_string(entry->column()));
            columns.push_back(entry->column());
            values.push_back(entry->value());
          }
        matrix.set(row, columns.size(), columns.data(), values.data());
      }
    matrix.compress(VectorOperation::insert);

    AssertThrow(constant_modes.empty() ||
                  constant_modes[0].size() == dealii_matrix.m(),
                ExcMessage("CG AMG: the constant modes have " +
                           std::to_string(constant_modes[0].size()) +
                           " entries, the matrix " +
                           std::to_string(dealii_matrix.m()) + " rows"));
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    // Projected Newton matrices are SPD, "elliptic" in ML's sense (smoothed
    // aggregation, Chebyshev smoothing); linear shape functions.
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = 2;
    data.constant_modes        = constant_modes;
    preconditioner.initialize(matrix, data);
    preconditioner_set = true;
  }



  void
  CgAmgSolver::solve(const Vector<double> &rhs, Vector<double> &solution)
  {
    AssertThrow(preconditioner_set,
                ExcMessage("CG AMG: solve() needs a successful factorize()"));
    AssertDimension(rhs.size(), matrix.m());
    solution.reinit(rhs.size());
    n_iterations = 0;

    const double rhs_norm = rhs.l2_norm();
    if (!std::isfinite(rhs_norm))
      throw SimulationError("CG AMG: the right-hand side is not finite");
    if (rhs_norm == 0.)
      return;

    // No logging: deallog belongs to the caller (the tests write to it).
    SolverControl            control(max_iterations,
                          relative_tolerance * rhs_norm,
                          /*log_history*/ false,
                          /*log_result*/ false);
    SolverCG<Vector<double>> cg(control);
    try
      {
        cg.solve(matrix, solution, rhs, preconditioner);
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        std::ostringstream message;
        message << "CG AMG: CG did not converge in " << failure.last_step
                << " iterations (residual " << failure.last_residual
                << ", target " << relative_tolerance * rhs_norm
                << " = relative tolerance " << relative_tolerance
                << " x |rhs|); raise the maximum number of iterations or "
                   "choose a direct linear solver";
        throw SimulationError(message.str());
      }
    n_iterations = control.last_step();
  }



  std::string
  CgAmgSolver::name() const
  {
    return "CG AMG";
  }



  unsigned int
  CgAmgSolver::n_symbolic_analyses() const
  {
    return n_analyses;
  }



  unsigned int
  CgAmgSolver::last_n_iterations() const
  {
    return n_iterations;
  }
} // namespace bfemp
