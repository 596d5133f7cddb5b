// 'solver/Hessian projection': where the PSD projection of the local
// tangents is active at the solution, projected Newton converges only
// linearly, and Newton with the exact Hessian (used where the assembled sum
// is positive definite) quadratically, to the same minimizer.
//
// Scenes (as tests/solver/newton_quadratic_convergence, static, dt = 1):
// neo-Hookean boxes clamped at x = 0 and loaded by a dead-load traction on
// the face x = L along the axis, with a small transverse part (0.001 E):
// a stubby block (0.25 x 0.5 (x 0.5) m) compressed by 0.1 E, whose
// elements' rotation modes turn indefinite under compression. (In uniaxial
// tension the 3D bar's lateral twist mode is indefinite too, but there the
// projection changed the residuals by less than 1e-3.) The projection
// changes those tangents at the solution (checked), while the block as a
// whole is stable: the exact assembled Hessian is positive definite there
// (checked with CholmodSolver::factorize_if_positive_definite).
//
// Checked for each dim:
//  - full Newton steps with the exact Hessian converge quadratically
//    (r_k+1 / r_k -> 0), with the projected Hessian linearly (the last
//    ratios above round-off stay above 1e-3) and in more iterations;
//  - NewtonSolver with 'when indefinite' needs fewer iterations than with
//    'always', falls back to the projected Hessian in none of them near the
//    solution, and both reach the full-Newton minimizer; with UMFPACK and
//    CG AMG (no definiteness test, the descent check instead) 'when
//    indefinite' gives the same.
// Residual histories go to stdout; the output holds counts and checks.

#include <bfemp/base/input_error.h>
#include <bfemp/solver/cholmod_solver.h>
#include <bfemp/solver/newton_solver.h>
#include <bfemp/solver/positive_semidefinite.h>
#include <bfemp/solver/solver_parameters.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "solver_test_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::check;

namespace
{
  const double youngs_modulus = 1e6;
  const double poisson_ratio  = 0.3;
  const double tolerance      = 1e-12;

  /** r_k+1 / r_k of the last ratio whose r_k+1 is above @p noise. */
  double
  last_ratio_above(const std::vector<double> &r, const double noise)
  {
    double ratio = 1.;
    for (unsigned int k = 0; k + 1 < r.size(); ++k)
      if (r[k + 1] > noise)
        ratio = r[k + 1] / r[k];
    return ratio;
  }

  template <int dim>
  NewtonStatistics
  solve_with(bfemp_tests::FemScene<dim> &scene,
             const std::string          &projection,
             const std::string          &linear_solver,
             Vector<double>             &u,
             const std::string          &filter        = "clamp",
             const unsigned int          extrapolation = 0,
             const double                growth_limit  = 0.,
             const bool                  skip_failed   = false)
  {
    SolverParameters parameters;
    parameters.skip_failed_exact_factorizations = skip_failed;
    parameters.exact_step_growth_limit          = growth_limit;
    parameters.eigenvalue_filter                = filter;
    parameters.projected_step_extrapolation     = extrapolation;
    parameters.newton_tolerance                 = tolerance;
    parameters.maximum_newton_iterations        = 200;
    parameters.linear_solver                    = linear_solver;
    parameters.hessian_projection               = projection;
    parameters.check_invariants                 = true;
    NewtonSolver<dim> newton(parameters);
    u.reinit(scene.dofs.n_dofs());
    return newton.minimize(scene.potential, u, 1., "static block");
  }

  /** Ascending eigenvalues of a symmetric matrix (LAPACK's dgeev). */
  std::vector<double>
  eigenvalues(const FullMatrix<double> &matrix)
  {
    LAPACKFullMatrix<double> lapack(matrix.m(), matrix.n());
    lapack = matrix;
    lapack.compute_eigenvalues();
    std::vector<double> values(matrix.m());
    for (unsigned int m = 0; m < values.size(); ++m)
      values[m] = lapack.eigenvalue(m).real();
    std::sort(values.begin(), values.end());
    return values;
  }

