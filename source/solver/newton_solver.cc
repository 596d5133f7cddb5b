#include <bfemp/base/input_error.h>
#include <bfemp/solver/newton_solver.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace bfemp
{
  NewtonStatistics &
  NewtonStatistics::operator+=(const NewtonStatistics &other)
  {
    iterations += other.iterations;
    backtracks += other.backtracks;
    bound_hits += other.bound_hits;
    ccd_bound_hits += other.ccd_bound_hits;
    partial_constraint_moves += other.partial_constraint_moves;
    carried_constraint_moves += other.carried_constraint_moves;
    projected_hessians += other.projected_hessians;
    long_exact_directions += other.long_exact_directions;
    skipped_exact_factorizations += other.skipped_exact_factorizations;
    factorizations += other.factorizations;
    modified_iterations += other.modified_iterations;
    cg_iterations += other.cg_iterations;
    residual            = other.residual;
    energy              = other.energy;
    minimum_determinant = other.minimum_determinant;
    minimum_distance    = other.minimum_distance;
    assembly_time += other.assembly_time;
    factorization_time += other.factorization_time;
    solve_time += other.solve_time;
    line_search_time += other.line_search_time;
    return *this;
  }



  namespace
  {
    /**
     * Relative CG residual at which a direction counts as the exact Newton
     * step: with it, factorization reuse ends the reduced twist's steps
     * within 1e-14 m of factorizing every iteration
     * (experiments/twist_newton_levers).
     */
    constexpr double exact_forcing = 1e-8;

    /**
     * The rigid translations of the unified DoF space (component c of every
     * node), the near-null space that lets AMG coarsen a vector problem
     * without mixing components.
     */
    std::vector<std::vector<bool>>
    translation_modes_of(const unsigned int dim, const std::size_t n_dofs)
    {
      std::vector<std::vector<bool>> modes(dim, std::vector<bool>(n_dofs));
      for (std::size_t i = 0; i < n_dofs; ++i)
        modes[i % dim][i] = true;
      return modes;
    }

    /**
     * "name value J; ..." of every term of E at u, for 'log iterations': the
     * elastic term alone is the strain energy whose convergence seed 002
     * Fig. 26 draws, and a term that moves against the total shows which
     * part of the physics a slow step fights.
     */
    template <int dim>
    std::string
    term_energies(const IncrementalPotential<dim> &potential,
                  const Vector<double>            &u)
    {
      const std::vector<std::string> names  = potential.term_names();
      const std::vector<double>      values = potential.term_values(u);
      std::ostringstream             text;
      text << std::setprecision(10);
      for (unsigned int t = 0; t < names.size(); ++t)
        text << (t > 0 ? "; " : "") << names[t] << " " << values[t] << " J";
      return text.str();
    }
  } // namespace



  template <int dim>
  NewtonSolver<dim>::NewtonSolver(const SolverParameters &parameters)
    : parameters(parameters)
    , solver(create_linear_solver(linear_solver_type_from_string(
                                    parameters.linear_solver),
                                  parameters.cg_tolerance))
  {}



  template <int dim>
  const LinearSolver &
  NewtonSolver<dim>::linear_solver() const
  {
    return *solver;
  }



  template <int dim>
  double
  NewtonSolver<dim>::line_search(const IncrementalPotential<dim> &potential,
                                 const Vector<double>            &u,
                                 const Vector<double>            &p,
                                 const double                     energy,
                                 const double                     slope,
                                 Vector<double>                  &trial,
                                 double                          &trial_energy,
                                 const bool                       projected,
                                 NewtonStatistics &statistics) const
  {
    // Filtering (Section 5): no trial point may reach det F = 0 or a
    // contact distance of 0, so start below the first such root.
    const EnergyTerm<dim> *limiting = nullptr;
    const double           bound    = potential.step_bound(u, p, &limiting);
    double                 step     = 1.;
    if (parameters.step_bound_fraction * bound < 1.)
      {
        step = parameters.step_bound_fraction * bound;
        ++statistics.bound_hits;
        if (limiting->is_contact())
          ++statistics.ccd_bound_hits;
      }
    // Near the minimizer the decrease t |g.p| falls below the round-off of
    // E, and comparing energies decides nothing. There the change of E is
    // measured by the trapezoidal rule on the directional derivative,
    // t/2 (g(u).p + g(u + t p).p), exact for a quadratic and free of the
    // cancellation in E; the trial point must also not raise E beyond its
    // round-off.
    const double   round_off = potential.round_off();
    Vector<double> trial_gradient;
    for (unsigned int k = 0; k <= parameters.maximum_backtracks; ++k)
      {
        trial = u;
        trial.add(step, p);
        trial_energy = potential.value(trial);
        if (std::isfinite(trial_energy))
          {
            if (trial_energy <=
                energy + parameters.armijo_constant * step * slope)
              return projected && step == 1.
                       ? extrapolate(potential,
                                     u,
                                     p,
                                     parameters.step_bound_fraction * bound,
                                     trial,
                                     trial_energy)
                       : step;
            if (step * std::abs(slope) <= round_off &&
                trial_energy <= energy + round_off)
              {
                potential.gradient(trial, trial_gradient);
                const double change = 0.5 * step * (slope + trial_gradient * p);
                if (change <= parameters.armijo_constant * step * slope)
                  return step;
              }
          }
        step *= 0.5;
        ++statistics.backtracks;
      }
    return 0.;
  }



  template <int dim>
  double
  NewtonSolver<dim>::extrapolate(const IncrementalPotential<dim> &potential,
                                 const Vector<double>            &u,
                                 const Vector<double>            &p,
                                 const double                     bound,
                                 Vector<double>                  &trial,
                                 double &trial_energy) const
  {
    // The projected Hessian's model overestimates the curvature along p
    // (H+ >= H), so E often still falls beyond the full step: double it
    // while it does, inside the filter's bound.
    double         step = 1.;
    Vector<double> longer;
    for (unsigned int k = 0; k < parameters.projected_step_extrapolation; ++k)
      {
        if (2. * step > bound)
          break;
        longer = u;
        longer.add(2. * step, p);
        const double longer_energy = potential.value(longer);
        if (!(longer_energy < trial_energy))
          break;
        step *= 2.;
        trial.swap(longer);
        trial_energy = longer_energy;
      }
    return step;
  }



  template <int dim>
  double
  NewtonSolver<dim>::move_constraints(IncrementalPotential<dim> &potential,
                                      Vector<double>            &u,
                                      const double               progress,
                                      double                    &energy,
                                      NewtonStatistics &statistics) const
  {
    // The rest of the way to the targets: the constrained components of
    // impose(u) - u, and the obstacles from progress to 1.
    Vector<double> move = u;
    potential.dof_space().impose(move);
    move -= u;
    potential.set_obstacle_path(progress, 1.);
    double bound = potential.step_bound(u, move);

    // Moved alone, a boundary pressing into a stiff body advances only
    // about the contact gap per iteration (the free DoFs stay behind it).
    // The free DoFs' linear response carries them along, so the relative
    // motion that the filter sees is small; it is used when it lets the
    // move go further.
    if (bound > 0. && bound < 1.)
      {
        Vector<double> along =
          free_response(potential, u, move, progress, bound);
        along += move;
        potential.set_obstacle_path(progress, 1.);
        const double carried_bound = potential.step_bound(u, along);
        if (carried_bound > bound)
          {
            bound = carried_bound;
            move.swap(along);
            ++statistics.carried_constraint_moves;
          }
      }

    double t = 1.;
    if (parameters.step_bound_fraction * bound < 1.)
      {
        t = parameters.step_bound_fraction * bound;
        ++statistics.partial_constraint_moves;
      }
    u.add(t, move);
    const double moved = t == 1. ? 1. : progress + t * (1. - progress);
    if (t == 1.)
      potential.dof_space().impose(u); // exact targets, free of round-off
    potential.set_obstacle_path(moved, moved);
    energy = potential.value(u);
    return moved;
  }



  template <int dim>
  Vector<double>
  NewtonSolver<dim>::free_response(IncrementalPotential<dim> &potential,
                                   const Vector<double>      &u,
                                   const Vector<double>      &move,
                                   const double               progress,
                                   const double               bound) const
  {
    // H_fc m as a one-sided difference of the free gradient P grad E along
    // the move, over a fraction of the feasible move small enough that the
    // barrier's curvature (scale: the gap) hardly changes on it.
    const double   h = 1e-3 * std::min(1., bound);
    Vector<double> gradient_here, gradient_moved;
    potential.set_obstacle_path(progress, progress);
    potential.gradient(u, gradient_here);
    const SparseMatrix<double> &hessian = potential.hessian(u);
    Vector<double>              moved   = u;
    moved.add(h, move);
    const double moved_progress = progress + h * (1. - progress);
    potential.set_obstacle_path(moved_progress, moved_progress);
    potential.gradient(moved, gradient_moved);
    potential.set_obstacle_path(progress, progress);

    // H_ff r = -H_fc m; the projected matrix keeps r free.
    Vector<double> coupling = gradient_moved;
    coupling -= gradient_here;
    coupling *= -1. / h;
    Vector<double> response(u.size());
    solver->factorize(hessian);
    factorization_reusable = true;
    factorized_numbering   = potential.dof_space().numbering();
    solver->solve(coupling, response);
    potential.dof_space().project(response);
    if (!std::isfinite(response.linfty_norm()))
      response = 0.;
    return response;
  }



  template <int dim>
  void
  NewtonSolver<dim>::log_iteration(const std::string      &step_label,
                                   const NewtonStatistics &statistics,
                                   const double            stop_at,
                                   const double            step,
                                   const double            energy,
                                   const double            gradient_norm,
                                   const double            forcing,
                                   const bool              factorized,
                                   const bool              modified,
                                   const unsigned int      cg_iterations,
                                   const HessianKind       kind,
                                   const double            model_ratio,
                                   const double            rejected_exact,
                                   const std::string      &term_energies) const
  {
    std::ostringstream line;
    line << std::setprecision(3) << "  " << step_label << ": iteration "
         << statistics.iterations << ", ||p||/dt " << statistics.residual
         << " m/s (stop " << stop_at << "), step " << step << ", backtracks "
         << statistics.backtracks << ", E " << std::setprecision(10) << energy
         << std::setprecision(3) << " J, ||g|| " << gradient_norm << ", "
         << (modified     ? "last factorization, no Hessian (modified Newton)"
             : factorized ? "factorized"
                          : "CG with an older factorization");
    if (!factorized && !modified)
      line << " to eta " << forcing;
    if (cg_iterations > 0)
      line << ", " << cg_iterations << " CG iterations";
    // the exact Hessian was not used (with 'when indefinite': it was
    // indefinite or its solve failed, and the factorization count includes
    // the failed attempt)
    if (rejected_exact > 0.)
      line << ", exact direction " << rejected_exact
           << " m/s too long (growth limit)";
    if (kind == HessianKind::projected)
      line << ", projected Hessian";
    else if (kind == HessianKind::absolute)
      line << ", projected Hessian (absolute eigenvalues)";
    line << ", model ratio " << model_ratio << ", terms: " << term_energies;
    std::cout << line.str() << std::endl;
  }



  template <int dim>
  double
  NewtonSolver<dim>::exact_direction_too_long(
    const IncrementalPotential<dim> &potential,
    const Vector<double>            &direction,
    const double                     dt,
    const double                     last_move) const
  {
    // Newton's moves shrink near the minimizer (quadratically once there);
    // an exact direction many times longer than the last move follows a
    // curvature near zero that the line search would cut back by 1/2^k at
    // one energy evaluation per halving, for a short step.
    if (!(parameters.exact_step_growth_limit > 0.) || !(last_move > 0.))
      return 0.;
    const double length = potential.increment_norm(direction) / dt;
    return length > parameters.exact_step_growth_limit * last_move ? length
                                                                   : 0.;
  }



  template <int dim>
  bool
  NewtonSolver<dim>::skip_exact_factorization() const
  {
    // The exact Hessian of a contact or compressed scene stays indefinite
    // over runs of iterations, and each failed attempt costs up to a whole
    // factorization besides the projected one that follows. After a failure
    // the next 1, then 2, 4, ... attempts are skipped until one succeeds:
    // at most log2(n) + 1 failures in n iterations, and the exact Hessian
    // (quadratic convergence) comes back within twice the length of the
    // indefinite run.
    if (!parameters.skip_failed_exact_factorizations || exact_skips_left == 0)
      return false;
    --exact_skips_left;
    return true;
  }



  template <int dim>
  void
  NewtonSolver<dim>::record_exact_factorization(const bool succeeded) const
  {
    exact_skip_length = succeeded ? 0 : std::max(1u, 2 * exact_skip_length);
    exact_skips_left  = exact_skip_length;
  }



  template <int dim>
  HessianKind
  NewtonSolver<dim>::next_filter(const HessianKind current,
                                 const double      model_ratio)
  {
    // Called after an iteration that used the filtered Hessian (its exact
    // iterations say nothing about the filter). The filtered model is at
    // least as curved as the exact one, so rho is usually near or above 1.
    // Well below 1, the energy rose faster than the model along the step
    // (the barrier's higher derivatives, or curvature that clamping to 0
    // dropped): absolute values keep that curvature, so the next step is
    // shorter. Well above 1 the model was too curved: clamping is the
    // flatter of the two. The band between keeps the last choice, so that
    // the model does not flip every iteration.
    if (model_ratio < 0.25)
      return HessianKind::absolute;
    if (model_ratio > 0.75)
      return HessianKind::projected;
    return current;
  }



  template <int dim>
  double
  NewtonSolver<dim>::forcing(const double gradient_norm, const bool first) const
  {
    if (parameters.forcing_term == "none")
      return exact_forcing;
    // Eisenstat and Walker (1996), choice 2 with gamma = 0.9, alpha = 2:
    // eta_k follows the gradient's decrease, so the linear solve is as
    // accurate as the quadratic model is at this distance from the
    // minimizer. Their eta_max (0.9, for GMRES with a weak preconditioner)
    // is far too loose for IPC contact: on the full-resolution twist an
    // eta of 0.1 or 1e-2 cost as many Newton iterations (backtracks at the
    // friction's stick-slip kink) as factorizations it saved, 1e-3 and
    // 1e-4 saved 15 % of the wall time. Below 0.1 their safeguard (eta_k
    // >= gamma eta_k-1^2 where that exceeds 0.1) never acts.
    constexpr double gamma = 0.9, eta_max = 1e-3;
    double           eta = eta_max;
    if (!first && last_gradient_norm > 0.)
      {
        const double ratio = gradient_norm / last_gradient_norm;
        eta                = gamma * ratio * ratio;
      }
    eta                = std::clamp(eta, exact_forcing, eta_max);
    last_gradient_norm = gradient_norm;
    return eta;
  }



  template <int dim>
  bool
  NewtonSolver<dim>::solve_with_last_factorization(
    const SparseMatrix<double> &hessian,
    const Vector<double>       &minus_gradient,
    const double                relative_tolerance,
    const bool                  warm_start,
    Vector<double>             &direction,
    NewtonStatistics           &statistics) const
  {
    // Within a step the Hessian changes little from one iteration to the
    // next once the contact set has settled: an earlier factorization is
    // then a preconditioner under which CG needs a few iterations, each a
    // pair of triangular solves, instead of a new factorization.
    struct LastFactorization
    {
      LinearSolver &solver;
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        solver.solve(src, dst);
      }
    };
    SolverControl            control(parameters.factorization_reuse,
                          relative_tolerance * minus_gradient.l2_norm(),
                          false,
                          false);
    SolverCG<Vector<double>> cg(control);
    if (!warm_start)
      direction.reinit(minus_gradient.size());
    try
      {
        cg.solve(hessian,
                 direction,
                 minus_gradient,
                 LastFactorization{*solver});
      }
    catch (const SolverControl::NoConvergence &)
      {
        statistics.cg_iterations += control.last_step();
        return false;
      }
    statistics.cg_iterations += control.last_step();
    return std::isfinite(direction.linfty_norm());
  }



  template <int dim>
  bool
  NewtonSolver<dim>::holds_factorization_for(
    const IncrementalPotential<dim> &potential) const
  {
    return factorization_reusable &&
           factorized_numbering == potential.dof_space().numbering();
  }



  template <int dim>
  bool
  NewtonSolver<dim>::modified_direction(
    const IncrementalPotential<dim> &potential,
    const Vector<double>            &minus_gradient,
    const double                     dt,
    const double                     last_residual,
    Vector<double>                  &direction,
    NewtonStatistics                &statistics) const
  {
    // The chord method when H_0 is kept through a solve, Shamanskii's when
    // it is refreshed every few iterations (Kelley 1995, Ch. 5): with H_0
    // positive definite, p = -H_0^-1 g descends, and the error contracts
    // by about ||I - H_0^-1 H|| per iteration. The contraction of the
    // increments measures that factor, so a direction that shrinks too
    // slowly is set aside for the assembled Hessian (only a pair of
    // triangular solves spent).
    if (!(parameters.modified_newton_contraction > 0.) ||
        !holds_factorization_for(potential))
      return false;
    Timer timer;
    try
      {
        solver->solve(minus_gradient, direction);
      }
    catch (const SimulationError &)
      {
        return false;
      }
    potential.dof_space().project(direction);
    statistics.solve_time += timer.wall_time();
    if (!std::isfinite(direction.linfty_norm()) ||
        !(-(minus_gradient * direction) < 0.))
      return false;
    const double residual = potential.increment_norm(direction) / dt;
    return last_residual == 0. ||
           residual <= parameters.modified_newton_contraction * last_residual;
  }



  template <int dim>
  bool
  NewtonSolver<dim>::newton_direction(IncrementalPotential<dim> &potential,
                                      const Vector<double>      &u,
                                      const Vector<double>      &minus_gradient,
                                      const HessianKind          kind,
                                      const InexactSolve        &inexact,
                                      Vector<double>            &direction,
                                      NewtonStatistics &statistics) const
  {
    const bool reuse =
      parameters.factorization_reuse > 0 && holds_factorization_for(potential);
    const bool skip_factorization =
      kind == HessianKind::exact && skip_exact_factorization();
    if (skip_factorization)
      ++statistics.skipped_exact_factorizations;
    // nothing to do with the exact Hessian then: not even its assembly
    if (skip_factorization && !reuse)
      return false;
    Timer                       timer;
    const SparseMatrix<double> &hessian = potential.hessian(u, kind);
    statistics.assembly_time += timer.wall_time();

    // An exact Hessian may also be singular (LU) or stall CG: any failure of
    // the linear solver on it hands the iteration to the projected one.
    try
      {
        if (reuse)
          {
            timer.restart();
            bool solved = solve_with_last_factorization(hessian,
                                                        minus_gradient,
                                                        inexact.forcing,
                                                        false,
                                                        direction,
                                                        statistics);
            potential.dof_space().project(direction);
            // CG from p = 0 underestimates |p| (its iterates grow in the
            // preconditioner's norm): a loose direction that would pass the
            // stopping test is solved on to an exact step first.
            if (solved && inexact.forcing > exact_forcing &&
                potential.increment_norm(direction) / inexact.dt <
                  inexact.exact_below)
              {
                solved = solve_with_last_factorization(hessian,
                                                       minus_gradient,
                                                       exact_forcing,
                                                       true,
                                                       direction,
                                                       statistics);
                potential.dof_space().project(direction);
              }
            statistics.solve_time += timer.wall_time();
            // CG on an indefinite matrix need not descend: then the
            // factorization below decides.
            if (solved && -(minus_gradient * direction) < 0.)
              return true;
          }
        if (skip_factorization)
          return false;
        timer.restart();
        bool factorized = true;
        ++statistics.factorizations;
        if (kind != HessianKind::exact)
          solver->factorize(hessian);
        else
          factorized = solver->factorize_if_positive_definite(hessian);
        statistics.factorization_time += timer.wall_time();
        factorization_reusable = factorized;
        factorized_numbering   = potential.dof_space().numbering();
        if (kind == HessianKind::exact)
          record_exact_factorization(factorized);
        if (!factorized)
          return false;
        timer.restart();
        solver->solve(minus_gradient, direction);
        // P H P + (I - P) keeps p = P p only up to round-off of the size of
        // H; projecting again keeps slanted slip constraints exact.
        potential.dof_space().project(direction);
        statistics.solve_time += timer.wall_time();
      }
    catch (const SimulationError &)
      {
        if (kind != HessianKind::exact)
          throw;
        return false;
      }
    if (kind != HessianKind::exact)
      return true;
    // Solvers that cannot detect indefiniteness: a direction that does not
    // descend (or is not finite) came from an indefinite matrix.
    const double slope = -(minus_gradient * direction);
    return std::isfinite(direction.linfty_norm()) && slope < 0.;
  }



  template <int dim>
  NewtonStatistics
  NewtonSolver<dim>::minimize(IncrementalPotential<dim> &potential,
                              Vector<double>            &u,
                              const double               dt,
                              const std::string         &step_label,
                              const double               start_progress,
                              const double               stop_tolerance)
  {
    // Looser than eps_d for the friction passes before a step's last.
    const double stop_at =
      stop_tolerance > 0. ? stop_tolerance : parameters.newton_tolerance;
    NewtonStatistics statistics;
    Timer            timer;
    Vector<double>   gradient, direction(u.size()), trial(u.size());
    double           progress = start_progress;
    solver->set_constant_modes(translation_modes_of(dim, u.size()));
    potential.set_obstacle_path(progress, progress);
    double energy = potential.value(u);
    if (!std::isfinite(energy))
      throw SimulationError(step_label +
                            ": the incremental potential is not finite at "
                            "the initial guess: an element or particle is "
                            "inverted (or the state holds a NaN). If nodes "
                            "have a prescribed motion, their displacement in "
                            "one step may exceed the size of the elements "
                            "next to them; reduce the time step.");

    auto fail = [&](const std::string &what) {
      std::ostringstream message;
      message << step_label << ": " << what << " after "
              << statistics.iterations << " Newton iterations (residual "
              << "||p|| / dt = " << statistics.residual
              << " m/s, 'solver/Newton tolerance' = "
              << parameters.newton_tolerance << " m/s, energy " << energy
              << " J";
      if (progress < 1.)
        message << ", prescribed motions and obstacles moved "
                << 100. * progress
                << " % of the way to their targets: something blocks them";
      message << "). Reduce the time step, or raise 'solver/maximum Newton "
                 "iterations'.";
      throw SimulationError(message.str());
    };

    // The positive semi-definite model the projected iterations use; with
    // 'adaptive' it follows the model ratio of the last iteration.
    HessianKind filtered_kind = parameters.eigenvalue_filter == "absolute"
                                  ? HessianKind::absolute
                                  : HessianKind::projected;
    // ||t p|| / dt of the last accepted iterate ('exact step growth limit')
    double last_move  = 0.;
    exact_skip_length = 0;
    exact_skips_left  = 0;
    // set after a modified Newton direction along which E did not fall
    bool refresh_hessian = false;
    while (true)
      {
        if (statistics.iterations == parameters.maximum_newton_iterations)
          fail("no convergence");
        ++statistics.iterations;

        timer.restart();
        if (progress < 1.)
          progress =
            move_constraints(potential, u, progress, energy, statistics);
        statistics.line_search_time += timer.wall_time();

        timer.restart();
        potential.gradient(u, gradient);
        gradient *= -1.;
        statistics.assembly_time += timer.wall_time();
        const unsigned int factorizations_before = statistics.factorizations;
        const unsigned int cg_iterations_before  = statistics.cg_iterations;
        const InexactSolve inexact{forcing(gradient.l2_norm(),
                                           statistics.iterations == 1),
                                   stop_at,
                                   dt};
        // The projection keeps every local Hessian PSD but drops curvature
        // where it acts (the rotation mode of a compressed neo-Hookean
        // particle or element, a contact distance's curvature): Newton then
        // converges linearly at best. Where the exact sum is positive
        // definite it gives a descent direction with quadratic convergence.
        const bool modified =
          !refresh_hessian && modified_direction(potential,
                                                 gradient,
                                                 dt,
                                                 statistics.residual,
                                                 direction,
                                                 statistics);
        if (modified)
          ++statistics.modified_iterations;
        bool exact = !modified &&
                     parameters.hessian_projection == "when indefinite" &&
                     newton_direction(potential,
                                      u,
                                      gradient,
                                      HessianKind::exact,
                                      inexact,
                                      direction,
                                      statistics);
        const double rejected_exact =
          exact ? exact_direction_too_long(potential, direction, dt, last_move)
                : 0.;
        if (rejected_exact > 0.)
          {
            exact = false;
            ++statistics.long_exact_directions;
          }
        if (!exact && !modified)
          {
            newton_direction(potential,
                             u,
                             gradient,
                             filtered_kind,
                             inexact,
                             direction,
                             statistics);
            ++statistics.projected_hessians;
          }
        if (!std::isfinite(direction.linfty_norm()))
          fail("the linear solver returned a non-finite Newton direction");
        statistics.residual = potential.increment_norm(direction) / dt;

        timer.restart();
        // gradient holds -g: the slope along p is g.p = -(-g).p.
        const double slope        = -(gradient * direction);
        double       trial_energy = energy;
        const double step         = statistics.residual == 0.
                                      ? 0.
                                      : line_search(potential,
                                            u,
                                            direction,
                                            energy,
                                            slope,
                                            trial,
                                            trial_energy,
                                            !exact && !modified,
                                            statistics);
        statistics.line_search_time += timer.wall_time();

        // rho = actual / predicted decrease, the model m(t p) = E + t g.p +
        // t^2 p.H p / 2 with H p = -g: m(t p) - E = t g.p (1 - t / 2).
        // (An extrapolated step t > 1 is measured against the model's
        // decrease at t = 1, its minimum.)
        const double model_step = std::min(step, 1.);
        const double model_ratio =
          step > 0. && slope < 0.
            ? (trial_energy - energy) /
                (model_step * slope * (1. - 0.5 * model_step))
            : 0.;
        if (step > 0.)
          {
            u.swap(trial);
            energy = trial_energy;
          }
        last_move = step * statistics.residual;
        if (parameters.check_invariants)
          {
            statistics.minimum_determinant = potential.minimum_determinant(u);
            if (!(statistics.minimum_determinant > 0.))
              fail("an accepted iterate has det F = " +
                   std::to_string(statistics.minimum_determinant) +
                   " <= 0 (invariant check)");
            statistics.minimum_distance = potential.minimum_distance(u);
            if (!(statistics.minimum_distance > 0.))
              fail("an accepted iterate has a particle-boundary distance " +
                   std::to_string(statistics.minimum_distance) +
                   " <= 0 (invariant check)");
          }
        if (parameters.log_iterations)
          log_iteration(step_label,
                        statistics,
                        stop_at,
                        step,
                        energy,
                        gradient.l2_norm(),
                        inexact.forcing,
                        statistics.factorizations > factorizations_before,
                        modified,
                        statistics.cg_iterations - cg_iterations_before,
                        exact || modified ? HessianKind::exact : filtered_kind,
                        model_ratio,
                        rejected_exact,
                        term_energies(potential, u));
        if (!exact && !modified && parameters.eigenvalue_filter == "adaptive")
          filtered_kind = next_filter(filtered_kind, model_ratio);
        if (statistics.residual < stop_at && progress == 1.)
          break;
        // An older matrix's direction that the line search cannot use says
        // nothing about the energy: the next iteration assembles.
        refresh_hessian = modified && step == 0.;
        if (step == 0. && !modified && !(statistics.residual < stop_at))
          fail("the line search found no decrease of the energy");
      }
    statistics.energy = energy;
    return statistics;
  }



  template class NewtonSolver<2>;
  template class NewtonSolver<3>;
} // namespace bfemp
