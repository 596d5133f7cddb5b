#ifndef bfemp_integrator_time_parameters_h
#define bfemp_integrator_time_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace bfemp
{
  using namespace dealii;

  /** prm subsection "time": the integrator and its time step. */
  struct TimeParameters
  {
    enum class Integrator
    {
      explicit_usl,
      explicit_usf,
      implicit_backward_euler,
      implicit_newmark
    };

    /**
     * The (alpha, beta, gamma) of the implicit family of BFEMP eq. 21:
     * backward Euler (1, 1/2, 1) or midpoint Newmark (1/2, 1/4, 1/2).
     */
    struct ImplicitScheme
    {
      double alpha = 1.;
      double beta  = 0.5;
      double gamma = 1.;

      /** 2 alpha beta, the weight of dt^2 Psi in eq. 22. */
      double
      potential_weight() const
      {
        return 2. * alpha * beta;
      }
    };

    bool
    is_implicit() const
    {
      return integrator == Integrator::implicit_backward_euler ||
             integrator == Integrator::implicit_newmark;
    }

    /** The scheme of the chosen implicit integrator. */
    ImplicitScheme
    implicit_scheme() const;

    Integrator integrator = Integrator::explicit_usl;
    /** Fixed dt, or dt = CFL number * dx / (c_p + max |v_p|). */
    bool   adaptive           = false;
    double time_step          = 1e-4;
    double cfl_number         = 0.3;
    double maximum_time_step  = 1e-2;
    double maximum_cfl_number = 1.;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);
  };
} // namespace bfemp

#endif
