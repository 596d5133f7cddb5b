#include <bfemp/base/input_error.h>
#include <bfemp/solver/umfpack_solver.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bfemp
{
  void
  UmfpackSolver::factorize(const SparseMatrix<double> &matrix)
  {
    factorized = false;
    try
      {
        umfpack.initialize(matrix);
      }
    catch (const ExceptionBase &error)
      {
        // deal.II reports UMFPACK's status, e.g. a singular matrix, as an
        // exception; for the Newton solver it is a failed step.
        // deal.II's explanation runs over several paragraphs; its first
        // line names the UMFPACK routine and status.
        std::ostringstream info;
        error.print_info(info);
        std::string first_line = info.str();
        first_line.erase(0, first_line.find_first_not_of(" \n"));
        first_line.erase(std::min(first_line.find('\n'), first_line.size()));
        throw SimulationError(
          "UMFPACK: the factorization of the Newton matrix failed (" +
          first_line +
          " Status 1 means a singular matrix: check the mass term and the "
          "Dirichlet conditions)");
      }
    ++n_analyses;
    factorized = true;
  }



  void
  UmfpackSolver::solve(const Vector<double> &rhs, Vector<double> &solution)
  {
    AssertThrow(factorized,
                ExcMessage("UMFPACK: solve() needs a successful factorize()"));
    AssertDimension(rhs.size(), umfpack.m());
    solution = rhs;
    umfpack.solve(solution);
    if (!std::isfinite(solution.l2_norm()))
      throw SimulationError(
        "UMFPACK: the solution is not finite (is the matrix nearly singular or "
        "the right-hand side not finite?)");
  }



  std::string
  UmfpackSolver::name() const
  {
    return "UMFPACK";
  }



  unsigned int
  UmfpackSolver::n_symbolic_analyses() const
  {
    return n_analyses;
  }
} // namespace bfemp
