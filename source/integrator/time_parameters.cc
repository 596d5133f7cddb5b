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
                                          "implicit Newmark"),
                      "[-] Time integrator: explicit MPM with update stress "
                      "last or first (MPM bodies only), or the implicit "
                      "incremental potential of BFEMP eqs. 21-22 with "
                      "backward Euler or midpoint Newmark (MPM and FEM "
                      "bodies; see subsection 'solver').");
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
                      "than a cell per step.");
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
                               : Integrator::implicit_newmark;
    adaptive               = prm.get("time step mode") == "CFL";
    time_step              = prm.get_double("time step");
    cfl_number             = prm.get_double("CFL number");
    maximum_time_step      = prm.get_double("maximum time step");
    maximum_cfl_number     = prm.get_double("maximum CFL number");
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
  }



  TimeParameters::ImplicitScheme
  TimeParameters::implicit_scheme() const
  {
    if (integrator == Integrator::implicit_newmark)
      return {0.5, 0.25, 0.5};
    return {1., 0.5, 1.};
  }
} // namespace bfemp
