// The sparse linear solvers of projected Newton (CHOLMOD, UMFPACK, CG AMG):
// each solves SPD systems (a 2D vector-valued elasticity matrix plus a mass
// term, a random diagonally dominant matrix) to a small residual, and they
// agree; CHOLMOD and CG AMG rebuild their symbolic analysis only when the
// sparsity pattern's content changes and stay correct when only the values
// change; a matrix that is not positive definite, a singular matrix and CG
// out of iterations end in a SimulationError; the prm names round-trip.

#include <bfemp/base/input_error.h>
#include <bfemp/solver/cg_amg_solver.h>
#include <bfemp/solver/cholmod_solver.h>
#include <bfemp/solver/linear_solver.h>
#include <bfemp/solver/umfpack_solver.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <set>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  /**
   * A 2D linear elasticity stiffness (Lame parameters @p lambda, @p mu) plus
   * @p mass times the mass matrix, Q1 x Q1 on a 40 x 40 grid of the unit
   * square (3362 unknowns, no boundary conditions): the structure of an
   * implicit step's Hessian, M / dt^2 + K. The pattern is the full symmetric
   * one of DoFTools.
   */
  class Elasticity
  {
  public:
    Elasticity()
      : fe(FE_Q<2>(1), 2)
    {
      GridGenerator::subdivided_hyper_cube(triangulation, 40);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(fe);
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp);
      pattern.copy_from(dsp);
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(2, true),
                                       constant_modes);
    }

    /** Assembles into @p matrix, which must use a copy of #pattern. */
    void
    assemble(SparseMatrix<double> &matrix,
             const double          lambda,
             const double          mu,
             const double          mass) const
    {
      matrix = 0.;
      const QGauss<2>                      quadrature(2);
      FEValues<2>                          fe_values(fe,
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
      const unsigned int                   n = fe.n_dofs_per_cell();
      FullMatrix<double>                   cell_matrix(n, n);
      std::vector<types::global_dof_index> dofs(n);
      const FEValuesExtractors::Vector     u(0);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell_matrix = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                cell_matrix(i, j) +=
                  (lambda * fe_values[u].divergence(i, q) *
                     fe_values[u].divergence(j, q) +
                   2. * mu *
                     scalar_product(fe_values[u].symmetric_gradient(i, q),
                                    fe_values[u].symmetric_gradient(j, q)) +
                   mass * fe_values[u].value(i, q) * fe_values[u].value(j, q)) *
                  fe_values.JxW(q);
          cell->get_dof_indices(dofs);
          matrix.add(dofs, cell_matrix);
        }
    }

    Triangulation<2>               triangulation;
    FESystem<2>                    fe;
    DoFHandler<2>                  dof_handler;
    SparsityPattern                pattern;
    std::vector<std::vector<bool>> constant_modes;
  };



  /**
   * A random symmetric matrix of @p n rows with about 6 entries a row,
   * strictly diagonally dominant with a positive diagonal, hence SPD.
   */
  void
  make_random_spd(const unsigned int    n,
                  SparsityPattern      &pattern,
                  SparseMatrix<double> &matrix)
  {
    bfemp_tests::RandomNumbers              random(7);
    std::vector<std::set<unsigned int>>     neighbours(n);
    std::vector<std::map<unsigned, double>> entries(n);
    for (unsigned int row = 0; row < n; ++row)
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int column =
            std::min(n - 1, static_cast<unsigned int>(random.uniform(0, n)));
          if (column == row)
            continue;
          const double value   = random.uniform(-1., 1.);
          entries[row][column] = value;
          entries[column][row] = value;
        }
    DynamicSparsityPattern dsp(n);
    for (unsigned int row = 0; row < n; ++row)
      {
        dsp.add(row, row);
        for (const auto &entry : entries[row])
          dsp.add(row, entry.first);
      }
    pattern.copy_from(dsp);
    matrix.reinit(pattern);
    for (unsigned int row = 0; row < n; ++row)
      {
        double off_diagonal = 0.;
        for (const auto &entry : entries[row])
          {
            matrix.set(row, entry.first, entry.second);
            off_diagonal += std::abs(entry.second);
          }
        matrix.set(row, row, off_diagonal + random.uniform(0.1, 1.));
      }
  }



  Vector<double>
  random_vector(const unsigned int n, const unsigned int seed)
  {
    bfemp_tests::RandomNumbers random(seed);
    Vector<double>             v(n);
    for (double &entry : v)
      entry = random.uniform(-1., 1.);
    return v;
  }



  /** ||A x - b|| / ||b||. */
  double
  relative_residual(const SparseMatrix<double> &A,
                    const Vector<double>       &x,
                    const Vector<double>       &b)
  {
    Vector<double> r(b.size());
    A.residual(r, x, b);
    return r.l2_norm() / b.l2_norm();
  }



  double
  relative_difference(const Vector<double> &x, const Vector<double> &y)
  {
    Vector<double> d = x;
    d -= y;
    return d.l2_norm() / y.l2_norm();
  }



  /** The residual bound of each solver: direct ones to round-off. */
  double
  tolerance(const LinearSolver &solver)
  {
    return solver.name() == "CG AMG" ? 1e-8 : 1e-10;
  }



  /** Factorizes and solves with @p solver, checks the residual. */
  Vector<double>
  check_solve(LinearSolver               &solver,
              const SparseMatrix<double> &A,
              const Vector<double>       &b,
              const std::string          &what)
  {
    solver.factorize(A);
    Vector<double> x;
    solver.solve(b, x);
    bfemp_tests::check(relative_residual(A, x, b) < tolerance(solver),
                       solver.name() + ", " + what + ": |Ax - b| / |b| < " +
                         (tolerance(solver) == 1e-8 ? "1e-8" : "1e-10"));
    return x;
  }



  /** All three solvers on one system; their solutions agree. */
  void
  check_agreement(const SparseMatrix<double> &A, const std::string &what)
  {
    const Vector<double> b = random_vector(A.m(), 3);
    CholmodSolver        cholmod;
    UmfpackSolver        umfpack;
    CgAmgSolver          cg_amg(1e-12, 1000);
    const Vector<double> x_cholmod = check_solve(cholmod, A, b, what);
    const Vector<double> x_umfpack = check_solve(umfpack, A, b, what);
    const Vector<double> x_cg      = check_solve(cg_amg, A, b, what);
    bfemp_tests::check(relative_difference(x_cholmod, x_umfpack) < 1e-9,
                       what + ": CHOLMOD and UMFPACK agree to 1e-9");
    bfemp_tests::check(relative_difference(x_cg, x_umfpack) < 1e-6,
                       what + ": CG AMG and UMFPACK agree to 1e-6");
  }



  /**
   * Symbolic reuse of @p solver: new values on the same pattern object or on
   * an equal copy of it keep the analysis, a different pattern does not.
   */
  void
  check_symbolic_reuse(LinearSolver &solver, const Elasticity &elasticity)
  {
    const std::string    name = solver.name();
    const unsigned int   n    = elasticity.dof_handler.n_dofs();
    const Vector<double> b    = random_vector(n, 5);

    SparseMatrix<double> A(elasticity.pattern);
    elasticity.assemble(A, 1., 1., 10.);
    const Vector<double> x_soft = check_solve(solver, A, b, "soft");
    bfemp_tests::check(solver.n_symbolic_analyses() == 1,
                       name + ": 1 symbolic analysis after one factorize");

    // Other values on the same pattern: the analysis is reused and the
    // solution is that of the new matrix.
    elasticity.assemble(A, 50., 20., 1000.);
    const Vector<double> x_stiff = check_solve(solver, A, b, "stiff");
    bfemp_tests::check(solver.n_symbolic_analyses() == 1,
                       name + ": still 1 analysis after new values");
    bfemp_tests::check(relative_difference(x_soft, x_stiff) > 0.1,
                       name + ": the new values change the solution");

    // An equal pattern in another object: compared by content, reused.
    SparsityPattern copy;
    copy.copy_from(elasticity.pattern);
    SparseMatrix<double> B(copy);
    elasticity.assemble(B, 1., 1., 10.);
    const Vector<double> x_copy = check_solve(solver, B, b, "copied pattern");
    bfemp_tests::check(solver.n_symbolic_analyses() == 1,
                       name + ": still 1 analysis for an equal pattern copy");
    bfemp_tests::check(relative_difference(x_copy, x_soft) < 1e-6,
                       name + ": same matrix, same solution");

    // A different pattern: a new analysis, and back again: another one.
    SparsityPattern      random_pattern;
    SparseMatrix<double> R;
    make_random_spd(500, random_pattern, R);
    check_solve(solver, R, random_vector(500, 6), "random");
    bfemp_tests::check(solver.n_symbolic_analyses() == 2,
                       name + ": 2 analyses after a different pattern");
    check_solve(solver, A, b, "stiff again");
    bfemp_tests::check(solver.n_symbolic_analyses() == 3,
                       name + ": 3 analyses after returning to the first");
  }



  /** Runs @p action and checks that it throws a SimulationError whose
   *  message contains @p text. */
  template <typename Action>
  void
  check_simulation_error(const Action      &action,
                         const std::string &text,
                         const std::string &what)
  {
    bool        thrown = false;
    std::string message;
    try
      {
        action();
      }
    catch (const SimulationError &error)
      {
        thrown  = true;
        message = error.what();
      }
    bfemp_tests::check(thrown, what + ": throws a SimulationError");
    bfemp_tests::check(message.find(text) != std::string::npos,
                       what + ": the message says '" + text + "'");
  }



  void
  check_failures(const Elasticity &elasticity)
  {
    const unsigned int   n = elasticity.dof_handler.n_dofs();
    const Vector<double> b = random_vector(n, 9);
    SparseMatrix<double> A(elasticity.pattern);

    // Indefinite: one negative diagonal entry. CHOLMOD refuses it; the
    // solver recovers with the next SPD matrix (same pattern).
    CholmodSolver cholmod;
    elasticity.assemble(A, 1., 1., 10.);
    A.set(100, 100, -1.);
    check_simulation_error([&]() { cholmod.factorize(A); },
                           "not positive definite",
                           "CHOLMOD, negative diagonal entry");
    bool solve_refused = false;
    try
      {
        Vector<double> x;
        cholmod.solve(b, x);
      }
    catch (const ExceptionBase &)
      {
        solve_refused = true;
      }
    bfemp_tests::check(solve_refused,
                       "CHOLMOD: no solve after a failed factorization");
    elasticity.assemble(A, 1., 1., 10.);
    check_solve(cholmod, A, b, "SPD after the indefinite one");

    // factorize_if_positive_definite: false instead of the error, and the
    // next SPD matrix factorizes (Newton's exact-Hessian attempt).
    A.set(100, 100, -1.);
    bfemp_tests::check(!cholmod.factorize_if_positive_definite(A),
                       "CHOLMOD: factorize_if_positive_definite refuses an "
                       "indefinite matrix");
    elasticity.assemble(A, 1., 1., 10.);
    bfemp_tests::check(cholmod.factorize_if_positive_definite(A),
                       "CHOLMOD: factorize_if_positive_definite accepts the "
                       "SPD matrix after it");
    check_solve(cholmod, A, b, "SPD after factorize_if_positive_definite");

    // Negative definite: -A.
    A *= -1.;
    check_simulation_error([&]() { cholmod.factorize(A); },
                           "not positive definite",
                           "CHOLMOD, negative definite matrix");
    A *= -1.;

    // A NaN is reported as such, not as a failed factorization. Written
    // through the row's first entry (the diagonal of a square deal.II
    // pattern) because SparseMatrix::set asserts finite values in Debug.
    A.begin(7)->value() = std::nan("");
    check_simulation_error([&]() { cholmod.factorize(A); },
                           "non-finite",
                           "CHOLMOD, NaN entry");

    // Singular (row and column 10 zero): UMFPACK's error, as a
    // SimulationError.
    elasticity.assemble(A, 1., 1., 10.);
    for (auto entry = A.begin(10); entry != A.end(10); ++entry)
      {
        A.set(entry->column(), 10, 0.);
        entry->value() = 0.;
      }
    UmfpackSolver umfpack;
    check_simulation_error([&]() { umfpack.factorize(A); },
                           "UMFPACK",
                           "UMFPACK, singular matrix");

    // CG out of iterations.
    elasticity.assemble(A, 1., 1., 10.);
    CgAmgSolver cg_amg(1e-14, 2);
    cg_amg.factorize(A);
    check_simulation_error(
      [&]() {
        Vector<double> x;
        cg_amg.solve(b, x);
      },
      "CG AMG: CG did not converge",
      "CG AMG, 2 iterations");
  }



  /** CG AMG with the constant modes of the two displacement components. */
  void
  check_constant_modes(const Elasticity &elasticity)
  {
    SparseMatrix<double> A(elasticity.pattern);
    elasticity.assemble(A, 50., 20., 1.);
    const Vector<double> b = random_vector(A.m(), 11);
    CgAmgSolver          plain(1e-10, 1000), with_modes(1e-10, 1000);
    with_modes.set_constant_modes(elasticity.constant_modes);
    check_solve(plain, A, b, "scalar AMG");
    check_solve(with_modes, A, b, "AMG with 2 constant modes");
    bfemp_tests::check(with_modes.last_n_iterations() > 0 &&
                         with_modes.last_n_iterations() <
                           plain.last_n_iterations(),
                       "CG AMG: the constant modes save iterations");

    // A zero right-hand side gives zero without iterating.
    Vector<double> x;
    with_modes.solve(Vector<double>(A.m()), x);
    bfemp_tests::check(x.l2_norm() == 0. && with_modes.last_n_iterations() == 0,
                       "CG AMG: zero right-hand side, zero solution");
  }



  void
  check_names()
  {
    deallog << "pattern: " << pattern_of_linear_solvers() << std::endl;
    const Patterns::Selection selection(pattern_of_linear_solvers());
    for (const std::string name : {"CHOLMOD", "UMFPACK", "CG AMG"})
      {
        const LinearSolverType type   = linear_solver_type_from_string(name);
        const auto             solver = create_linear_solver(type, 1e-8, 50);
        bfemp_tests::check(solver->name() == name &&
                             linear_solver_name(type) == name &&
                             selection.match(name),
                           "'" + name + "' round-trips");
      }
    bool thrown = false;
    try
      {
        linear_solver_type_from_string("PARDISO");
      }
    catch (const InputError &error)
      {
        thrown = std::string(error.what()).find("CG AMG") != std::string::npos;
      }
    bfemp_tests::check(thrown,
                       "an unknown name is an InputError listing the names");
  }
} // namespace



