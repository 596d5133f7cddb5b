#include <bfemp/integrator/substepped_mpm.h>

namespace bfemp
{
  template <int dim>
  SubsteppedMPM<dim>::SubsteppedMPM(
    const BackgroundGrid<dim>         &grid,
    ParticleSystem<dim>               &particles,
    const ParticleGridTransfer<dim>   &substep_transfer,
    const ParticleGridTransfer<dim>   &macro_transfer,
    const GridBoundaries<dim>         &boundaries,
    const Tensor<1, dim>              &gravity,
    const TimeParameters::Substepping &parameters,
    ParticleLoads<dim>                *loads)
    : grid(grid)
    , particles(particles)
    , substep_transfer(substep_transfer)
    , macro_transfer(macro_transfer)
    , boundaries(boundaries)
    , substep_integrator(grid,
                         particles,
                         substep_transfer,
                         boundaries,
                         gravity,
                         parameters.update,
                         loads)
    , reconstruction(grid, parameters)
    , secant_end_velocity(parameters.secant_end_velocity)
    , affine_substeps(substep_transfer.parameters().scheme ==
                      TransferParameters::Scheme::apic)
  {}



  template <int dim>
  void
  SubsteppedMPM<dim>::save_start_state()
  {
    using Layout        = ParticleLayout<dim>;
    const std::size_t n = particles.n_particles();
    start_position.resize(n);
    start_velocity.resize(n);
    start_affine_velocity.resize(n);
    start_deformation_gradient.resize(n);
    targets.resize(n);
    end_targets.resize(n);
    particles.for_each([&](auto &particle) {
      const auto                    id = particle.get_id();
      const ArrayView<const double> p  = particle.get_properties();
      start_position[id]               = particle.get_location();
      start_velocity[id] = Layout::get_vector(p, Layout::velocity);
      start_affine_velocity[id] =
        Layout::get_tensor(p, Layout::affine_velocity);
      start_deformation_gradient[id] =
        Layout::get_tensor(p, Layout::deformation_gradient);
    });
  }



  template <int dim>
  void
  SubsteppedMPM<dim>::secant_targets_and_restore(const double dt)
  {
    using Layout                  = ParticleLayout<dim>;
    const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();
    particles.for_each([&](auto &particle) {
      const auto              id      = particle.get_id();
      const ArrayView<double> p       = particle.get_properties();
      const Tensor<2, dim>    F_start = start_deformation_gradient[id];
      // Eq. 1.
      targets[id].velocity =
        (particle.get_location() - start_position[id]) / dt;
      targets[id].velocity_gradient =
        (Layout::get_tensor(p, Layout::deformation_gradient) * invert(F_start) -
         identity) /
        dt;
      end_targets[id].velocity = Layout::get_vector(p, Layout::velocity);
      end_targets[id].velocity_gradient =
        affine_substeps ? Layout::get_tensor(p, Layout::affine_velocity)
                        : targets[id].velocity_gradient;
      particle.set_location(start_position[id]);
      Layout::set_vector(p, Layout::velocity, start_velocity[id]);
      Layout::set_tensor(p, Layout::affine_velocity, start_affine_velocity[id]);
      Layout::set_tensor(p, Layout::deformation_gradient, F_start);
    });
    particles.update_cells();
  }



  template <int dim>
  void
  SubsteppedMPM<dim>::substep_and_reconstruct(const double       dt,
                                              const double       time,
                                              const unsigned int substeps,
                                              GridState<dim>    &macro_grid)
  {
    save_start_state();
    const double substep = dt / substeps;
    for (unsigned int s = 0; s < substeps; ++s)
      substep_integrator.step({substep, time + s * substep});
    secant_targets_and_restore(dt);

    std::vector<Tensor<1, dim>> &secant = macro_grid.displacement;
    reconstruction.reconstruct(particles, targets, macro_grid.mass, secant);
    boundaries.apply(grid.lattice(), macro_grid.mass, secant, time + dt);
    if (secant_end_velocity)
      macro_grid.new_velocity = secant;
    else
      {
        reconstruction.reconstruct(particles,
                                   end_targets,
                                   macro_grid.mass,
                                   macro_grid.new_velocity);
        boundaries.apply(grid.lattice(),
                         macro_grid.mass,
                         macro_grid.new_velocity,
                         time + dt);
      }
    for (Tensor<1, dim> &u : secant)
      u *= dt;
  }



  template <int dim>
  void
  SubsteppedMPM<dim>::step(const TimeStep &step)
  {
    Assert(step.substeps > 0, ExcMessage("a macro step needs substeps"));
    // The grid of step n: its masses weight the reconstruction, its
    // velocities v_k^n are FLIP's old grid velocity in the macro G2P.
    state.reinit(grid.lattice().n_nodes);
    macro_transfer.particles_to_grid(particles, state, false);
    for (std::size_t k = 0; k < state.mass.size(); ++k)
      if (state.mass[k] > 0.)
        state.velocity[k] /= state.mass[k];
    substep_and_reconstruct(step.dt, step.time, step.substeps, state);
    macro_transfer.grid_to_particles(particles, state, true);
    particles.update_cells();
  }



  template <int dim>
  double
  SubsteppedMPM<dim>::constant_force_ratio(const unsigned int substeps) const
  {
    // Under a constant acceleration a the substeps move by
    // delta t^2 a (1 + 2 + ... + S) = dt^2 a (S + 1) / (2 S) and change the
    // velocity by dt a.
    return secant_end_velocity ? 1. : (substeps + 1.) / (2. * substeps);
  }



  template <int dim>
  const GridState<dim> &
  SubsteppedMPM<dim>::grid_state() const
  {
    return state;
  }



  template class SubsteppedMPM<2>;
  template class SubsteppedMPM<3>;
} // namespace bfemp
