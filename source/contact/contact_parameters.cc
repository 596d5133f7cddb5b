#include <bfemp/base/input_error.h>
#include <bfemp/contact/contact_parameters.h>

#include <deal.II/base/utilities.h>

namespace bfemp
{
  double
  ContactParameters::friction_coefficient(const unsigned int mpm_body,
                                          const unsigned int fem_body) const
  {
    const auto entry = friction_coefficients.find({mpm_body, fem_body});
    return entry == friction_coefficients.end() ? default_friction_coefficient
                                                : entry->second;
  }



  bool
  ContactParameters::has_friction() const
  {
    if (default_friction_coefficient > 0.)
      return true;
    for (const auto &entry : friction_coefficients)
      if (entry.second > 0.)
        return true;
    return false;
  }



  void
  ContactParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("contact");
    prm.declare_entry("activation distance",
                      "1e-3",
                      Patterns::Double(),
                      "[m] dhat of the barrier b(d, dhat) (BFEMP eq. 27): a "
                      "particle closer than this to an FEM boundary feels "
                      "the barrier; the contact gap stays below it. > 0.");
    prm.declare_entry("barrier stiffness",
                      "1e6",
                      Patterns::Double(),
                      "[Pa] kappa of eq. 27; > 0.");
    prm.declare_entry("static friction velocity",
                      "1e-5",
                      Patterns::Double(),
                      "[m/s] eps_v of the friction mollifier (eq. 36): "
                      "relative sliding slower than this is treated as "
                      "sticking; > 0.");
    prm.declare_entry("friction coefficient",
                      "0",
                      Patterns::Double(),
                      "[-] mu of every MPM body / FEM body pair that the "
                      "table below does not list; >= 0. With mu = 0 for "
                      "every pair no friction code runs.");
    prm.declare_entry("friction coefficients",
                      "",
                      Patterns::Anything(),
                      "[-] Per body pair: 'm, f: mu; ...' with m an MPM body "
                      "index (subsection 'body m') and f an FEM body index "
                      "(subsection 'fem body f'), e.g. '0, 0: 0.2; 1, 0: "
                      "0.5'.");
    prm.declare_entry("maximum friction iterations",
                      "20",
                      Patterns::Integer(1),
                      "[-] Friction updates per time step (Algorithm 1): the "
                      "normal forces and tangent bases are lagged, the "
                      "potential minimized, and both recomputed until the "
                      "Newton tolerance holds with the updated friction. A "
                      "step that reaches this count goes on and is reported.");
    prm.declare_entry(
      "friction pass tolerance factor",
      "1",
      Patterns::Double(),
      "[-] F >= 1: the Newton solve of a step's first friction pass stops at "
      "F eps_d ('solver/Newton tolerance'), each later one at a tenth of "
      "the previous factor, never below eps_d. A pass before the last only "
      "gives the point at which friction is lagged next, so it need not be "
      "solved to eps_d; the step still ends when, with the friction "
      "updated, the first Newton increment meets eps_d. 1 solves every pass "
      "to eps_d (Algorithm 1 as written); 100 saved 8-18 % of the Newton "
      "iterations of the twist's compression (doc/experiments/twist.md).");
    prm.declare_entry(
      "friction pass mollifier factor",
      "1",
      Patterns::Double(),
      "[-] G >= 1: a step's first friction pass uses the mollifier of eq. 36 "
      "widened to G eps_v dt ('static friction velocity'), each later pass "
      "a tenth of the previous factor, never below 1. Like the pass "
      "tolerance, a widened pass only gives the point at which friction is "
      "lagged next: the step ends only when, in a pass at eps_v itself, "
      "the first Newton increment meets eps_d, so the answer is the "
      "lagged friction's fixed point of Algorithm 1. 1 uses eps_v in "
      "every pass (doc/experiments/twist.md).");
    prm.leave_subsection();
  }



  void
  ContactParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("contact");
    activation_distance          = prm.get_double("activation distance");
    barrier_stiffness            = prm.get_double("barrier stiffness");
    static_friction_velocity     = prm.get_double("static friction velocity");
    default_friction_coefficient = prm.get_double("friction coefficient");
    maximum_friction_iterations =
      prm.get_integer("maximum friction iterations");
    friction_pass_tolerance_factor =
      prm.get_double("friction pass tolerance factor");
    friction_pass_mollifier_factor =
      prm.get_double("friction pass mollifier factor");
    const std::string table = prm.get("friction coefficients");
    prm.leave_subsection();

    require_input(activation_distance > 0.,
                  "contact",
                  "activation distance",
                  to_input_string(activation_distance),
                  "must be > 0 [m]");
    require_input(barrier_stiffness > 0.,
                  "contact",
                  "barrier stiffness",
                  to_input_string(barrier_stiffness),
                  "must be > 0 [Pa]");
    require_input(static_friction_velocity > 0.,
                  "contact",
                  "static friction velocity",
                  to_input_string(static_friction_velocity),
                  "must be > 0 [m/s]");
    require_input(friction_pass_tolerance_factor >= 1.,
                  "contact",
                  "friction pass tolerance factor",
                  to_input_string(friction_pass_tolerance_factor),
                  "must be >= 1 (1: every friction pass solved to the Newton "
                  "tolerance)");
    require_input(friction_pass_mollifier_factor >= 1.,
                  "contact",
                  "friction pass mollifier factor",
                  to_input_string(friction_pass_mollifier_factor),
                  "must be >= 1 (1: every friction pass with the mollifier "
                  "of 'static friction velocity')");
    require_input(default_friction_coefficient >= 0.,
                  "contact",
                  "friction coefficient",
                  to_input_string(default_friction_coefficient),
                  "must be >= 0");

    friction_coefficients.clear();
    for (const std::string &item : Utilities::split_string_list(table, ';'))
      {
        const auto what = [&](const std::string &problem) {
          return problem + " in '" + item +
                 "'; write 'm, f: mu' with m an MPM body index, f an FEM "
                 "body index and mu >= 0, items separated by ';'";
        };
        const auto colon = item.find(':');
        require_input(colon != std::string::npos,
                      "contact",
                      "friction coefficients",
                      table,
                      what("no ':'"));
        const auto bodies =
          Utilities::split_string_list(item.substr(0, colon), ',');
        bool   valid = bodies.size() == 2;
        int    m = -1, f = -1;
        double mu = -1.;
        try
          {
            if (valid)
              {
                m  = Utilities::string_to_int(bodies[0]);
                f  = Utilities::string_to_int(bodies[1]);
                mu = Utilities::string_to_double(
                  Utilities::trim(item.substr(colon + 1)));
              }
          }
        catch (...)
          {
            valid = false;
          }
        require_input(valid && m >= 0 && f >= 0 && mu >= 0.,
                      "contact",
                      "friction coefficients",
                      table,
                      what("an unreadable entry"));
        require_input(friction_coefficients
                        .emplace(std::make_pair(static_cast<unsigned int>(m),
                                                static_cast<unsigned int>(f)),
                                 mu)
                        .second,
                      "contact",
                      "friction coefficients",
                      table,
                      what("a body pair listed twice"));
      }
  }



  void
  ContactParameters::check_bodies(const unsigned int n_mpm_bodies,
                                  const unsigned int n_fem_bodies) const
  {
    for (const auto &entry : friction_coefficients)
      require_input(entry.first.first < n_mpm_bodies &&
                      entry.first.second < n_fem_bodies,
                    "contact",
                    "friction coefficients",
                    std::to_string(entry.first.first) + ", " +
                      std::to_string(entry.first.second) + ": " +
                      to_input_string(entry.second),
                    "names a body the scene does not have (MPM bodies 0.." +
                      std::to_string(static_cast<int>(n_mpm_bodies) - 1) +
                      ", FEM bodies 0.." +
                      std::to_string(static_cast<int>(n_fem_bodies) - 1) + ")");
  }
} // namespace bfemp
