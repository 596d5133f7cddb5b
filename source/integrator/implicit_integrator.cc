#include <bfemp/integrator/implicit_integrator.h>

#include <algorithm>
#include <string>

namespace bfemp
{
  namespace
  {
    /** MpmElasticityTerm::begin_step() for a scope (the Newton solve of a
     *  step), end_step() when it ends, also by an exception. */
    template <int dim>
    class StencilsOfStep
    {
    public:
      explicit StencilsOfStep(MpmElasticityTerm<dim> *term)
        : term(term)
      {
        if (term != nullptr)
          term->begin_step();
      }

      ~StencilsOfStep()
      {
        if (term != nullptr)
          term->end_step();
      }

      StencilsOfStep(const StencilsOfStep &) = delete;
      StencilsOfStep &
      operator=(const StencilsOfStep &) = delete;

    private:
      MpmElasticityTerm<dim> *term;
    };
  } // namespace



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
    const SolverParameters                            &solver,
    const ContactParameters                           &contact,
    std::unique_ptr<SubsteppedMPM<dim>>                substepped,
    CmpmDiscretization<dim>                           *cmpm,
    ParticleLoads<dim>                                *loads)
    : grid(grid)
    , particles(particles)
    , transfer(transfer)
    , materials(materials)
    , fem_bodies(fem_bodies)
    , boundaries(boundaries)
    , gravity(gravity)
    , scheme(scheme)
    , with_mpm(particles.n_particles() > 0)
    , owned_substepped_mpm(std::move(substepped))
    , substepped_mpm(owned_substepped_mpm.get())
    , cmpm(cmpm)
    , contact_parameters(contact)
    , with_contact(with_mpm && !fem_bodies.empty())
    , with_friction(with_contact && contact.has_friction())
    , fem_elasticity(fem_bodies, dofs)
    , mpm_elasticity(grid, particles, materials, dofs, cmpm)
    , mpm_correction_elasticity(mpm_elasticity)
    , potential(dofs)
    , newton(solver)
  {
    // A scene switches on only the terms it has; each is registered once
    // with what the step does with it.
    register_term(inertia, {}, false);
    if (cmpm)
      {
        cmpm_inertia =
          std::make_unique<CmpmInertiaTerm<dim>>(particles, *cmpm, dofs);
        register_term(*cmpm_inertia, {}, false);
        const double r =
          cmpm->coarse_grid().parameters().weak_node_regularization;
        if (r > 0.)
          {
            cmpm_regularization =
              std::make_unique<CmpmRegularizationTerm<dim>>(particles,
                                                            *cmpm,
                                                            dofs,
                                                            r);
            register_term(*cmpm_regularization, {}, false);
          }
      }
    if (std::any_of(fem_bodies.begin(), fem_bodies.end(), [](const auto &b) {
          return !b->is_kinematic();
        }))
      register_term(
        fem_elasticity,
        [this](const double s, const double) { fem_elasticity.set_scale(s); },
        true);
    // substepped MPM: the elasticity relative to the substeps' prediction,
    // whose force the substeps already applied (no a^n share)
    const auto set_mpm_scale = [this](const double s, const double) {
      mpm_elasticity.set_scale(s);
    };
    if (with_mpm && substepped_mpm)
      register_term(mpm_correction_elasticity, set_mpm_scale, false);
    else if (with_mpm)
      register_term(mpm_elasticity, set_mpm_scale, true);
    // substepped MPM bodies: the substeps apply the loads (as gravity)
    if (with_mpm && !substepped_mpm && loads != nullptr && !loads->empty())
      {
        particle_loads = std::make_unique<ParticleLoadTerm<dim>>(grid,
                                                                 particles,
                                                                 *loads,
                                                                 dofs,
                                                                 cmpm);
        register_term(
          *particle_loads,
          [this](const double s, const double) {
            particle_loads->set_scale(s);
          },
          true);
      }
    if (with_contact)
      {
        contact_geometry = std::make_unique<ContactGeometry<dim>>(grid,
                                                                  particles,
                                                                  fem_bodies,
                                                                  dofs,
                                                                  cmpm);
        barrier          = std::make_unique<BarrierTerm<dim>>(*contact_geometry,
                                                     contact_parameters);
        // The barrier is a force of the state x^n, but with the contact
        // impulse at the step's end it stays out of a^n like friction.
        register_term(
          *barrier,
          [this](const double s, const double) {
            barrier->set_scale(s * contact_factor());
          },
          !scheme.contact_at_step_end);
      }
    if (with_friction)
      {
        // Lagged friction (BFEMP Section 5) is a force of the lagged
        // state, not of x^n: it stays out of a^n, as in the paper.
        friction =
          std::make_unique<FrictionTerm<dim>>(*barrier, contact_parameters);
        register_term(
          *friction,
          [this](const double s, const double dt) {
            friction->set_scale(s * contact_factor(), dt);
          },
          false);
      }
    std::vector<const EnergyTerm<dim> *> terms;
    for (const RegisteredTerm &registered : registered_terms)
      terms.push_back(registered.term);
    potential.set_terms(terms);
    if (solver.newton_increment == "material points")
      potential.set_increment_measure(
        [this](const Vector<double> &p) { return material_increment(p); });
    last_contact.active = with_contact;
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::register_term(
    const EnergyTerm<dim>                       &term,
    std::function<void(double scale, double dt)> set_time_step,
    const bool                                   force_at_start)
  {
    registered_terms.push_back(
      {&term, std::move(set_time_step), force_at_start});
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::particles_to_grid(
    const std::vector<Tensor<1, dim>> *coarse_displacement)
  {
    if (cmpm)
      {
        // seed 002 Fig. 17: the shape functions of this step's particle
        // distribution, then P2G through them
        cmpm->reinit(particles, materials, coarse_displacement);
        cmpm->particles_to_grid(particles, state);
      }
    else
      {
        state.reinit(grid.lattice().n_nodes);
        transfer.particles_to_grid(particles, state, false);
      }
    // A particle at the very edge of a node's kernel support gives it a
    // mass like 1e-40 kg. As an unknown such a node has a Hessian of that
    // size, its Newton increment is round-off, and ||p||_inf never falls
    // below the tolerance. Its kernel weight and gradient are negligible,
    // so it is left out of the step, as a node without mass.
    const double max_mass =
      *std::max_element(state.mass.begin(), state.mass.end());
    // cMPM's marks are sums of m_p |Phi_Ip|, and its mass matrix holds
    // |Phi_Ip|^2: a node below 1e-8 of the largest has a mass below round-off
    // and makes the consistent mass numerically singular.
    const double negligible_mass = (cmpm ? 1e-8 : 1e-12) * max_mass;
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
      fem_nodes.push_back(body->is_kinematic() ? 0 : body->n_nodes());
    dofs.reinit(fem_nodes, with_mpm ? state.mass : std::vector<double>());

    node_mass.resize(dofs.n_nodes());
    start_velocity.reinit(dofs.n_dofs());
    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      for (unsigned int a = 0;
           a < fem_bodies[b]->n_nodes() && !fem_bodies[b]->is_kinematic();
           ++a)
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
        node_mass[node]     = state.mass[i] / node_force_ratio(node);
        DofSpace<dim>::set(start_velocity,
                           node,
                           substepped_mpm ? state.new_velocity[i]
                                          : state.velocity[i]);
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
        if (body.is_kinematic())
          continue; // an obstacle, no unknowns (ContactGeometry moves it)
        for (const unsigned int a : body.prescribed_nodes())
          {
            const Point<dim> &X = body.mesh().rest_position(a);
            add(dofs.fem_node(b, a),
                Tensor<2, dim>(),
                body.motion(a).position(X, end_time) - body.positions()[a],
                body.motion(a).velocity(X, end_time));
          }
      }
    // Grid walls and level sets hold FEM nodes inside them as they hold
    // grid nodes (prescribed nodes already are fully fixed).
    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      if (!fem_bodies[b]->is_kinematic())
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
    if (with_mpm && !cmpm)
      for (const auto &c : boundaries.implicit_constraints(grid.lattice(),
                                                           state.mass,
                                                           state.velocity,
                                                           end_time))
        add(dofs.grid_node(c.node),
            c.free_projector,
            dt * c.obstacle_velocity,
            c.obstacle_velocity);
    if (with_mpm && cmpm)
      {
        // Planar Dirichlet boundaries on the coarse nodes (seed 002 Section
        // 8): walls and level sets hold the coarse nodes within them as
        // they hold grid nodes; the walls stay where the grid's faces are.
        // (an element's interior-mode node sits at the element's centre)
        const CoarseGrid<dim>  &coarse = cmpm->coarse_grid();
        std::vector<Point<dim>> positions(coarse.n_unknown_nodes());
        for (std::size_t i = 0; i < positions.size(); ++i)
          positions[i] = coarse.unknown_position(i);
        for (const auto &c : boundaries.implicit_constraints(grid.lattice(),
                                                             positions,
                                                             state.velocity,
                                                             end_time))
          if (dofs.grid_node(c.node) != DofSpace<dim>::invalid)
            add(dofs.grid_node(c.node),
                c.free_projector,
                dt * c.obstacle_velocity,
                c.obstacle_velocity);
      }
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
    for (const RegisteredTerm &registered : registered_terms)
      if (registered.force_at_start)
        registered.term->add_gradient(at_start, elastic_gradient);
    for (unsigned int node = 0; node < dofs.n_nodes(); ++node)
      DofSpace<dim>::set(acceleration,
                         node,
                         node_gravity(node) -
                           DofSpace<dim>::get(elastic_gradient, node) /
                             (scale * node_mass[node]));
    return acceleration;
  }



  template <int dim>
  Tensor<1, dim>
  ImplicitIntegrator<dim>::free_advance(const unsigned int node,
                                        const double       dt) const
  {
    if (substepped_mpm && node >= dofs.n_fem_nodes())
      return state.displacement[dofs.lattice_node(node)];
    return dt * DofSpace<dim>::get(start_velocity, node);
  }



  template <int dim>
  double
  ImplicitIntegrator<dim>::node_force_ratio(const unsigned int node) const
  {
    return substepped_mpm && node >= dofs.n_fem_nodes() ? constant_force_ratio
                                                        : 1.;
  }



  template <int dim>
  Tensor<1, dim>
  ImplicitIntegrator<dim>::node_gravity(const unsigned int node) const
  {
    return substepped_mpm && node >= dofs.n_fem_nodes() ? Tensor<1, dim>()
                                                        : gravity;
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
                         free_advance(node, dt) +
                           a_weight * DofSpace<dim>::get(acceleration, node) +
                           scale * node_gravity(node));
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
            (scale * node_force_ratio(node)) +
          node_gravity(node);
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
                                             const Vector<double> &velocity,
                                             const double          end_time)
  {
    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      for (unsigned int a = 0; a < fem_bodies[b]->n_nodes(); ++a)
        if (fem_bodies[b]->is_kinematic())
          {
            const Point<dim> &X = fem_bodies[b]->mesh().rest_position(a);
            fem_bodies[b]->positions()[a] =
              fem_bodies[b]->motion(a).position(X, end_time);
            fem_bodies[b]->velocities()[a] =
              fem_bodies[b]->motion(a).velocity(X, end_time);
          }
        else
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
    if (cmpm)
      cmpm->grid_to_particles(particles, state, transfer.parameters());
    else
      transfer.grid_to_particles(particles, state, true);
    particles.update_cells();
  }



  template <int dim>
  double
  ImplicitIntegrator<dim>::material_increment(const Vector<double> &p) const
  {
    // FEM nodes are material points themselves; the unified numbering puts
    // them first (DofSpace).
    double largest = 0.;
    for (unsigned int i = 0; i < dim * dofs.n_fem_nodes(); ++i)
      largest = std::max(largest, std::abs(p[i]));
    if (with_mpm)
      largest =
        std::max(largest,
                 mpm_elasticity.material_increment(p, grid.lattice().dx));
    return largest;
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::minimize_with_friction(Vector<double>    &u,
                                                  const double       dt,
                                                  const std::string &label)
  {
    last_contact.friction_updates   = 0;
    last_contact.friction_converged = true;
    double progress                 = 0.;
    // Passes before the last only give the point at which friction is
    // lagged next ('contact/friction pass tolerance factor' and 'friction
    // pass mollifier factor'): they may stop early and use a wider
    // mollifier; the step ends only in a pass at eps_d and eq. 36's eps_v.
    const double eps_d = newton.tolerance();
    double       tolerance =
      with_friction ? contact_parameters.friction_pass_tolerance_factor * eps_d
                          : eps_d;
    double widening =
      with_friction ? contact_parameters.friction_pass_mollifier_factor : 1.;
    // What the step hands on (dissipation, friction forces) is measured
    // with eps_v itself, however the loop ends (a return or a solver
    // exception that the caller answers with a smaller step).
    struct MollifierReset
    {
      FrictionTerm<dim> *term;
      ~MollifierReset()
      {
        if (term != nullptr)
          term->set_mollifier_factor(1.);
      }
    } const reset{with_friction ? friction.get() : nullptr};
    for (unsigned int j = 0;; ++j)
      {
        // The last pass allowed is the step's answer.
        if (j == contact_parameters.maximum_friction_iterations)
          {
            tolerance = eps_d;
            widening  = 1.;
          }
        if (with_friction)
          friction->set_mollifier_factor(widening);
        const NewtonStatistics s =
          newton.minimize(potential,
                          u,
                          dt,
                          j == 0
                            ? label
                            : label + ", friction update " + std::to_string(j),
                          progress,
                          tolerance);
        tolerance = std::max(eps_d, 0.1 * tolerance);
        if (j == 0)
          last_statistics = s;
        else
          last_statistics += s;
        progress = 1.;
        if (!with_friction)
          return;
        // Converged friction (Section 5): with (F, lambda, T) at the
        // current x, the first Newton increment already met eps_d (not
        // only a looser pass tolerance), with eps_v itself.
        if (j > 0 && s.iterations == 1 && s.residual < eps_d && widening == 1.)
          return;
        if (j == contact_parameters.maximum_friction_iterations)
          {
            last_contact.friction_converged = false;
            return;
          }
        widening                        = std::max(1., 0.1 * widening);
        const unsigned int lagged_pairs = friction->n_pairs();
        friction->update(u);
        ++last_contact.friction_updates;
        // No friction before and after: the potential did not change; a
        // pass stopped at a looser tolerance is finished at eps_d.
        if (lagged_pairs == 0 && friction->n_pairs() == 0)
          {
            if (s.residual < eps_d)
              return;
            tolerance = eps_d;
          }
      }
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::measure_barrier(const Vector<double> &u)
  {
    const auto m                  = barrier->measure(u);
    last_contact.pairs            = m.pairs;
    last_contact.particles        = m.particles;
    last_contact.minimum_distance = m.minimum_distance;
    last_contact.barrier_energy   = m.energy;
    last_contact.force            = m.force;
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::measure_contact(const Vector<double> &u)
  {
    if (!with_contact)
      return;
    measure_barrier(u);
    last_contact.particles_inside = contact_geometry->particles_inside(u);
    if (with_friction)
      {
        last_contact.friction_pairs   = friction->n_pairs();
        last_contact.step_dissipation = friction->dissipation(u);
        last_contact.accumulated_dissipation += last_contact.step_dissipation;
        for (const auto &[bodies, force] : friction->forces(u))
          last_contact.force[bodies] += force;
      }
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::step(const TimeStep &time_step)
  {
    const double       dt          = time_step.dt;
    const double       time        = time_step.time;
    const unsigned int step_number = time_step.number;
    const unsigned int substeps    = time_step.substeps;
    scale                          = scheme.potential_weight() * dt * dt;
    for (const RegisteredTerm &registered : registered_terms)
      if (registered.set_time_step)
        registered.set_time_step(scale, dt);

    // cMPM's `full Newton` local solve (seed 002 Section 8.1.4) solves the
    // step twice: the second pass's shape functions come from the local
    // equilibrium at the coarse displacement the first pass reached.
    const unsigned int          passes = cmpm && cmpm->full_newton() ? 2 : 1;
    std::vector<Tensor<1, dim>> first_pass_displacement;
    NewtonStatistics            first_pass_statistics;
    Vector<double>              u, acceleration, predicted;
    for (unsigned int pass = 0; pass < passes; ++pass)
      {
        if (with_mpm)
          particles_to_grid(pass == 0 ? nullptr : &first_pass_displacement);
        if (with_mpm && substepped_mpm)
          {
            substepped_mpm->substep_and_reconstruct(dt, time, substeps, state);
            constant_force_ratio =
              substepped_mpm->constant_force_ratio(substeps);
          }
        number_unknowns();
        constrain(dt, time + dt);
        if (with_contact)
          contact_geometry->begin_step(time + dt);
        // the loads of Newmark's a^n are those at t^n, the step's at t^n+1
        if (particle_loads)
          particle_loads->set_time(time);
        acceleration = start_acceleration();
        if (particle_loads)
          particle_loads->set_time(time + dt);
        predicted = predictor(acceleration, dt);
        if (cmpm_inertia)
          {
            // cMPM's inertia is the consistent one over the particles.
            // Coarse nodes whose shape functions the particles see only in
            // combination leave it singular (combinations that vanish at
            // every particle); a lumped nodal inertia 1e-8 times the coarse
            // nodes' marks keeps the Newton matrix definite and moves such
            // combinations with the body. It changes the momentum by at
            // most 1e-8 of the step's. FEM nodes keep their own lumped mass
            // (and with it their gravity).
            std::vector<double> lumped(node_mass);
            for (unsigned int node = dofs.n_fem_nodes(); node < dofs.n_nodes();
                 ++node)
              lumped[node] *= 1e-8;
            inertia.reinit(lumped, predicted);
            cmpm_inertia->reinit(dt, scale, gravity);
            if (cmpm_regularization)
              cmpm_regularization->reinit(node_mass);
          }
        else
          inertia.reinit(node_mass, predicted);
        if (with_mpm && substepped_mpm)
          mpm_correction_elasticity.set_reference(predicted);

        // Algorithm 1 lines 3, 5: start from x^n, friction lagged there.
        // The Newton solver moves constrained nodes and obstacles onto
        // their targets as collisions allow.
        u.reinit(dofs.n_dofs());
        if (with_contact)
          barrier->begin_step(u);
        if (with_friction)
          friction->update(u);
        potential.setup_system();
        {
          // the particles' stencils, fixed during the solve, computed once
          const StencilsOfStep<dim> stencils(with_mpm ? &mpm_elasticity
                                                      : nullptr);
          minimize_with_friction(u,
                                 dt,
                                 "step " + std::to_string(step_number) +
                                   ", t = " + std::to_string(time + dt) +
                                   (pass > 0 ? ", full-Newton pass" : ""));
        }
        if (pass + 1 < passes)
          {
            first_pass_statistics = last_statistics;
            first_pass_displacement.assign(state.mass.size(), Tensor<1, dim>());
            for (unsigned int node = dofs.n_fem_nodes(); node < dofs.n_nodes();
                 ++node)
              first_pass_displacement[dofs.lattice_node(node)] =
                DofSpace<dim>::get(u, node);
          }
        else if (pass > 0)
          last_statistics += first_pass_statistics;
      }
    measure_contact(u);

    const Vector<double> velocity =
      end_velocity(u, predicted, acceleration, dt);
    update_fem_bodies(u, velocity, time + dt);
    if (with_mpm)
      grid_to_particles(u, velocity);
  }



  template <int dim>
  unsigned int
  ImplicitIntegrator<dim>::particles_touching_fem()
  {
    if (!with_contact)
      return 0;
    particles_to_grid();
    number_unknowns();
    contact_geometry->begin_step(0.);
    const Vector<double> at_start(dofs.n_dofs());
    const unsigned int   touching =
      contact_geometry->particles_inside(at_start) +
      (contact_geometry->minimum_distance(
         at_start,
         contact_parameters.activation_distance) > 0.
         ? 0
         : 1);
    if (touching == 0)
      {
        // The state at t = 0 for the first diagnostics row: a body that
        // starts closer than dhat to an FEM boundary stores barrier energy
        // (eq. 27) that the first step turns into motion.
        barrier->begin_step(at_start);
        measure_barrier(at_start);
      }
    return touching;
  }



  template <int dim>
  std::set<std::pair<unsigned int, unsigned int>>
  ImplicitIntegrator<dim>::bodies_overlapping_fem() const
  {
    if (!with_contact)
      return {};
    return contact_geometry->overlapping_bodies(Vector<double>(dofs.n_dofs()));
  }



  template <int dim>
  void
  ImplicitIntegrator<dim>::resume_friction_dissipation(const double accumulated)
  {
    last_contact.accumulated_dissipation = accumulated;
  }



  template <int dim>
  const ContactStatistics<dim> *
  ImplicitIntegrator<dim>::contact_statistics() const
  {
    return &last_contact;
  }



  template <int dim>
  const GridState<dim> &
  ImplicitIntegrator<dim>::grid_state() const
  {
    return state;
  }



  template <int dim>
  const NewtonStatistics *
  ImplicitIntegrator<dim>::newton_statistics() const
  {
    return &last_statistics;
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
