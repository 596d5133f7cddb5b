#ifndef bfemp_solver_newton_solver_h
#define bfemp_solver_newton_solver_h

#include <bfemp/solver/incremental_potential.h>
#include <bfemp/solver/linear_solver.h>
#include <bfemp/solver/solver_parameters.h>

#include <memory>
#include <string>

namespace bfemp
{
  /** What one minimization cost and how it ended (diagnostics columns). */
  struct NewtonStatistics
  {
    unsigned int iterations = 0;
    /** Step halvings of the Armijo line search, summed over iterations. */
    unsigned int backtracks = 0;
    /** Iterations whose first trial step was cut by the det F bound. */
    unsigned int bound_hits = 0;
    /** Of those, the iterations cut by collision detection (contact). */
    unsigned int ccd_bound_hits = 0;
    /**
     * Iterations that moved constrained DoFs and kinematic obstacles only
     * part of the way to their targets, because the full move would have
     * crossed a particle or inverted an element.
     */
    unsigned int partial_constraint_moves = 0;
    /** Constraint moves that carried the free DoFs along (their linear
     *  response), because that let the move go further. */
    unsigned int carried_constraint_moves = 0;
    /**
     * Iterations whose direction came from the projected Hessian: all with
     * 'Hessian projection = always', the fall-backs with 'when indefinite'.
     */
    unsigned int projected_hessians = 0;
    /** Of those, the iterations whose exact direction the 'exact step
     *  growth limit' set aside. */
    unsigned int long_exact_directions = 0;
    /** Iterations that left out the exact Hessian's factorization after a
     *  failed one ('skip failed exact factorizations'). */
    unsigned int skipped_exact_factorizations = 0;
    /** Factorizations of a Newton iteration's Hessian (fewer than the
     *  iterations with `solver/factorization reuse`, more where a fall-back
     *  refactorizes; the constraint moves' response solves not counted). */
    unsigned int factorizations = 0;
    /** Iterations whose direction came from the last factorization as it
     *  stood, with no Hessian assembled (`solver/modified Newton
     *  contraction`). */
    unsigned int modified_iterations = 0;
    /** Conjugate-gradient iterations preconditioned with an older
     *  factorization (`solver/factorization reuse`), failed solves
     *  included: each costs a pair of triangular solves. */
    unsigned int cg_iterations = 0;
    /** ||p|| / dt of the last iteration [m/s], p measured as
     *  IncrementalPotential::increment_norm() says. */
    double residual = 0.;
    /** E at the minimizer. */
    double energy = 0.;
    /** Smallest det F over accepted iterates (with check invariants). */
    double minimum_determinant = 0.;
    /** Smallest contact distance over accepted iterates (check invariants). */
    double minimum_distance   = 0.;
    double assembly_time      = 0.;
    double factorization_time = 0.;
    double solve_time         = 0.;
    double line_search_time   = 0.;

    NewtonStatistics &
    operator+=(const NewtonStatistics &other);
  };



  /**
   * Projected Newton with a filtered backtracking line search (BFEMP
   * Algorithm 2). Each iteration assembles the gradient and the Hessian
   * (the exact one where it is positive definite, else the projected PSD
   * one; 'solver/Hessian projection'), solves H p = -g, starts the line search
   * at the fraction 'step bound fraction' of the largest step that keeps every
   * det F > 0 (and every contact distance > 0), capped at 1, and halves it
   * until the Armijo condition holds. It stops when ||p|| / dt < eps_d, with
   * ||p|| = ||p||_inf or the measure of IncrementalPotential::
   * increment_norm() ('solver/Newton increment').
   */
  /**
   * What newton_direction() needs of an inexact Newton step: the relative
   * CG residual of the reuse path, and when to solve exactly anyway.
   */
  struct InexactSolve
  {
    /** eta_k: relative residual of CG with the last factorization. */
    double forcing = 1e-8;
    /** A direction with increment_norm(p) / dt below this is solved to
     *  1e-8 before it is returned (the stopping test's threshold). */
    double exact_below = 0.;
    double dt          = 1.;
  };



