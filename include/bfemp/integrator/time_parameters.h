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
      explicit_usf
    };

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