  /**
   * filter_eigenvalues() on symmetric matrices of the contact stencils'
   * sizes, indefinite and rank deficient: the eigenvalues become max(l, 0)
   * (clamp) or |l| (absolute) of LAPACK's, on the same eigenvectors (the
   * result commutes with the matrix).
   */
  void
  check_filter_eigenvalues()
  {
    bfemp_tests::RandomNumbers random(20261128);
    double                     worst_values = 0., worst_commutator = 0.;
    for (const unsigned int n : {3u, 6u, 12u, 24u})
      for (const unsigned int rank : {n, n / 2})
        {
          // A = sum of rank terms s_k v_k v_k^T with signs of both kinds
          FullMatrix<double> A(n, n);
          for (unsigned int k = 0; k < rank; ++k)
            {
              Vector<double> v(n);
              for (unsigned int i = 0; i < n; ++i)
                v[i] = random.uniform(-1., 1.);
              const double weight = (k % 3 == 0 ? -1. : 1.) *
                                    std::pow(10., random.uniform(-3., 3.));
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  A(i, j) += weight * v[i] * v[j];
            }
          const std::vector<double> values = eigenvalues(A);
          const double              largest =
            std::max(std::abs(values.front()), std::abs(values.back()));
          for (const EigenvalueFilter filter :
               {EigenvalueFilter::clamp, EigenvalueFilter::absolute})
            {
              FullMatrix<double> F(A);
              filter_eigenvalues(F, filter);
              std::vector<double> expected(n, 0.);
              for (unsigned int m = 0; m < values.size(); ++m)
                expected[m] = filtered_eigenvalue(values[m], filter);
              std::sort(expected.begin(), expected.end());
              const std::vector<double> filtered_values = eigenvalues(F);
              for (unsigned int m = 0; m < n; ++m)
                worst_values =
                  std::max(worst_values,
                           std::abs(filtered_values[m] - expected[m]) /
                             largest);
              FullMatrix<double> AF(n, n), FA(n, n);
              A.mmult(AF, F);
              F.mmult(FA, A);
              AF.add(-1., FA);
              worst_commutator =
                std::max(worst_commutator,
                         AF.frobenius_norm() / (largest * largest));
            }
        }
    bfemp_tests::check_below(worst_values,
                             1e-12,
                             "filter_eigenvalues: clamp and absolute give "
                             "max(l, 0) and |l| of LAPACK's eigenvalues l: "
                             "largest difference / |l|_max");
    bfemp_tests::check_below(worst_commutator,
                             1e-12,
                             "filter_eigenvalues: the result commutes with the "
                             "matrix (same eigenvectors): |AF - FA| / "
                             "|l|_max^2");
  }