  template <int dim>
  class NewtonSolver
  {
  public:
    explicit NewtonSolver(const SolverParameters &parameters);

    /**
     * Minimizes @p potential starting from @p u, which must have every
     * det F > 0 and every contact distance > 0 with kinematic obstacles at
     * the start of their path (@p start_progress, 0 at the start of a time
     * step). Constrained DoFs move to their
     * targets and obstacles to the ends of their paths as fast as the same
     * det F and collision filter allows (move_constraints()); the Newton
     * iterations run in between, and convergence needs both there.
     * Stops at ||p|| / dt < @p stop_tolerance (the Newton tolerance eps_d
     * where 0). Throws SimulationError naming @p step_label, the residual
     * and the energy if it does not converge.
     */
    NewtonStatistics
    minimize(IncrementalPotential<dim> &potential,
             Vector<double>            &u,
             const double               dt,
             const std::string         &step_label,
             const double               start_progress = 0.,
             const double               stop_tolerance = 0.);

    const LinearSolver &
    linear_solver() const;

    /** eps_d, 'solver/Newton tolerance' [m/s]. */
    double
    tolerance() const
    {
      return parameters.newton_tolerance;
    }

  private:
    /**
     * The Newton direction p of H p = -g with the Hessian of @p kind. For
     * the exact Hessian, false if it is not positive definite (or, with a
     * solver that cannot tell, if p does not descend); the projected one
     * always gives a direction (BFEMP Algorithm 2).
     */
    bool
    newton_direction(IncrementalPotential<dim> &potential,
                     const Vector<double>      &u,
                     const Vector<double>      &minus_gradient,
                     const HessianKind          kind,
                     const InexactSolve        &inexact,
                     Vector<double>            &direction,
                     NewtonStatistics          &statistics) const;

    /** Whether the linear solver holds a factorization of a Hessian on the
     *  unknowns of @p potential as they are numbered now. */
    bool
    holds_factorization_for(const IncrementalPotential<dim> &potential) const;

    /**
     * `solver/modified Newton contraction` > 0: the direction p = -H_0^-1 g
     * with H_0 the last factorized Hessian of the same unknowns (no
     * assembly). True if it descends and its increment ||p|| / dt is at
     * most the contraction times @p last_residual (that of the previous
     * iteration, 0 for the first of a Newton solve: no test).
     */
    bool
    modified_direction(const IncrementalPotential<dim> &potential,
                       const Vector<double>            &minus_gradient,
                       const double                     dt,
                       const double                     last_residual,
                       Vector<double>                  &direction,
                       NewtonStatistics                &statistics) const;

    /**
     * The relative CG residual eta_k of `solver/forcing term` for the
     * gradient norm @p gradient_norm of the current iteration (@p first:
     * the first of a minimize() call); 1e-8 with 'none'.
     */
    double
    forcing(const double gradient_norm, const bool first) const;

    /** `solver/log iterations`: one line on stdout for the iteration just
     *  done (@p factorized: its direction came from a new factorization;
     *  @p modified: from the last one without an assembled Hessian;
     *  @p cg_iterations: those of its solves with an older one;
     *  @p kind: the Hessian its direction came from; @p model_ratio: the
     *  actual over the predicted decrease of the energy; @p rejected_exact:
     *  the length of an exact direction the growth limit set aside, or 0). */
    void
    log_iteration(const std::string      &step_label,
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
                  const std::string      &term_energies) const;

    /**
     * 'exact step growth limit': the length ||p|| / dt of an exact-Hessian
     * @p direction that exceeds the limit times @p last_move (the last
     * accepted ||t p|| / dt), else 0 (also without a limit or a last move).
     */
    double
    exact_direction_too_long(const IncrementalPotential<dim> &potential,
                             const Vector<double>            &direction,
                             const double                     dt,
                             const double                     last_move) const;

