#ifndef bfemp_integrator_time_integrator_h
#define bfemp_integrator_time_integrator_h

#include <bfemp/contact/contact_statistics.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/solver/newton_solver.h>

namespace bfemp
{
  /** One step to take: from @p time to time + dt. */
  struct TimeStep
  {
    double dt   = 0.;
    double time = 0.;
    /** The number of the step being taken (1 for the first), for messages. */
    unsigned int number = 0;
    /** Explicit substeps S of a substepped macro step (0 otherwise). */
    unsigned int substeps = 0;
  };



  /**
   * What Simulation needs from a time integrator: take a step, and report
   * the grid fields and the solver and contact state of the last one.
   * ExplicitMPM, SubsteppedMPM and ImplicitIntegrator implement it;
   * Simulation::create_integrator() is the one place that maps
   * 'time/integrator' (and the scene) to a class, so a new integrator is a
   * class and one case there, and Simulation's time loop stays the same.
   *
   * The queries an explicit integrator has no answer to have defaults that
   * say so (no Newton solve, no unknowns, no contact).
   */
  template <int dim>
  class TimeIntegrator
  {
  public:
    virtual ~TimeIntegrator() = default;

    /** Advances the particles (and FEM bodies) by one step; throws
     *  SimulationError when the step cannot be taken. */
    virtual void
    step(const TimeStep &step) = 0;

    /** The grid fields of the last step (for output). */
    virtual const GridState<dim> &
    grid_state() const = 0;

    /** Newton statistics of the last step; nullptr if the integrator
     *  solves no nonlinear system. */
    virtual const NewtonStatistics *
    newton_statistics() const
    {
      return nullptr;
    }

    /** Unknowns of the last step's global system (0: none). */
    virtual unsigned int
    n_dofs() const
    {
      return 0;
    }

    /** Contact state at the end of the last step; nullptr without
     *  particle-FEM contact. */
    virtual const ContactStatistics<dim> *
    contact_statistics() const
    {
      return nullptr;
    }

    /** Continues the friction dissipation of a checkpointed run. */
    virtual void
    resume_friction_dissipation(const double /*accumulated*/)
    {}
  };
} // namespace bfemp

#endif
