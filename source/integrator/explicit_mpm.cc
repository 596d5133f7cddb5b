#include <bfemp/integrator/explicit_mpm.h>

#include <deal.II/base/parallel.h>

namespace bfemp
{
  template <int dim>
  ExplicitMPM<dim>::ExplicitMPM(const BackgroundGrid<dim>       &grid,
                                ParticleSystem<dim>             &particles,
                                const ParticleGridTransfer<dim> &transfer,
                                const GridBoundaries<dim>       &boundaries,
                                const Tensor<1, dim>            &gravity,
                                const TimeParameters::Integrator variant,
                                ParticleLoads<dim>              *loads)
    : grid(grid)
    , particles(particles)
    , transfer(transfer)
    , boundaries(boundaries)
    , gravity(gravity)
    , variant(variant)
    , loads(loads)
  {}



  template <int dim>
  template <typename Function>
  void
  ExplicitMPM<dim>::for_each_node(const Function &f)
  {
    parallel::apply_to_subranges(
      std::size_t(0),
      state.mass.size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t node = begin; node < end; ++node)
          if (state.mass[node] > 0.)
            f(node);
      },
      4096);
  }



  template <int dim>
  void
  ExplicitMPM<dim>::momentum_to_velocity()
  {
    for_each_node([&](const std::size_t node) {
      state.velocity[node] /= state.mass[node];
    });
  }



  template <int dim>
  void
  ExplicitMPM<dim>::update_grid_velocity(const double dt, const double time)
  {
    for_each_node([&](const std::size_t node) {
      state.new_velocity[node] =
        state.velocity[node] +
        dt * (state.force[node] / state.mass[node] + gravity);
    });
    boundaries.apply(grid.lattice(), state.mass, state.new_velocity, time + dt);
  }



  template <int dim>
  void
  ExplicitMPM<dim>::add_loads(const double time)
  {
    // the force of the state at t^n, as the stresses'
    if (loads == nullptr)
      return;
    loads->set_time(time);
    loads->add_to_grid(grid, particles, state.force);
  }



  template <int dim>
  void
  ExplicitMPM<dim>::set_displacement(
    const std::vector<Tensor<1, dim>> &velocity,
    const double                       dt)
  {
    for_each_node([&](const std::size_t node) {
      state.displacement[node] = dt * velocity[node];
    });
  }



  template <int dim>
  void
  ExplicitMPM<dim>::step(const TimeStep &step)
  {
    const double dt   = step.dt;
    const double time = step.time;
    state.reinit(grid.lattice().n_nodes);
    if (variant == TimeParameters::Integrator::explicit_usl)
      {
        transfer.particles_to_grid(particles, state, true);
        add_loads(time);
        momentum_to_velocity();
        update_grid_velocity(dt, time);
        transfer.grid_to_particles(particles, state, true, dt);
      }
    else
      {
        transfer.particles_to_grid(particles, state, false);
        momentum_to_velocity();
        boundaries.apply(grid.lattice(), state.mass, state.velocity, time);
        set_displacement(state.velocity, dt);
        transfer.update_deformation_gradient(particles, state.displacement);
        transfer.stress_to_grid(particles, state);
        add_loads(time);
        update_grid_velocity(dt, time);
        transfer.grid_to_particles(particles, state, false, dt);
      }
    particles.update_cells();
  }



  template <int dim>
  const GridState<dim> &
  ExplicitMPM<dim>::grid_state() const
  {
    return state;
  }



  template class ExplicitMPM<2>;
  template class ExplicitMPM<3>;
} // namespace bfemp
