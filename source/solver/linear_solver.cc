#include <bfemp/base/input_error.h>
#include <bfemp/solver/cg_amg_solver.h>
#include <bfemp/solver/cholmod_solver.h>
#include <bfemp/solver/linear_solver.h>
#include <bfemp/solver/umfpack_solver.h>

#include <array>
#include <utility>

namespace bfemp
{
  namespace
  {
    /** The prm names, in the order of the enum. */
    const std::array<std::pair<LinearSolverType, const char *>, 3>
      linear_solver_names = {{{LinearSolverType::cholmod, "CHOLMOD"},
                              {LinearSolverType::umfpack, "UMFPACK"},
                              {LinearSolverType::cg_amg, "CG AMG"}}};
  } // namespace



  bool
  LinearSolver::factorize_if_positive_definite(
    const SparseMatrix<double> &matrix)
  {
    factorize(matrix);
    return true;
  }



  unsigned int
  LinearSolver::n_symbolic_analyses() const
  {
    return 0;
  }



  bool
  LinearSolver::record_sparsity_pattern(const SparsityPattern &pattern)
  {
    const SparsityPattern::size_type n_rows = pattern.n_rows();

    bool changed = !pattern_recorded || pattern.n_cols() != recorded_n_cols ||
                   recorded_row_starts.size() != n_rows + 1 ||
                   recorded_columns.size() != pattern.n_nonzero_elements();
    // Same sizes: compare row by row until the first difference.
    for (SparsityPattern::size_type row = 0; row < n_rows && !changed; ++row)
      {
        if (pattern.row_length(row) !=
            recorded_row_starts[row + 1] - recorded_row_starts[row])
          {
            changed = true;
            break;
          }
        std::size_t k = recorded_row_starts[row];
        for (auto entry = pattern.begin(row); entry != pattern.end(row);
             ++entry, ++k)
          if (entry->column() != recorded_columns[k])
            {
              changed = true;
              break;
            }
      }
    if (!changed)
      return false;

    pattern_recorded = true;
    recorded_n_cols  = pattern.n_cols();
    recorded_row_starts.resize(n_rows + 1);
    recorded_columns.resize(pattern.n_nonzero_elements());
    recorded_row_starts[0] = 0;
    std::size_t k          = 0;
    for (SparsityPattern::size_type row = 0; row < n_rows; ++row)
      {
        for (auto entry = pattern.begin(row); entry != pattern.end(row);
             ++entry, ++k)
          recorded_columns[k] = entry->column();
        recorded_row_starts[row + 1] = k;
      }
    return true;
  }



  LinearSolverType
  linear_solver_type_from_string(const std::string &name)
  {
    for (const auto &entry : linear_solver_names)
      if (name == entry.second)
        return entry.first;
    throw InputError("unknown linear solver '" + name + "': allowed are " +
                     pattern_of_linear_solvers());
  }



  std::string
  linear_solver_name(const LinearSolverType type)
  {
    for (const auto &entry : linear_solver_names)
      if (type == entry.first)
        return entry.second;
    Assert(false, ExcInternalError());
    return "";
  }



  std::string
  pattern_of_linear_solvers()
  {
    std::string pattern;
    for (const auto &entry : linear_solver_names)
      pattern += (pattern.empty() ? "" : "|") + std::string(entry.second);
    return pattern;
  }



  std::unique_ptr<LinearSolver>
  create_linear_solver(const LinearSolverType type,
                       const double           cg_relative_tolerance,
                       const unsigned int     cg_max_iterations)
  {
    switch (type)
      {
        case LinearSolverType::cholmod:
          return std::make_unique<CholmodSolver>();
        case LinearSolverType::umfpack:
          return std::make_unique<UmfpackSolver>();
        case LinearSolverType::cg_amg:
          return std::make_unique<CgAmgSolver>(cg_relative_tolerance,
                                               cg_max_iterations);
      }
    Assert(false, ExcInternalError());
    return nullptr;
  }
} // namespace bfemp