    /**
     * 'skip failed exact factorizations': whether this iteration leaves out
     * the exact Hessian's factorization (counting the skip).
     */
    bool
    skip_exact_factorization() const;

    /** Updates the back-off of skip_exact_factorization() after an
     *  attempt to factorize the exact Hessian. */
    void
    record_exact_factorization(const bool succeeded) const;

    /**
     * 'eigenvalue filter = adaptive': the projected Hessian for the next
     * iteration from the model ratio rho of the last one that used it (after
     * Chen et al., SIGGRAPH Asia 2024): absolute eigenvalues below rho = 0.25,
     * clamped ones above 0.75, the last choice between.
     */
    static HessianKind
    next_filter(const HessianKind current, const double model_ratio);

    /**
     * Moves the constrained components of @p u towards their targets and
     * the obstacles towards the ends of their paths by the largest common
     * fraction that the step bound allows (all of the way if nothing is in
     * the way). The free DoFs move along with their linear response
     * (free_response()) when that lets the move go further. Returns the new
     * obstacle progress; @p energy is updated.
     */
    double
    move_constraints(IncrementalPotential<dim> &potential,
                     Vector<double>            &u,
                     const double               progress,
                     double                    &energy,
                     NewtonStatistics          &statistics) const;

    /**
     * The free DoFs' linear response r to the constraint and obstacle
     * @p move, H_ff r = -H_fc m, with H_fc m the difference of the free
     * gradient along a small fraction of the move (@p bound: the feasible
     * fraction of the move alone).
     */
    Vector<double>
    free_response(IncrementalPotential<dim> &potential,
                  const Vector<double>      &u,
                  const Vector<double>      &move,
                  const double               progress,
                  const double               bound) const;

    /**
     * Backtracks from the bounded trial step; returns the accepted step
     * length (0 if no step decreased E enough).
     */
    double
    line_search(const IncrementalPotential<dim> &potential,
                const Vector<double>            &u,
                const Vector<double>            &p,
                const double                     energy,
                const double                     slope,
                Vector<double>                  &trial,
                double                          &trial_energy,
                const bool                       projected,
                NewtonStatistics                &statistics) const;

    /**
     * `solver/projected step extrapolation`: from the accepted full step
     * along a projected-Hessian direction @p p (at @p trial, energy
     * @p trial_energy), doubles the step while E falls and 2 t stays below
     * @p bound; returns the step taken and updates @p trial and
     * @p trial_energy.
     */
    double
    extrapolate(const IncrementalPotential<dim> &potential,
                const Vector<double>            &u,
                const Vector<double>            &p,
                const double                     bound,
                Vector<double>                  &trial,
                double                          &trial_energy) const;

    /**
     * `solver/factorization reuse` > 0: solves H p = -g by conjugate
     * gradients preconditioned with the last factorization (of an earlier
     * Hessian on the same unknowns) to the relative residual
     * @p relative_tolerance, from p = 0 or, with @p warm_start, from the
     * given @p direction; false if that takes more than the entry's
     * iterations.
     */
    bool
    solve_with_last_factorization(const SparseMatrix<double> &hessian,
                                  const Vector<double>       &minus_gradient,
                                  const double      relative_tolerance,
                                  const bool        warm_start,
                                  Vector<double>   &direction,
                                  NewtonStatistics &statistics) const;

    const SolverParameters        parameters;
    std::unique_ptr<LinearSolver> solver;
    /** Whether the solver holds a factorization, and of which numbering
     *  of the unknowns (DofSpace::numbering()). */
    mutable bool         factorization_reusable = false;
    mutable unsigned int factorized_numbering   = 0;
    /** Eisenstat-Walker's state: ||g_k-1||. */
    mutable double last_gradient_norm = 0.;
    /** 'skip failed exact factorizations': the exact-Hessian factorizations
     *  skipped after the last failed one, and those still to skip. */
    mutable unsigned int exact_skip_length = 0;
    mutable unsigned int exact_skips_left  = 0;
  };
} // namespace bfemp

#endif
