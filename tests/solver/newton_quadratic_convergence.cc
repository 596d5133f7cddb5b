// Quadratic convergence of Newton's method on the incremental potential of
// a static FEM problem (BFEMP Section 5 without inertia, dt = 1): a
// neo-Hookean bar (L = 1 m) clamped at x = 0 (node constraints P = 0) and
// loaded by dead-load tractions, E(u) = Psi(u) - f.u, in 2D (plane strain)
// and 3D: the end face x = L is pulled along the bar (0.1 E) with a small
// transverse part (0.001 E), the lateral faces outwards (0.05 E). The bar
// stretches by about 8 % and bends slightly, so the problem is
// geometrically and materially nonlinear, but every element is stretched in
// all directions: the tangents stay PSD near the solution, the PSD
// projection does nothing there (checked), and projected Newton is plain
// Newton. (Under uniaxial tension alone the lateral contraction makes the
// 3D neo-Hookean tangent indefinite in the lateral twist mode; the
// projection then limits Newton to linear convergence, rate ~1e-2.)
//
// A test-local loop takes full Newton steps p = -H^-1 g (CHOLMOD) from
// u = 0 and records r_k = ||p_k||_inf; quadratic convergence means
// r_{k+1} / r_k^2 stays bounded while r_{k+1} / r_k -> 0, checked on the
// ratios whose r_{k+1} lies well above the round-off floor of ||p||
// (measured as the Newton step at the converged u). The library's
// NewtonSolver (with its line search and det F > 0 filter) must reach the
// same minimizer. The ratios depend on round-off in their last digits and
// go to stdout; the output holds counts and checks.

#include <bfemp/base/input_error.h>
#include <bfemp/solver/cholmod_solver.h>
#include <bfemp/solver/newton_solver.h>
#include <bfemp/solver/solver_parameters.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>

#include "solver_test_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::check;

namespace
{
  /**
   * E and the sum of the "terms:" values of one 'log iterations' line
   * (NaN for the sum if the line has no terms).
   */
  std::pair<double, double>
  energy_and_term_sum(const std::string &line)
  {
    const std::size_t e     = line.find(", E ");
    const std::size_t terms = line.find(", terms: ");
    if (e == std::string::npos || terms == std::string::npos)
      return {0., std::nan("")};
    const double energy = std::stod(line.substr(e + 4));
    double       sum    = 0.;
    // each entry is "<name> <value> J", separated by "; "
    std::string rest = line.substr(terms + 9) + ";";
    for (std::size_t end; (end = rest.find(" J;")) != std::string::npos;
         rest = rest.substr(end + 3))
      sum += std::stod(rest.substr(rest.rfind(' ', end - 1) + 1));
    return {energy, sum};
  }

  const double youngs_modulus = 1e6;
  const double poisson_ratio  = 0.3;
  const double length         = 1.;

