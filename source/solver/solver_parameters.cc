#include <bfemp/base/input_error.h>
#include <bfemp/solver/solver_parameters.h>

namespace bfemp
{
  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("solver");
    prm.declare_entry("Newton tolerance",
                      "1e-6",
                      Patterns::Double(),
                      "[m/s] eps_d: Newton stops when the Newton increment "
                      "divided by dt, ||p|| / dt, falls below this (BFEMP "
                      "Section 5: the largest entry of p; 'Newton "
                      "increment' chooses what p is measured on); > 0.");
    prm.declare_entry("maximum Newton iterations",
                      "100",
                      Patterns::Integer(1),
                      "[-] A time step that has not converged after this "
                      "many iterations stops the run with a message; the "
                      "output up to the last converged step stays.");
    prm.declare_entry("linear solver",
                      "CHOLMOD",
                      Patterns::Selection("CHOLMOD|UMFPACK|CG AMG"),
                      "[-] CHOLMOD: SuiteSparse supernodal Cholesky (the "
                      "symbolic analysis is reused while the sparsity "
                      "pattern is unchanged); UMFPACK: deal.II's LU; CG AMG: "
                      "Trilinos conjugate gradients with ML algebraic "
                      "multigrid, for large 3D problems.");
    prm.declare_entry(
      "Hessian projection",
      "when indefinite",
      Patterns::Selection("always|when indefinite"),
      "[-] always: every local Hessian (particle, element, contact) is "
      "projected onto the positive semi-definite cone before assembly, the "
      "projected Newton of BFEMP Section 5; where a projection acts (the "
      "rotation mode of a compressed neo-Hookean element, the curvature of "
      "a contact distance) Newton then converges only linearly. when "
      "indefinite: each iteration first factorizes the exact Hessian and "
      "falls back to the projected one where it is not positive definite "
      "(UMFPACK and CG AMG cannot tell: there the exact direction is kept "
      "if it descends), which restores quadratic convergence near a "
      "minimizer at the price of a second assembly where it falls back. "
      "The converged steps agree within the Newton tolerance.");
    prm.declare_entry(
      "eigenvalue filter",
      "clamp",
      Patterns::Selection("clamp|absolute|adaptive"),
      "[-] How the projected Hessian (every iteration with 'Hessian "
      "projection = always', the fallback otherwise) makes each local "
      "Hessian positive semi-definite. clamp: negative eigenvalues set to "
      "0, the nearest PSD matrix, as in BFEMP Section 5. absolute: negative "
      "eigenvalues replaced by their absolute values (Chen et al., "
      "'Trust-region eigenvalue filtering for projected Newton', SIGGRAPH "
      "Asia 2024), so that a direction of negative curvature (a compressed "
      "neo-Hookean particle's rotation, a contact distance to an edge) "
      "keeps a curvature of its size; near a minimizer whose exact Hessian "
      "is positive definite this overestimates the curvature, and Newton "
      "crawls. adaptive: chooses per iteration from the ratio rho of the "
      "actual to the predicted decrease of the last one, absolute below "
      "rho = 0.25 (the model was too flat), clamp above 0.75, the last "
      "choice between (after the same paper). The minimizer is the same.");
    prm.declare_entry("CG tolerance",
                      "1e-10",
                      Patterns::Double(),
                      "[-] Relative residual at which CG AMG stops, in "
                      "(0, 1).");
    prm.declare_entry("Armijo constant",
                      "1e-4",
                      Patterns::Double(),
                      "[-] c of the sufficient decrease E(x + t p) <= E(x) + "
                      "c t grad E . p, in [0, 0.5); 0 only asks for any "
                      "decrease, as Algorithm 2 of the paper does.");
    prm.declare_entry("step bound fraction",
                      "0.9",
                      Patterns::Double(),
                      "[-] The line search starts at this fraction of the "
                      "largest step that keeps every det F > 0 (and, with "
                      "contact, every distance > 0), in (0, 1).");
    prm.declare_entry("maximum backtracks",
                      "60",
                      Patterns::Integer(1),
                      "[-] Step halvings before the line search reports "
                      "failure.");
    prm.declare_entry(
      "Newton increment",
      "unknowns",
      Patterns::Selection("unknowns|material points"),
      "[-] What the stopping test ||p|| / dt < 'Newton tolerance' measures "
      "the Newton increment p on. unknowns: the largest entry of p over "
      "the FEM nodes and grid nodes, as BFEMP Section 5 writes it. "
      "material points: the largest change p gives what the step hands on "
      "to the next, FEM nodes |p_a| and, for each particle, its "
      "displacement |sum_i w_ip p_i| and h |dF_p| (h the grid's cell "
      "size). Grid nodes at the edge of a body's kernel support carry "
      "little mass and stiffness: their entries of p can be 100 times "
      "larger than any particle's move, and with 'unknowns' they decide "
      "when Newton stops.");
    prm.declare_entry(
      "factorization reuse",
      "0",
      Patterns::Integer(0),
      "[-] With CHOLMOD or UMFPACK: before factorizing a Newton iteration's "
      "Hessian, try conjugate gradients preconditioned by the last "
      "factorization (kept across time steps while the unknowns are "
      "numbered the same), to the residual that 'forcing term' sets, for "
      "at most this many iterations; factorize only if they do not reach "
      "it (or the direction does not descend). 0: factorize every "
      "iteration, as the paper does. Must be 0 with CG AMG, which has no "
      "factorization.");
    prm.declare_entry(
      "forcing term",
      "none",
      Patterns::Selection("none|Eisenstat-Walker"),
      "[-] How accurately the conjugate gradients of 'factorization reuse' "
      "solve H p = -g. none: to a residual of 1e-8 ||g||, an exact Newton "
      "step. Eisenstat-Walker: inexact Newton, to eta_k ||g_k|| with "
      "eta_k = 0.9 (||g_k|| / ||g_k-1||)^2 (Eisenstat and Walker 1996, "
      "choice 2), at most 1e-3: loose while Newton is far from the "
      "minimizer, so that an older factorization still serves, and "
      "tightening as it converges. A direction that passes the "
      "stopping test is solved again to 1e-8 ||g|| before Newton stops, so "
      "the test decides on the exact step as with none. Needs 'factorization "
      "reuse' > 0.");
    prm.declare_entry(
      "modified Newton contraction",
      "0",
      Patterns::Double(0., 1.),
      "[-] Modified Newton (the chord and Shamanskii methods, Kelley 1995, "
      "Ch. 5): with CHOLMOD or UMFPACK, an iteration first "
      "solves with the last factorization as it stands (kept across time "
      "steps while the unknowns are numbered the same), without assembling "
      "the Hessian, and keeps that direction if it descends and its "
      "increment ||p|| / dt is at most this fraction of the last "
      "iteration's (the first iteration of a Newton solve keeps it if it "
      "descends). Otherwise, and after a line search that found no "
      "decrease along it, the iteration assembles the Hessian as usual. "
      "The stopping test reads the increment of the matrix that was used. "
      "Pays where the Hessian's assembly or factorization dominates a step "
      "and the Hessian changes little between iterations and steps (cMPM's "
      "condensation). 0: every iteration assembles the Hessian, as the "
      "paper does. Must lie in [0, 1) and be 0 with CG AMG.");
    prm.declare_entry(
      "projected step extrapolation",
      "0",
      Patterns::Integer(0, 10),
      "[-] A projected Hessian is stiffer than the exact one (its negative "
      "eigenvalues raised to 0 or above), so its Newton step is too short "
      "wherever the projection acts and projected Newton crawls. When the "
      "line search accepts a full step along such a direction, it tries up "
      "to this many doublings of it while the energy keeps falling (each "
      "one energy evaluation; the CCD and det F > 0 bounds still apply). 0: "
      "the paper's line search.");
    prm.declare_entry(
      "exact step growth limit",
      "0",
      Patterns::Double(0.),
      "[-] With 'Hessian projection = when indefinite': an exact-Hessian "
      "direction longer than this many times the last iteration's accepted "
      "move (in the Newton increment's norm) is not used, and the iteration "
      "takes the projected Hessian's. Near the minimizer Newton's moves "
      "shrink; a direction that grows by much more comes from an exact "
      "Hessian whose smallest curvature is near zero along it, and the line "
      "search would cut it to a short, expensive step. 0: no limit, the "
      "paper's Algorithm 1.");
    prm.declare_entry(
      "skip failed exact factorizations",
      "false",
      Patterns::Bool(),
      "[-] With 'Hessian projection = when indefinite': after the exact "
      "Hessian's factorization has found it indefinite, the next 1, then 2, "
      "4, ... iterations of the Newton solve do not attempt to factorize it "
      "(they still try it through CG with the last factorization, with "
      "'factorization reuse') and factorize the projected one directly, "
      "until an attempt succeeds. A failed attempt costs up to a whole "
      "factorization, and the exact Hessian of a contact or compressed scene "
      "often stays indefinite over runs of iterations. false: every "
      "iteration attempts it (the paper's Algorithm 1).");
    prm.declare_entry("log iterations",
                      "false",
                      Patterns::Bool(),
                      "[-] Print one line per Newton iteration (also with "
                      "'run/quiet'): ||p|| / dt against the pass's stopping "
                      "tolerance, the accepted step length, the line search's "
                      "backtracks, E, ||g||, the forcing term and whether the "
                      "direction came from a new factorization or from CG "
                      "with an older one, and whether the iteration fell "
                      "back to the projected Hessian, then the value of every "
                      "energy term (the elastic one is the strain energy). "
                      "For finding out where "
                      "a scene's Newton iterations go; "
                      "benchmarks/newton_log_summary.py sums such a log per "
                      "step and friction pass.");
    prm.declare_entry("check invariants",
                      "false",
                      Patterns::Bool(),
                      "[-] Verify det F > 0 for every element and particle "
                      "at every accepted iterate and stop if not (slow; for "
                      "tests).");
    prm.leave_subsection();
  }



  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("solver");
    newton_tolerance          = prm.get_double("Newton tolerance");
    maximum_newton_iterations = prm.get_integer("maximum Newton iterations");
    linear_solver             = prm.get("linear solver");
    hessian_projection        = prm.get("Hessian projection");
    eigenvalue_filter         = prm.get("eigenvalue filter");
    cg_tolerance              = prm.get_double("CG tolerance");
    armijo_constant           = prm.get_double("Armijo constant");
    step_bound_fraction       = prm.get_double("step bound fraction");
    maximum_backtracks        = prm.get_integer("maximum backtracks");
    check_invariants          = prm.get_bool("check invariants");
    log_iterations            = prm.get_bool("log iterations");
    projected_step_extrapolation =
      prm.get_integer("projected step extrapolation");
    exact_step_growth_limit = prm.get_double("exact step growth limit");
    skip_failed_exact_factorizations =
      prm.get_bool("skip failed exact factorizations");
    newton_increment            = prm.get("Newton increment");
    factorization_reuse         = prm.get_integer("factorization reuse");
    forcing_term                = prm.get("forcing term");
    modified_newton_contraction = prm.get_double("modified Newton contraction");
    prm.leave_subsection();

    require_input(newton_tolerance > 0.,
                  "solver",
                  "Newton tolerance",
                  to_input_string(newton_tolerance),
                  "must be > 0 [m/s]");
    require_input(cg_tolerance > 0. && cg_tolerance < 1.,
                  "solver",
                  "CG tolerance",
                  to_input_string(cg_tolerance),
                  "must lie in (0, 1)");
    require_input(factorization_reuse == 0 || linear_solver != "CG AMG",
                  "solver",
                  "factorization reuse",
                  std::to_string(factorization_reuse),
                  "must be 0 with 'linear solver' = CG AMG (it has no "
                  "factorization to reuse)");
    require_input(modified_newton_contraction < 1.,
                  "solver",
                  "modified Newton contraction",
                  to_input_string(modified_newton_contraction),
                  "must lie in [0, 1): a direction whose increment does not "
                  "shrink would be kept forever");
    require_input(modified_newton_contraction == 0. ||
                    linear_solver != "CG AMG",
                  "solver",
                  "modified Newton contraction",
                  to_input_string(modified_newton_contraction),
                  "must be 0 with 'linear solver' = CG AMG (it has no "
                  "factorization to reuse)");
    require_input(forcing_term == "none" || factorization_reuse > 0,
                  "solver",
                  "forcing term",
                  forcing_term,
                  "must be none with 'factorization reuse' = 0 (the forcing "
                  "term sets the accuracy of the conjugate gradients that "
                  "reuse a factorization; a factorization solves exactly)");
    require_input(armijo_constant >= 0. && armijo_constant < 0.5,
                  "solver",
                  "Armijo constant",
                  to_input_string(armijo_constant),
                  "must lie in [0, 0.5)");
    require_input(step_bound_fraction > 0. && step_bound_fraction < 1.,
                  "solver",
                  "step bound fraction",
                  to_input_string(step_bound_fraction),
                  "must lie in (0, 1): a step of the full bound would make "
                  "some det F exactly 0");
  }
} // namespace bfemp