int
main(int argc, char **argv)
{
  // Trilinos (CG AMG) needs MPI.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  check_names();

  const Elasticity elasticity;
  deallog << "elasticity: " << elasticity.dof_handler.n_dofs() << " unknowns, "
          << elasticity.pattern.n_nonzero_elements() << " entries" << std::endl;
  {
    SparseMatrix<double> A(elasticity.pattern);
    elasticity.assemble(A, 1., 1., 10.);
    check_agreement(A, "elasticity");
  }
  {
    SparsityPattern      pattern;
    SparseMatrix<double> R;
    make_random_spd(200, pattern, R);
    check_agreement(R, "random SPD");
  }

  CholmodSolver cholmod;
  check_symbolic_reuse(cholmod, elasticity);
  CgAmgSolver cg_amg;
  check_symbolic_reuse(cg_amg, elasticity);
  UmfpackSolver umfpack;
  {
    SparseMatrix<double> A(elasticity.pattern);
    elasticity.assemble(A, 1., 1., 10.);
    const Vector<double> b = random_vector(A.m(), 4);
    check_solve(umfpack, A, b, "first");
    check_solve(umfpack, A, b, "second");
    bfemp_tests::check(umfpack.n_symbolic_analyses() == 2,
                       "UMFPACK: an analysis in every factorize");
  }

  check_failures(elasticity);
  check_constant_modes(elasticity);
}