  template <int dim>
  void
  run(const double width,
      const double edge,
      const double axial,
      const double lateral,
      const double transverse)
  {
    const std::string          what = std::to_string(dim) + "D bar: ";
    bfemp_tests::FemScene<dim> scene(
      {bfemp_tests::neo_hookean_bar<dim>(length,
                                         width,
                                         edge,
                                         youngs_modulus,
                                         poisson_ratio)});
    const unsigned int n_clamped = scene.clamp(0);

    // Dead load: tractions pulling the end face x = L (boundary id 1)
    // along the bar with a small transverse part, and every lateral face
    // (ids 2 .. 2 dim - 1) outwards, so that each element is stretched in
    // all directions (with uniaxial tension alone, the lateral contraction
    // makes the 3D neo-Hookean tangent indefinite in the lateral twist
    // mode, the projection becomes active and convergence only linear).
    bfemp_tests::DeadLoadTerm<dim> load(scene.dofs.n_dofs());
    Tensor<1, dim>                 end_traction;
    end_traction[0] = axial * youngs_modulus;
    end_traction[1] = transverse * youngs_modulus;
    bfemp_tests::add_traction(scene, load, 1, end_traction);
    for (unsigned int d = 1; d < dim; ++d)
      for (const unsigned int side : {0u, 1u})
        {
          Tensor<1, dim> t;
          t[d] = (side == 0 ? -1. : 1.) * lateral * youngs_modulus;
          bfemp_tests::add_traction(scene, load, 2 * d + side, t);
        }
    const unsigned int n_loaded = [&]() {
      unsigned int n = 0;
      for (unsigned int node = 0; node < scene.dofs.n_nodes(); ++node)
        if (DofSpace<dim>::get(load.forces(), node).norm() > 0.)
          ++n;
      return n;
    }();

    scene.elasticity.set_scale(1.);
    scene.potential.set_terms({&scene.elasticity, &load});
    scene.potential.setup_system();
    deallog << what << scene.bodies[0]->elements().size() << " elements, "
            << scene.dofs.n_dofs() << " DoFs, " << n_clamped
            << " clamped nodes, " << n_loaded << " loaded nodes" << std::endl;

    // Test-local full Newton from u = 0.
    const double                     tolerance = 1e-12;
    Vector<double>                   u(scene.dofs.n_dofs());
    CholmodSolver                    cholmod;
    const bfemp_tests::NewtonHistory history =
      bfemp_tests::full_newton(scene.potential, cholmod, u, tolerance, 20);
    const std::vector<double> &r = history.residuals;

    std::cout << what << "residuals";
    for (const double r_k : r)
      std::cout << ' ' << r_k;
    std::cout << std::endl;
    // Ratios are meaningful while r_{k+1} is well above round-off: measure
    // the round-off floor of ||p||_inf as the Newton step at the converged
    // u (one more solve), and use ratios with r_{k+1} > 100 floor.
    double floor = 0.;
    {
      Vector<double> g, p;
      scene.potential.gradient(u, g);
      cholmod.factorize(scene.potential.hessian(u));
      g *= -1.;
      cholmod.solve(g, p);
      floor = p.linfty_norm();
    }
    const double noise = 100. * floor;
    std::cout << what << "round-off floor of ||p||_inf " << floor << std::endl;
    double       max_quadratic_ratio = 0., last_linear_ratio = 1.;
    unsigned int n_ratios = 0;
    for (unsigned int k = 1; k + 1 < r.size(); ++k)
      {
        const double quadratic = r[k + 1] / (r[k] * r[k]);
        const double linear    = r[k + 1] / r[k];
        std::cout << what << "k = " << k << ": r_k+1 / r_k^2 = " << quadratic
                  << " 1/m, r_k+1 / r_k = " << linear
                  << (r[k + 1] > noise ? "" : " (round-off)") << std::endl;
        if (r[k + 1] > noise)
          {
            max_quadratic_ratio = std::max(max_quadratic_ratio, quadratic);
            last_linear_ratio   = linear;
            ++n_ratios;
          }
      }

    deallog << what << "full Newton: " << r.size() << " iterations"
            << std::endl;
    check(history.converged,
          what + "full Newton converges to ||p||_inf < 1e-12 m");
    check(r.size() >= 4 && r.size() <= 6,
          what + "the load needs 4 to 6 Newton iterations");
    check(history.minimum_determinant > 0.,
          what + "every iterate has det F > 0");
    check(bfemp_tests::projected_tangents(scene, u) == 0,
          what + "no tangent is projected at the solution");
    check(n_ratios >= 2, what + "at least 2 ratios above round-off");
    // Quadratic: r_{k+1} <= C r_k^2 with C of order 1 / width, where linear
    // convergence with rate q would give q / r_k, growing without bound.
    check(max_quadratic_ratio < 100. / length,
          what + "r_k+1 / r_k^2 < 100 / L (quadratic convergence)");
    check(last_linear_ratio < 1e-3, what + "r_k+1 / r_k -> 0 (< 1e-3)");

    // The minimizer: gradient zero on the free DoFs.
    Vector<double> g;
    scene.potential.gradient(u, g);
    check(g.linfty_norm() < 1e-9 * load.forces().linfty_norm(),
          what + "||P grad E|| < 1e-9 ||f|| at the end");

    // The library's projected Newton with line search and filtering.
    SolverParameters parameters;
    parameters.newton_tolerance = tolerance;
    parameters.linear_solver    = "CHOLMOD";
    parameters.check_invariants = true;
    parameters.log_iterations   = true;
    NewtonSolver<dim>      newton(parameters);
    Vector<double>         u_solver(scene.dofs.n_dofs());
    std::stringstream      log;
    std::streambuf        *console = std::cout.rdbuf(log.rdbuf());
    const NewtonStatistics statistics =
      newton.minimize(scene.potential, u_solver, 1., "static bar");
    std::cout.rdbuf(console);
    std::cout << log.str();
    // 'solver/log iterations': one line per iteration, each from a new
    // factorization (no reuse here)
    unsigned int n_lines = 0, n_factorized = 0, n_projected = 0;
    // the terms' energies at the end of each line add up to its E (printed
    // to 10 digits each)
    double                    largest_gap = 0.;
    std::pair<double, double> last;
    for (std::string line; std::getline(log, line);)
      if (line.rfind("  static bar: iteration ", 0) == 0)
        {
          ++n_lines;
          n_factorized += line.find(", factorized") != std::string::npos;
          n_projected += line.find(", projected Hessian") != std::string::npos;
          last = energy_and_term_sum(line);
          // NaN (no terms) fails the check below
          const double gap = std::abs(last.second - last.first) /
                             std::max(std::abs(last.first), 1e-300);
          largest_gap = std::isnan(gap) ? 1. : std::max(largest_gap, gap);
        }
    {
      std::ostringstream energies;
      energies << std::setprecision(6) << "last log line: E = " << last.first
               << " J, sum of its terms = " << last.second << " J";
      deallog << what << energies.str() << std::endl;
    }
    check(largest_gap < 1e-8,
          what + "the terms' energies in each log line add up to its E "
                 "(relative gap < 1e-8)");
    check(n_lines == statistics.iterations && n_factorized == n_lines,
          what + "the iteration log has one line per Newton iteration (" +
            std::to_string(n_lines) + "), each from a factorization (" +
            std::to_string(n_factorized) + ")");
    check(n_projected == statistics.projected_hessians,
          what + "the log marks the iterations with the projected Hessian (" +
            std::to_string(n_projected) + " of " +
            std::to_string(statistics.projected_hessians) + ")");
    {
      // Projected Newton throughout: every line says so.
      SolverParameters always(parameters);
      always.hessian_projection = "always";
      NewtonSolver<dim> projected_newton(always);
      Vector<double>    u_projected(scene.dofs.n_dofs());
      std::stringstream projected_log;
      std::streambuf   *saved = std::cout.rdbuf(projected_log.rdbuf());
      const auto        s     = projected_newton.minimize(scene.potential,
                                               u_projected,
                                               1.,
                                               "static bar");
      std::cout.rdbuf(saved);
      unsigned int marked = 0;
      for (std::string line; std::getline(projected_log, line);)
        marked += line.find(", projected Hessian") != std::string::npos;
      check(marked == s.iterations && s.projected_hessians == s.iterations,
            what +
              "with 'Hessian projection = always' every log line marks "
              "the projected Hessian (" +
              std::to_string(marked) + " of " + std::to_string(s.iterations) +
              " iterations)");
    }
    Vector<double> difference(u_solver);
    difference -= u;
    std::cout << what << "NewtonSolver: " << statistics.iterations
              << " iterations, " << statistics.backtracks << " backtracks, "
              << statistics.bound_hits << " bound hits, |u - u_full| "
              << difference.linfty_norm() << ", tip displacement "
              << u.linfty_norm() << " m" << std::endl;
    deallog << what << "NewtonSolver: " << statistics.iterations
            << " iterations" << std::endl;
    check(statistics.residual < tolerance, what + "NewtonSolver converges");
    check(difference.linfty_norm() < 1e-10 * u.linfty_norm(),
          what + "NewtonSolver finds the same minimizer");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  // Tractions in units of E: axial 0.1, lateral 0.05, transverse 0.001.
  run<2>(0.2, 0.05, 0.1, 0.05, 0.001);
  run<3>(0.25, 0.125, 0.1, 0.05, 0.001);
}
