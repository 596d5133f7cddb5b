#include <bfemp/integrator/implicit_integrator.h>

#include <algorithm>
#include <string>

namespace bfemp
{
  template <int dim>
  ImplicitIntegrator<dim>::ImplicitIntegrator(
    const BackgroundGrid<dim>                         &grid,
    ParticleSystem<dim>                               &particles,
    const ParticleGridTransfer<dim>                   &transfer,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    std::vector<std::unique_ptr<FemBody<dim>>>        &fem_bodies,
    const GridBoundaries<dim>                         &boundaries,
    const Tensor<1, dim>                              &gravity,
    const TimeParameters::ImplicitScheme              &scheme,
    const SolverParameters                            &solver)
    : grid(grid)
    , particles(particles)
    , transfer(transfer)
    , fem_bodies(fem_bodies)
    , boundaries(boundaries)
    , gravity(gravity)
    , scheme(scheme)
    , with_mpm(particles.n_particles() > 0)
    , fem_elasticity(fem_bodies, dofs)
    , mpm_elasticity(grid, particles, materials, dofs)
    , potential(dofs)
    , newton(solver)
  {
    // A scene switches on only the terms it has.
    std::vector<const EnergyTerm<dim> *> terms = {&inertia};
    if (!fem_bodies.empty())
      terms.push_back(&fem_elasticity);
    if (with_mpm)
      terms.push_back(&mpm_elasticity);
    potential.set_terms(terms);
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::particles_to_grid()
  {
    state.reinit(grid.lattice().n_nodes);
    transfer.particles_to_grid(particles, state, false);
    // A particle at the very edge of a node's kernel support gives it a
    // mass like 1e-40 kg. As an unknown such a node has a Hessian of that
    // size, its Newton increment is round-off, and ||p||_inf never falls
    // below the tolerance. Its kernel weight and gradient are negligible,
    // so it is left out of the step, as a node without mass.
    const double max_mass =
      *std::max_element(state.mass.begin(), state.mass.end());
    const double negligible_mass = 1e-12 * max_mass;
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      if (state.mass[i] > negligible_mass)
        state.velocity[i] /= state.mass[i];
      else
        {
          state.mass[i]     = 0.;
          state.velocity[i] = 0.;
        }
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::number_unknowns()
  {
    std::vector<unsigned int> fem_nodes;
    for (const auto &body : fem_bodies)
      fem_nodes.push_back(body->n_nodes());
    dofs.reinit(fem_nodes, with_mpm ? state.mass : std::vector<double>());

    node_mass.resize(dofs.n_nodes());
    start_velocity.reinit(dofs.n_dofs());
    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      for (unsigned int a = 0; a < fem_bodies[b]->n_nodes(); ++a)
        {
          const unsigned int node = dofs.fem_node(b, a);
          node_mass[node]         = fem_bodies[b]->masses()[a];
          DofSpace<dim>::set(start_velocity,
                             node,
                             fem_bodies[b]->velocities()[a]);
        }
    for (unsigned int node = dofs.n_fem_nodes(); node < dofs.n_nodes(); ++node)
      {
        const std::size_t i = dofs.lattice_node(node);
        node_mass[node]     = state.mass[i];
        DofSpace<dim>::set(start_velocity, node, state.velocity[i]);
      }
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::constrain(const double dt, const double end_time)
  {
    constraint_velocity.clear();
    auto add = [&](const unsigned int    node,
                   const Tensor<2, dim> &free_projector,
                   const Tensor<1, dim> &target,
                   const Tensor<1, dim> &velocity) {
      const bool new_constraint =
        dofs.constraint_index(node) == DofSpace<dim>::invalid;
      dofs.constrain(node, free_projector, target);
      if (new_constraint)
        constraint_velocity.push_back(velocity);
      else
        {
          // Same composition rule as DofSpace::constrain for the velocity.
          Tensor<1, dim> &v = constraint_velocity[dofs.constraint_index(node)];
          v += (unit_symmetric_tensor<dim>() - free_projector) * (velocity - v);
        }
    };

    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      {
        const FemBody<dim> &body = *fem_bodies[b];
        for (const unsigned int a : body.prescribed_nodes())
          {
            const Point<dim> &X = body.mesh().rest_position(a);
            add(dofs.fem_node(b, a),
                Tensor<2, dim>(),
                body.motion().position(X, end_time) - body.positions()[a],
                body.motion().velocity(X, end_time));
          }
      }
    // Grid walls and level sets hold FEM nodes inside them as they hold
    // grid nodes (prescribed nodes already are fully fixed).
    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      for (const auto &c :
           boundaries.implicit_constraints(grid.lattice(),
                                           fem_bodies[b]->positions(),
                                           fem_bodies[b]->velocities(),
                                           end_time))
        {
          const unsigned int node  = dofs.fem_node(b, c.node);
          const unsigned int index = dofs.constraint_index(node);
          if (index != DofSpace<dim>::invalid &&
              dofs.constraints()[index].free_projector.norm_square() == 0.)
            continue;
          add(node,
              c.free_projector,
              dt * c.obstacle_velocity,
              c.obstacle_velocity);
        }
    if (with_mpm)
      for (const auto &c : boundaries.implicit_constraints(grid.lattice(),
                                                           state.mass,
                                                           state.velocity,
                                                           end_time))
        add(dofs.grid_node(c.node),
            c.free_projector,
            dt * c.obstacle_velocity,
            c.obstacle_velocity);
  }



  template <int dim>
  Vector<double>
  ImplicitIntegrator<dim>::start_acceleration() const
  {
    Vector<double> acceleration(dofs.n_dofs());
    if (scheme.alpha * (1. - 2. * scheme.beta) == 0. && scheme.gamma == 1.)
      return acceleration; // backward Euler never uses a^n
    const Vector<double> at_start(dofs.n_dofs());
    Vector<double>       elastic_gradient(dofs.n_dofs());
    if (!fem_bodies.empty())
      fem_elasticity.add_gradient(at_start, elastic_gradient);
    if (with_mpm)
      mpm_elasticity.add_gradient(at_start, elastic_gradient);
    for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
      DofSpace<dim>::set(acceleration,
                         node,
                         gravity - DofSpace<dim>::get(elastic_gradient, node) /
                                     (scale * node_mass[node]));
    return acceleration;
  }



  template <int dim>
  Vector<double>
  ImplicitIntegrator<dim>::predictor(const Vector<double> &acceleration,
                                     const double          dt) const
  {
    Vector<double> predicted(dofs.n_dofs());
    const double   a_weight = scheme.alpha * (1. - 2. * scheme.beta) * dt * dt;
    for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
      DofSpace<dim>::set(predicted,
                         node,
                         dt * DofSpace<dim>::get(start_velocity, node) +
                           a_weight * DofSpace<dim>::get(acceleration, node) +
                           scale * gravity);
    return predicted;
  }



  template <int dim>
  Vector<double>
  ImplicitIntegrator<dim>::end_velocity(const Vector<double> &u,
                                        const Vector<double> &predicted,
                                        const Vector<double> &acceleration,
                                        const double          dt) const
  {
    Vector<double> velocity(dofs.n_dofs());
    for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
      {
        const Tensor<1, dim> end_acceleration =
          (DofSpace<dim>::get(u, node) - DofSpace<dim>::get(predicted, node)) /
            scale +
          gravity;
        DofSpace<dim>::set(velocity,
                           node,
                           DofSpace<dim>::get(start_velocity, node) +
                             dt * ((1. - scheme.gamma) *
                                     DofSpace<dim>::get(acceleration, node) +
                                   scheme.gamma * end_acceleration));
      }
    const auto &constraints = dofs.constraints();
    for (unsigned int c = 0; c < constraints.size(); ++c)
      {
        const auto          &P = constraints[c].free_projector;
        const Tensor<1, dim> v =
          DofSpace<dim>::get(velocity, constraints[c].node);
        DofSpace<dim>::set(velocity,
                           constraints[c].node,
                           P * v + constraint_velocity[c] -
                             P * constraint_velocity[c]);
      }
    return velocity;
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::update_fem_bodies(const Vector<double> &u,
                                             const Vector<double> &velocity)
  {
    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      for (unsigned int a = 0; a < fem_bodies[b]->n_nodes(); ++a)
        {
          const unsigned int node = dofs.fem_node(b, a);
          fem_bodies[b]->positions()[a] += DofSpace<dim>::get(u, node);
          fem_bodies[b]->velocities()[a] = DofSpace<dim>::get(velocity, node);
        }
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::grid_to_particles(const Vector<double> &u,
                                             const Vector<double> &velocity)
  {
    for (unsigned int node = dofs.n_fem_nodes(); node < dofs.n_nodes(); ++node)
      {
        const std::size_t i   = dofs.lattice_node(node);
        state.displacement[i] = DofSpace<dim>::get(u, node);
        state.new_velocity[i] = DofSpace<dim>::get(velocity, node);
      }
    transfer.grid_to_particles(particles, state, true);
    particles.update_cells();
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::step(const double       dt,
                                const double       time,
                                const unsigned int step_number)
  {
    scale = scheme.potential_weight() * dt * dt;
    mpm_elasticity.set_scale(scale);
    fem_elasticity.set_scale(scale);

    if (with_mpm)
      particles_to_grid();
    number_unknowns();
    constrain(dt, time + dt);
    const Vector<double> acceleration = start_acceleration();
    const Vector<double> predicted    = predictor(acceleration, dt);
    inertia.reinit(node_mass, predicted);
    potential.setup_system();

    // Algorithm 1 line 3: start from x^n, moved onto the constraints.
    Vector<double> u(dofs.n_dofs());
    dofs.impose(u);
    last_statistics = newton.minimize(potential,
                                      u,
                                      dt,
                                      "step " + std::to_string(step_number) +
                                        ", t = " + std::to_string(time + dt));

    const Vector<double> velocity =
      end_velocity(u, predicted, acceleration, dt);
    update_fem_bodies(u, velocity);
    if (with_mpm)
      grid_to_particles(u, velocity);
  }



  template <int dim>
  const GridState<dim> &
  ImplicitIntegrator<dim>::grid_state() const
  {
    return state;
  }



  template <int dim>
  const NewtonStatistics &
  ImplicitIntegrator<dim>::statistics() const
  {
    return last_statistics;
  }



  template <int dim>
  unsigned int
  ImplicitIntegrator<dim>::n_dofs() const
  {
    return dofs.n_dofs();
  }



  template class ImplicitIntegrator<2>;
  template class ImplicitIntegrator<3>;
} // namespace bfemp
