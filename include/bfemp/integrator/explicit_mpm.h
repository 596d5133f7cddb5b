#ifndef bfemp_integrator_explicit_mpm_h
#define bfemp_integrator_explicit_mpm_h

#include <bfemp/boundary/grid_boundaries.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/integrator/time_integrator.h>
#include <bfemp/integrator/time_parameters.h>
#include <bfemp/particles/particle_loads.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/transfer/particle_grid_transfer.h>

namespace bfemp
{
  /**
   * Explicit MPM (seed 001, "Explicit Time Integration: USF vs. USL").
   *
   * USL: P2G of mass, momentum and the force of the stress at F^n -> grid
   * update v~ = v + dt (f / m + g) -> boundary conditions -> G2P of velocity,
   * position, affine matrix and F^{n+1}.
   *
   * USF: P2G of mass and momentum -> boundary conditions -> F^{n+1} from the
   * grid velocity of step n -> P2G of the force of the updated stress -> grid
   * update -> boundary conditions -> G2P without another F update.
   */
  template <int dim>
  class ExplicitMPM : public TimeIntegrator<dim>
  {
  public:
    ExplicitMPM(const BackgroundGrid<dim>       &grid,
                ParticleSystem<dim>             &particles,
                const ParticleGridTransfer<dim> &transfer,
                const GridBoundaries<dim>       &boundaries,
                const Tensor<1, dim>            &gravity,
                const TimeParameters::Integrator variant,
                ParticleLoads<dim>              *loads = nullptr);

    /** Advances from step.time to step.time + step.dt. */
    void
    step(const TimeStep &step) override;

    /** The grid fields of the last step (for output). */
    const GridState<dim> &
    grid_state() const override;

  private:
    /** v_i = (m v)_i / m_i on nodes with mass. */
    void
    momentum_to_velocity();

    /** v~_i = v_i + dt (f_i / m_i + g), then the grid boundaries. */
    void
    update_grid_velocity(const double dt, const double time);

    /** f_i += sum_p w_ip f_p(t) of the bodies' surface loads. */
    void
    add_loads(const double time);

    /** u_i = dt * velocity_i, the explicit grid displacement. */
    void
    set_displacement(const std::vector<Tensor<1, dim>> &velocity,
                     const double                       dt);

    template <typename Function>
    void
    for_each_node(const Function &f);

    const BackgroundGrid<dim>       &grid;
    ParticleSystem<dim>             &particles;
    const ParticleGridTransfer<dim> &transfer;
    const GridBoundaries<dim>       &boundaries;
    const Tensor<1, dim>             gravity;
    const TimeParameters::Integrator variant;
    /** The bodies' surface loads, or nullptr. */
    ParticleLoads<dim> *loads;
    GridState<dim>      state;
  };
} // namespace bfemp

#endif
