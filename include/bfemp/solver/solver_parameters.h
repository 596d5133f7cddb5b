#ifndef bfemp_solver_solver_parameters_h
#define bfemp_solver_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace bfemp
{
  using namespace dealii;

  /**
   * prm subsection "solver": the projected Newton minimization of the
   * incremental potential (BFEMP Section 5, Algorithm 2) and its linear
   * solver. Read by the implicit integrators only.
   */
  struct SolverParameters
  {
    /** eps_d: Newton stops when ||p||_inf / dt < eps_d [m/s]. */
    double newton_tolerance = 1e-6;
    /** A step that needs more iterations stops the run. */
    unsigned int maximum_newton_iterations = 100;
    /** "CHOLMOD", "UMFPACK" or "CG AMG". */
    std::string linear_solver = "CHOLMOD";
    /**
     * "always": every local Hessian projected onto the PSD cone (projected
     * Newton as in the paper); "when indefinite": the exact Hessian where it
     * is positive definite, the projected one otherwise.
     */
    std::string hessian_projection = "when indefinite";
    /**
     * What the projected Hessian does with negative local eigenvalues:
     * "clamp" (set to 0, the paper's), "absolute" (|lambda|) or
     * "adaptive" (NewtonSolver::next_filter()).
     */
    std::string eigenvalue_filter = "clamp";
    /** Relative residual of CG with AMG. */
    double cg_tolerance = 1e-10;
    /** Sufficient-decrease constant c of E(x + tp) <= E(x) + c t g.p. */
    double armijo_constant = 1e-4;
    /** The first trial step is this fraction of the det F > 0 bound. */
    double step_bound_fraction = 0.9;
    /** Halvings of the step before the line search gives up. */
    unsigned int maximum_backtracks = 60;
    /** Assert det F > 0 at every accepted iterate (tests). */
    bool check_invariants = false;
    /** `solver/log iterations`: one line per Newton iteration. */
    bool log_iterations = false;
    /**
     * Doublings of a full step along a projected-Hessian direction tried
     * while E keeps falling (0: none).
     */
    unsigned int projected_step_extrapolation = 0;
    /**
     * An exact direction longer than this times the last accepted move is
     * replaced by the projected one (0: never).
     */
    double exact_step_growth_limit = 0.;
    /**
     * After a failed factorization of the exact Hessian, skip the next 1,
     * 2, 4, ... attempts until one succeeds (within a Newton solve).
     */
    bool skip_failed_exact_factorizations = false;
    /** `solver/Newton increment`: "unknowns" (||p||_inf, the paper) or
     *  "material points" (FEM nodes and particles' u_p and h dF_p). */
    std::string newton_increment = "unknowns";
    /** `solver/factorization reuse`: CG iterations preconditioned by the
     *  last factorization before a new one; 0: factorize every iteration. */
    unsigned int factorization_reuse = 0;
    /** `solver/forcing term`: "none" (CG with the last factorization to
     *  1e-8 ||g||) or "Eisenstat-Walker" (inexact Newton, to eta_k ||g||). */
    std::string forcing_term = "none";
    /** `solver/modified Newton contraction`: keep a direction solved with
     *  the last factorization, without assembling the Hessian, while its
     *  increment shrinks by at least this factor per iteration; 0: off. */
    double modified_newton_contraction = 0.;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace bfemp

#endif
