#include <bfemp/base/input_error.h>
#include <bfemp/integrator/time_parameters.h>

namespace bfemp
{
  void
  TimeParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("time");
    prm.declare_entry("integrator",
                      "explicit USL",
                      Patterns::Selection("explicit USL|explicit USF|"
                                          "implicit backward Euler|"
                                          "implicit Newmark|"
                                          "substepped explicit"),
                      "[-] Time integrator: explicit MPM with update stress "
                      "last or first (MPM bodies only), or the implicit "
                      "incremental potential of BFEMP eqs. 21-22 with "
                      "backward Euler or midpoint Newmark (MPM and FEM "
                      "bodies; see subsection 'solver'), or explicit MPM "
                      "substeps wrapped into one macro step (seed 003; see "
                      "subsection 'substepping'), with FEM bodies taking the "
                      "macro step implicitly (backward Euler).");
    prm.declare_entry("time step mode",
                      "CFL",
                      Patterns::Selection("fixed|CFL"),
                      "[-] fixed: use 'time step'; CFL: dt = CFL number * dx "
                      "/ (c_p + max |v_p|), c_p = sqrt((lambda + 2 mu) / "
                      "rho).");
    prm.declare_entry("time step",
                      "1e-4",
                      Patterns::Double(),
                      "[s] Fixed time step (> 0).");
    prm.declare_entry("CFL number",
                      "0.3",
                      Patterns::Double(),
                      "[-] CFL number of the adaptive step, 0 < CFL <= "
                      "'maximum CFL number'.");
    prm.declare_entry("maximum time step",
                      "1e-2",
                      Patterns::Double(),
                      "[s] Upper bound of the adaptive step (> 0).");
    prm.declare_entry("maximum CFL number",
                      "1",
                      Patterns::Double(),
                      "[-] A step whose CFL number dt (c_p + max |v_p|) / dx "
                      "exceeds this stops the run: explicit MPM is unstable "
                      "there. Implicit integrators have no such limit: their "
                      "CFL number uses only the particle speed, dt max "
                      "|v_p| / dx, which keeps particles from crossing more "
                      "than a cell per step. The substepped integrator's "
                      "macro step counts as implicit here, and its substeps "
                      "as explicit.");
    prm.declare_entry(
      "Newmark contact impulse",
      "end of step",
      Patterns::Selection("end of step|trapezoidal"),
      "[-] How implicit Newmark steps integrate the contact forces "
      "(barrier and lagged friction). end of step: with the force at the "
      "step's end, as backward Euler does (impulse dt f^{n+1}); for a convex "
      "barrier the contact then never adds energy, while the elastic forces "
      "keep the trapezoidal rule. trapezoidal: the barrier enters a^n and "
      "a^{n+1} like the elastic forces (BFEMP eq. 21 as written), which "
      "conserves energy only for forces linear in x and gains energy when "
      "a contact ends within a step (doc/stability.md); lagged friction then "
      "acts with half its impulse, gamma dt f^{n+1}.");
    declare_substepping(prm);
    prm.leave_subsection();
  }



  void
  TimeParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("time");
    const std::string name = prm.get("integrator");
    integrator             = name == "explicit USL"   ? Integrator::explicit_usl
                             : name == "explicit USF" ? Integrator::explicit_usf
                             : name == "implicit backward Euler"
                               ? Integrator::implicit_backward_euler
                             : name == "implicit Newmark" ? Integrator::implicit_newmark
                                                          : Integrator::substepped_explicit;
    adaptive               = prm.get("time step mode") == "CFL";
    time_step              = prm.get_double("time step");
    cfl_number             = prm.get_double("CFL number");
    maximum_time_step      = prm.get_double("maximum time step");
    maximum_cfl_number     = prm.get_double("maximum CFL number");
    newmark_contact_at_step_end =
      prm.get("Newmark contact impulse") == "end of step";
    parse_substepping(prm);
    prm.leave_subsection();

    require_input(time_step > 0.,
                  "time",
                  "time step",
                  to_input_string(time_step),
                  "must be > 0 [s]");
    require_input(maximum_time_step > 0.,
                  "time",
                  "maximum time step",
                  to_input_string(maximum_time_step),
                  "must be > 0 [s]");
    require_input(maximum_cfl_number > 0.,
                  "time",
                  "maximum CFL number",
                  to_input_string(maximum_cfl_number),
                  "must be > 0");
    require_input(cfl_number > 0. && cfl_number <= maximum_cfl_number,
                  "time",
                  "CFL number",
                  to_input_string(cfl_number),
                  "must satisfy 0 < CFL number <= maximum CFL number (" +
                    to_input_string(maximum_cfl_number) + ")");
    check_substepping();
  }



  void
  TimeParameters::declare_substepping(ParameterHandler &prm)
  {
    prm.enter_subsection("substepping");
    prm.declare_entry("substep update",
                      "USL",
                      Patterns::Selection("USL|USF"),
                      "[-] The explicit MPM update of each substep: update "
                      "stress last or first.");
    prm.declare_entry("substeps",
                      "0",
                      Patterns::Integer(0),
                      "[-] Number S of explicit substeps per macro step; 0 "
                      "chooses the least S whose substep dt / S satisfies "
                      "'substep CFL number' at the start of the macro step. A "
                      "fixed S whose substep exceeds 'time/maximum CFL "
                      "number' stops the run.");
    prm.declare_entry("substep CFL number",
                      "0.3",
                      Patterns::Double(),
                      "[-] With substeps = 0: the CFL number (dt / S) (c_p + "
                      "max |v_p|) / dx the substeps keep, 0 < CFL <= "
                      "'time/maximum CFL number'.");
    prm.declare_entry("reconstruction",
                      "APIC",
                      Patterns::Selection("APIC|least squares"),
                      "[-] How the macro-step grid velocity is fitted to the "
                      "particles' secant velocities and velocity gradients "
                      "(seed 003 eq. 1): APIC, the closed form of eq. 5 "
                      "(lumped mass, lambda = D); least squares, the sparse "
                      "SPD system of eq. 4 with consistent mass and the "
                      "gradient term weighted by 'least squares weight'.");
    prm.declare_entry("least squares weight",
                      "1",
                      Patterns::Double(),
                      "[-] reconstruction = least squares: lambda / D of eq. "
                      "2, where D = dx^2 / 4 (quadratic kernel), dx^2 / 3 "
                      "(cubic) or dx^2 / 4 (linear); > 0.");
    prm.declare_entry("macro-step velocity",
                      "end of substeps",
                      Patterns::Selection("end of substeps|secant"),
                      "[-] The particle velocity the macro step leaves: "
                      "'end of substeps' reconstructs the particles' "
                      "end-of-substep velocities on the grid of step n as a "
                      "second field (positions and F still move with the "
                      "secant field v*); 'secant' uses v* for both, as seed "
                      "003 writes v^{n+1} = v*. The secant velocity lags the "
                      "end velocity by about dt a / 2, so 'secant' slows "
                      "accelerations by up to a factor 2 as S grows "
                      "(doc/substepping.md).");
    prm.declare_entry("macro-step transfer",
                      "as substeps",
                      Patterns::Selection("as substeps|PIC|FLIP|APIC"),
                      "[-] The grid-to-particle transfer of the macro step "
                      "(the substeps use subsection 'transfer'); FLIP takes "
                      "'transfer/FLIP PIC blend'.");
    prm.leave_subsection();
  }



  void
  TimeParameters::parse_substepping(ParameterHandler &prm)
  {
    prm.enter_subsection("substepping");
    Substepping &s = substepping;
    s.update     = prm.get("substep update") == "USF" ? Integrator::explicit_usf
                                                      : Integrator::explicit_usl;
    s.substeps   = prm.get_integer("substeps");
    s.cfl_number = prm.get_double("substep CFL number");
    s.reconstruction           = prm.get("reconstruction") == "APIC"
                                   ? Substepping::Reconstruction::apic
                                   : Substepping::Reconstruction::least_squares;
    s.least_squares_weight     = prm.get_double("least squares weight");
    s.secant_end_velocity      = prm.get("macro-step velocity") == "secant";
    const std::string transfer = prm.get("macro-step transfer");
    s.own_macro_transfer       = transfer != "as substeps";
    s.macro_transfer = transfer == "PIC"    ? TransferParameters::Scheme::pic
                       : transfer == "FLIP" ? TransferParameters::Scheme::flip
                                            : TransferParameters::Scheme::apic;
    prm.leave_subsection();
  }



  void
  TimeParameters::check_substepping() const
  {
    const Substepping &s = substepping;
    require_input(s.cfl_number > 0. && s.cfl_number <= maximum_cfl_number,
                  "time/substepping",
                  "substep CFL number",
                  to_input_string(s.cfl_number),
                  "must satisfy 0 < substep CFL number <= time/maximum CFL "
                  "number (" +
                    to_input_string(maximum_cfl_number) + ")");
    require_input(s.least_squares_weight > 0.,
                  "time/substepping",
                  "least squares weight",
                  to_input_string(s.least_squares_weight),
                  "must be > 0 (the consistent mass matrix alone can be "
                  "singular where particles are sparse)");
  }



  TimeParameters::ImplicitScheme
  TimeParameters::implicit_scheme() const
  {
    if (integrator == Integrator::implicit_newmark)
      return {0.5, 0.25, 0.5, newmark_contact_at_step_end};
    return {1., 0.5, 1., true};
  }
} // namespace bfemp