  template <int dim>
  void
  run(const double length,
      const double width,
      const double edge,
      const double axial)
  {
    const std::string          what = std::to_string(dim) + "D block: ";
    bfemp_tests::FemScene<dim> scene(
      {bfemp_tests::neo_hookean_bar<dim>(length,
                                         width,
                                         edge,
                                         youngs_modulus,
                                         poisson_ratio)});
    scene.clamp(0);
    bfemp_tests::DeadLoadTerm<dim> load(scene.dofs.n_dofs());
    Tensor<1, dim>                 end_traction;
    end_traction[0] = axial * youngs_modulus;
    end_traction[1] = 0.001 * youngs_modulus;
    bfemp_tests::add_traction(scene, load, 1, end_traction);
    scene.elasticity.set_scale(1.);
    scene.potential.set_terms({&scene.elasticity, &load});
    scene.potential.setup_system();

    // Full Newton steps with each Hessian.
    CholmodSolver  cholmod;
    Vector<double> u_exact(scene.dofs.n_dofs());
    Vector<double> u_projected(scene.dofs.n_dofs());
    const auto     exact     = bfemp_tests::full_newton(scene.potential,
                                                cholmod,
                                                u_exact,
                                                tolerance,
                                                60,
                                                HessianKind::exact);
    const auto     projected = bfemp_tests::full_newton(scene.potential,
                                                    cholmod,
                                                    u_projected,
                                                    tolerance,
                                                    60);
    for (const auto &[name, history] :
         {std::make_pair("exact", &exact),
          std::make_pair("projected", &projected)})
      {
        std::cout << what << name << " residuals";
        for (const double r : history->residuals)
          std::cout << ' ' << r;
        std::cout << std::endl;
      }
    check(exact.converged && projected.converged,
          what + "full Newton converges with both Hessians");
    const unsigned int n_projected =
      bfemp_tests::projected_tangents(scene, u_exact);
    deallog << what << (n_projected > 0 ? "some" : "no")
            << " element tangents projected at the solution" << std::endl;
    check(n_projected > 0, what + "the projection is active at the solution");
    check(cholmod.factorize_if_positive_definite(
            scene.potential.hessian(u_exact, HessianKind::exact)),
          what + "the exact Hessian is positive definite at the solution");

    // Ratios above 100 times the round-off floor of ||p||.
    Vector<double> g, p;
    scene.potential.gradient(u_exact, g);
    cholmod.factorize(scene.potential.hessian(u_exact, HessianKind::exact));
    g *= -1.;
    cholmod.solve(g, p);
    const double noise           = 100. * p.linfty_norm();
    const double exact_ratio     = last_ratio_above(exact.residuals, noise);
    const double projected_ratio = last_ratio_above(projected.residuals, noise);
    std::cout << what << "last ratios above round-off: exact " << exact_ratio
              << ", projected " << projected_ratio << std::endl;
    check(exact_ratio < 1e-3, what + "exact: r_k+1 / r_k -> 0 (< 1e-3)");
    check(projected_ratio > 1e-3,
          what + "projected: r_k+1 / r_k stays above 1e-3 (linear)");
    check(exact.residuals.size() < projected.residuals.size(),
          what + "exact needs fewer iterations");
    Vector<double> difference(u_projected);
    difference -= u_exact;
    check(difference.linfty_norm() < 1e-10 * u_exact.linfty_norm(),
          what + "both reach the same minimizer");

    // The library's NewtonSolver with each setting.
    Vector<double>         u_always, u_exact_solver, u_umfpack, u_cg;
    const NewtonStatistics always =
      solve_with(scene, "always", "CHOLMOD", u_always);
    const NewtonStatistics when_indefinite =
      solve_with(scene, "when indefinite", "CHOLMOD", u_exact_solver);
    const NewtonStatistics umfpack =
      solve_with(scene, "when indefinite", "UMFPACK", u_umfpack);
    const NewtonStatistics cg =
      solve_with(scene, "when indefinite", "CG AMG", u_cg);
    std::cout << what << "NewtonSolver iterations: always " << always.iterations
              << ", when indefinite " << when_indefinite.iterations << " ("
              << when_indefinite.projected_hessians << " projected), UMFPACK "
              << umfpack.iterations << " (" << umfpack.projected_hessians
              << " projected), CG AMG " << cg.iterations << " ("
              << cg.projected_hessians << " projected)" << std::endl;
    check(always.projected_hessians == always.iterations,
          what + "'always' projects in every iteration");
    check(when_indefinite.iterations < always.iterations,
          what + "'when indefinite' needs fewer iterations than 'always'");
    check(when_indefinite.projected_hessians < when_indefinite.iterations,
          what + "'when indefinite' uses the exact Hessian");
    check(umfpack.iterations == when_indefinite.iterations,
          what + "UMFPACK (descent check) takes the same iterations");
    check(cg.iterations < always.iterations &&
            cg.projected_hessians < cg.iterations,
          what + "CG AMG (descent check) uses the exact Hessian too");
    // The other eigenvalue filters and the extrapolated projected steps.
    Vector<double> u_absolute, u_adaptive, u_extrapolated, u_extrapolated_exact;
    const NewtonStatistics absolute =
      solve_with(scene, "always", "CHOLMOD", u_absolute, "absolute");
    const NewtonStatistics adaptive =
      solve_with(scene, "always", "CHOLMOD", u_adaptive, "adaptive");
    const NewtonStatistics extrapolated =
      solve_with(scene, "always", "CHOLMOD", u_extrapolated, "clamp", 3);
    const NewtonStatistics extrapolated_exact = solve_with(scene,
                                                           "when indefinite",
                                                           "CHOLMOD",
                                                           u_extrapolated_exact,
                                                           "clamp",
                                                           3);
    deallog << what << "NewtonSolver iterations with 'always': clamp "
            << always.iterations << ", absolute " << absolute.iterations
            << ", adaptive " << adaptive.iterations
            << "; 'when indefinite' with 3 extrapolations "
            << extrapolated_exact.iterations << std::endl;
    // The extrapolated projected steps' count goes to the log only: whether
    // a doubled step still lowers E is decided at round-off here (16 or 17
    // in 2D, 14 or 15 in 3D, depending on the machine's BLAS kernels).
    std::cout << what
              << "clamp with 3 extrapolations: " << extrapolated.iterations
              << " iterations" << std::endl;
    check(extrapolated.iterations <= always.iterations + 2,
          what + "'always' with 3 extrapolations takes at most 2 iterations "
                 "more than without");
    check(extrapolated_exact.iterations == when_indefinite.iterations,
          what + "extrapolation leaves exact Newton steps alone");
    // 'exact step growth limit': Newton's moves here shrink by 0.066, 0.015,
    // 4e-5 from one iteration to the next; at a limit of 0.01 the exact
    // direction of the second iteration is set aside, and those after the
    // projected moves (linear convergence) too. At 1e6 none is.
    Vector<double>         u_limited, u_unlimited;
    const NewtonStatistics limited   = solve_with(scene,
                                                "when indefinite",
                                                "CHOLMOD",
                                                u_limited,
                                                "clamp",
                                                0,
                                                0.01);
    const NewtonStatistics unlimited = solve_with(scene,
                                                  "when indefinite",
                                                  "CHOLMOD",
                                                  u_unlimited,
                                                  "clamp",
                                                  0,
                                                  1e6);
    deallog << what << "'when indefinite' with exact step growth limit 0.01: "
            << limited.iterations << " iterations, "
            << limited.long_exact_directions << " exact directions set aside"
            << std::endl;
    check(limited.long_exact_directions > 0 &&
            limited.long_exact_directions <= limited.projected_hessians,
          what + "growth limit 0.01 sets exact directions aside, and the "
                 "projected Hessian takes those iterations");
    check(unlimited.iterations == when_indefinite.iterations &&
            unlimited.long_exact_directions == 0,
          what + "growth limit 1e6 leaves Newton as it was");
    // 'skip failed exact factorizations': the exact Hessian of the block
    // stays positive definite, so nothing is skipped and Newton is as
    // before (tests/experiments/twist_projected_extrapolation has a scene
    // where it is indefinite).
    Vector<double>         u_skipping;
    const NewtonStatistics skipping = solve_with(scene,
                                                 "when indefinite",
                                                 "CHOLMOD",
                                                 u_skipping,
                                                 "clamp",
                                                 0,
                                                 0.,
                                                 true);
    deallog << what << "'when indefinite': " << when_indefinite.iterations
            << " iterations, " << when_indefinite.projected_hessians
            << " projected, " << when_indefinite.factorizations
            << " factorizations; skipping failed exact factorizations: "
            << skipping.iterations << " iterations, "
            << skipping.projected_hessians << " projected, "
            << skipping.factorizations << " factorizations, "
            << skipping.skipped_exact_factorizations << " skipped" << std::endl;
    check(skipping.skipped_exact_factorizations == 0 &&
            skipping.iterations == when_indefinite.iterations &&
            skipping.factorizations == when_indefinite.factorizations,
          what + "with a positive definite exact Hessian, skipping failed "
                 "exact factorizations changes nothing");
    for (const auto &[name, v] :
         {std::make_pair("skip failed exact factorizations", &u_skipping),
          std::make_pair("absolute", &u_absolute),
          std::make_pair("adaptive", &u_adaptive),
          std::make_pair("extrapolated", &u_extrapolated),
          std::make_pair("growth limit 0.01", &u_limited),
          std::make_pair("always", &u_always),
          std::make_pair("when indefinite", &u_exact_solver),
          std::make_pair("UMFPACK", &u_umfpack),
          std::make_pair("CG AMG", &u_cg)})
      {
        Vector<double> d(*v);
        d -= u_exact;
        check(d.linfty_norm() < 1e-10 * u_exact.linfty_norm(),
              what + name + ": NewtonSolver finds the same minimizer");
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  check_filter_eigenvalues();
  // A stubby block (0.25 x 0.5 (x 0.5) m) compressed by 0.1 E, where the
  // neo-Hookean rotation modes turn indefinite.
  run<2>(0.25, 0.5, 0.0625, -0.1);
  run<3>(0.25, 0.5, 0.125, -0.1);
}
