#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/particles/particle_layout.h>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace bfemp
{
  template <int dim>
  CmpmDiscretization<dim>::CmpmDiscretization(
    const BackgroundGrid<dim> &background,
    const CmpmParameters      &parameters)
    : grid(background.lattice().origin,
           background.lattice().dx,
           background.lattice().n_cells,
           parameters)
    , phi(grid)
  {}



  template <int dim>
  void
  CmpmDiscretization<dim>::reinit(
    ParticleSystem<dim>                               &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const std::vector<Tensor<1, dim>>                 *coarse_displacement)
  {
    using Layout = ParticleLayout<dim>;
    phi.clear();
    max_local_iterations = 0;
    std::mutex iterations_mutex;
    // Each cell of the particle system is one coarse element; elements are
    // independent, so the cell loop's threads rebuild them side by side.
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      std::vector<LocalQuadraturePoint<dim>> points;
      std::size_t                            element = 0;
      std::array<int, dim>                   index;
      Point<dim>                             corner;
      bool                                   first = true;
      for (const auto &particle : cell_particles)
        {
          const Point<dim> x = particle.get_location();
          if (first)
            {
              index   = grid.element_of(x);
              element = grid.element_index(index);
              corner  = grid.element_origin(index);
              first   = false;
            }
          const auto                p = particle.get_properties();
          LocalQuadraturePoint<dim> point;
          point.position = Point<dim>(x - corner);
          point.weight   = p[Layout::rest_volume];
          point.deformation_gradient =
            Layout::get_tensor(p, Layout::deformation_gradient);
          point.material =
            materials[static_cast<unsigned int>(p[Layout::material_id])].get();
          point.tangent =
            point.material->tangent(point.deformation_gradient, true);
          points.push_back(point);
        }
      if (first)
        return;
      if (coarse_displacement == nullptr)
        {
          phi.rebuild(element, points);
          return;
        }
      std::vector<Tensor<1, dim>> local(grid.n_local_nodes());
      for (unsigned int I = 0; I < local.size(); ++I)
        local[I] = (*coarse_displacement)[grid.global_node(index, I)];
      const unsigned int iterations =
        phi.rebuild_at_equilibrium(element, points, local).iterations;
      std::lock_guard<std::mutex> lock(iterations_mutex);
      max_local_iterations = std::max(max_local_iterations, iterations);
    });
    bound = 1.;
    for (std::size_t e = 0; e < grid.n_elements_total(); ++e)
      if (phi.is_active(e))
        bound = std::max(bound, phi.interpolation_bound(e));
  }



  template <int dim>
  bool
  CmpmDiscretization<dim>::full_newton() const
  {
    return grid.parameters().local_solve ==
           CmpmParameters::LocalSolve::full_newton;
  }



  template <int dim>
  unsigned int
  CmpmDiscretization<dim>::local_iterations() const
  {
    return max_local_iterations;
  }



  template <int dim>
  double
  CmpmDiscretization<dim>::interpolation_bound() const
  {
    return bound;
  }



  template <int dim>
  void
  CmpmDiscretization<dim>::particles_to_grid(ParticleSystem<dim> &particles,
                                             GridState<dim>      &state) const
  {
    using Layout = ParticleLayout<dim>;
    state.reinit(grid.node_lattice().n_nodes);
    particles.for_each_scattering([&](const auto &particle) {
      thread_local std::vector<CoarseShapeValue<dim>> values;
      phi.evaluate(particle.get_location(), values);
      const auto           p = particle.get_properties();
      const double         m = p[Layout::mass];
      const Tensor<1, dim> v = Layout::get_vector(p, Layout::velocity);
      // The averaged scalars sum to one per particle but are negative at
      // some coarse nodes outside the body (Phi is not positive), so their
      // row sums are no lumped masses: a node with a negative sum would drop
      // out of the step and pin its shape functions. The step's mass is the
      // consistent one of CmpmInertiaTerm; these sums of m_p |Phi_Ip| only
      // mark which coarse nodes carry particles.
      for (const CoarseShapeValue<dim> &value : values)
        {
          state.mass[value.node] += m * value.value.norm();
          state.velocity[value.node] += m * transpose(value.value) * v;
        }
    });
  }



  template <int dim>
  void
  CmpmDiscretization<dim>::grid_to_particles(
    ParticleSystem<dim>      &particles,
    const GridState<dim>     &state,
    const TransferParameters &transfer) const
  {
    using Layout                  = ParticleLayout<dim>;
    const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();
    const bool flip = transfer.scheme == TransferParameters::Scheme::flip;
    particles.for_each([&](auto &particle) {
      thread_local std::vector<CoarseShapeValue<dim>> values;
      const Point<dim> x = particle.get_location();
      phi.evaluate(x, values);
      Tensor<1, dim> v_pic, v_old, delta;
      Tensor<2, dim> grad_u;
      for (const CoarseShapeValue<dim> &value : values)
        {
          const Tensor<1, dim> &u = state.displacement[value.node];
          v_pic += value.value * state.new_velocity[value.node];
          if (flip)
            v_old += value.value * state.velocity[value.node];
          delta += value.value * u;
          // grad(Phi_I u_I)_ab = sum_c d(Phi_I)_ac/dx_b u_Ic
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int c = 0; c < dim; ++c)
              grad_u[a] += u[c] * value.gradient[a][c];
        }
      const ArrayView<double> p     = particle.get_properties();
      Tensor<1, dim>          v_new = v_pic;
      if (flip)
        v_new = transfer.pic_blend * v_pic +
                (1. - transfer.pic_blend) *
                  (Layout::get_vector(p, Layout::velocity) + v_pic - v_old);
      Layout::set_vector(p, Layout::velocity, v_new);
      Layout::set_tensor(p,
                         Layout::deformation_gradient,
                         (identity + grad_u) *
                           Layout::get_tensor(p, Layout::deformation_gradient));
      particle.set_location(x + delta);
    });
  }



  template <int dim>
  void
  CmpmDiscretization<dim>::evaluate(
    const Point<dim>                   &x,
    std::vector<CoarseShapeValue<dim>> &values) const
  {
    phi.evaluate(x, values);
  }



  template <int dim>
  const Lattice<dim> &
  CmpmDiscretization<dim>::node_lattice() const
  {
    return grid.node_lattice();
  }



  template <int dim>
  const CoarseGrid<dim> &
  CmpmDiscretization<dim>::coarse_grid() const
  {
    return grid;
  }



  template <int dim>
  const CoarsenedShapeFunctions<dim> &
  CmpmDiscretization<dim>::shape_functions() const
  {
    return phi;
  }



  template class CmpmDiscretization<2>;
  template class CmpmDiscretization<3>;
} // namespace bfemp
