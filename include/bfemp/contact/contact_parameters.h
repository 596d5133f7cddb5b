#ifndef bfemp_contact_contact_parameters_h
#define bfemp_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>
#include <utility>

namespace bfemp
{
  using namespace dealii;

  /**
   * prm subsection "contact": the barrier particle-mesh contact between MPM
   * bodies and FEM bodies (BFEMP Section 4) and its lagged friction. Used by
   * implicit scenes that hold both kinds of bodies.
   */
  struct ContactParameters
  {
    /** dhat of eq. 27 [m]: the barrier is active below this distance. */
    double activation_distance = 1e-3;
    /** kappa of eq. 27 [Pa]. */
    double barrier_stiffness = 1e6;
    /** eps_v of eq. 36 [m/s]: slower sliding counts as static. */
    double static_friction_velocity = 1e-5;
    /** mu of the MPM/FEM body pairs not in the table. */
    double default_friction_coefficient = 0.;
    /** (MPM body, FEM body) -> mu. */
    std::map<std::pair<unsigned int, unsigned int>, double>
      friction_coefficients;
    /** Friction updates of Algorithm 1 before the step goes on unconverged. */
    unsigned int maximum_friction_iterations = 20;
    /** Factor on eps_d at which the first friction pass of a step stops;
     *  each later pass stops at a tenth of the previous factor, never below
     *  eps_d. 1 (the default) solves every pass to eps_d. */
    double friction_pass_tolerance_factor = 1.;
    /** G >= 1: a step's first friction pass lags and minimizes with the
     *  mollifier widened to G eps_v dt, each later pass with a tenth of
     *  the previous factor, never below 1; the step ends only in a pass
     *  at eps_v itself. 1 (the default) is eq. 36 in every pass. */
    double friction_pass_mollifier_factor = 1.;

    /** mu between MPM body @p mpm_body and FEM body @p fem_body. */
    double
    friction_coefficient(const unsigned int mpm_body,
                         const unsigned int fem_body) const;

    /** True if some body pair has mu > 0: otherwise no friction code runs. */
    bool
    has_friction() const;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Refuses table entries naming bodies the scene does not have. */
    void
    check_bodies(const unsigned int n_mpm_bodies,
                 const unsigned int n_fem_bodies) const;
  };
} // namespace bfemp

#endif
