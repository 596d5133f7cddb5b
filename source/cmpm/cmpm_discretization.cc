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
      // cells of the particle loops are never empty
      const Element element = element_of(cell_particles);
      std::vector<LocalQuadraturePoint<dim>> points;
      for (const auto &particle : cell_particles)
        {
          const auto                p = particle.get_properties();
          LocalQuadraturePoint<dim> point;
          point.position = Point<dim>(particle.get_location() - element.corner);
          point.weight   = p[Layout::rest_volume];
          point.mass     = p[Layout::mass];
          point.deformation_gradient =
            Layout::get_tensor(p, Layout::deformation_gradient);
          point.material =
            materials[static_cast<unsigned int>(p[Layout::material_id])].get();
          point.tangent =
            point.material->tangent(point.deformation_gradient, true);
          points.push_back(point);
        }
      if (coarse_displacement == nullptr)
        {
          phi.rebuild(element.flat, points);
          return;
        }
      std::vector<Tensor<1, dim>> local(grid.n_local_nodes());
      for (unsigned int I = 0; I < local.size(); ++I)
        local[I] = (*coarse_displacement)[grid.global_node(element.index, I)];
      const unsigned int iterations =
        phi.rebuild_at_equilibrium(element.flat, points, local).iterations;
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
  template <typename ParticleRange>
  typename CmpmDiscretization<dim>::Element
  CmpmDiscretization<dim>::element_of(const ParticleRange &cell_particles) const
  {
    Element element;
    element.index  = grid.element_of(cell_particles.begin()->get_location());
    element.flat   = grid.element_index(element.index);
    element.corner = grid.element_origin(element.index);
    return element;
  }



  template <int dim>
  void
  CmpmDiscretization<dim>::gather(const Element                     &element,
                                  const std::vector<Tensor<1, dim>> &field,
                                  std::vector<Tensor<1, dim>>       &fine) const
  {
    thread_local std::vector<Tensor<1, dim>> coarse;
    coarse.resize(grid.n_element_unknowns());
    for (unsigned int I = 0; I < coarse.size(); ++I)
      coarse[I] = field[grid.unknown_node(element.index, I)];
    phi.fine_values(element.flat, coarse, fine);
  }



  template <int dim>
  void
  CmpmDiscretization<dim>::particles_to_grid(ParticleSystem<dim> &particles,
                                             GridState<dim>      &state) const
  {
    using Layout = ParticleLayout<dim>;
    state.reinit(grid.n_unknown_nodes());
    // Element by element: the momentum sum_p m_p Phi_Ip^T v_p = p^T (sum_p
    // m_p B_kp v_p) is formed on the fine patch and condensed once.
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      const Element      element = element_of(cell_particles);
      const unsigned int r       = grid.n_element_unknowns();
      thread_local std::vector<Tensor<1, dim>> fine_momentum, momentum;
      thread_local std::vector<Tensor<2, dim>> phi_p;
      thread_local std::vector<double>         activity;
      fine_momentum.assign(grid.n_fine(), Tensor<1, dim>());
      activity.assign(r, 0.);
      for (const auto &particle : cell_particles)
        {
          typename CoarseGrid<dim>::FineStencil B;
          grid.fine_stencil(Point<dim>(particle.get_location() -
                                       element.corner),
                            B);
          const auto           p = particle.get_properties();
          const double         m = p[Layout::mass];
          const Tensor<1, dim> v = Layout::get_vector(p, Layout::velocity);
          for (unsigned int k = 0; k < CoarseGrid<dim>::n_stencil; ++k)
            fine_momentum[B.node[k]] += (m * B.value[k]) * v;
          // The averaged scalars sum to one per particle but are negative at
          // some coarse nodes outside the body (Phi is not positive), so
          // their row sums are no lumped masses: a node with a negative sum
          // would drop out of the step and pin its shape functions. The
          // step's mass is the consistent one of CmpmInertiaTerm; these sums
          // of m_p |Phi_Ip| only mark which coarse nodes carry particles.
          phi.values(element.flat, B, phi_p);
          for (unsigned int I = 0; I < r; ++I)
            activity[I] += m * phi_p[I].norm();
        }
      phi.coarse_forces(element.flat, fine_momentum, momentum);
      for (unsigned int I = 0; I < r; ++I)
        {
          const std::size_t node = grid.unknown_node(element.index, I);
          state.mass[node] += activity[I];
          state.velocity[node] += momentum[I];
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
    // Element by element: the coarse fields become fine control values
    // once (q = p Q), and each particle sums its 3^dim fine functions.
    particles.for_each_cell([&](const auto &cell_particles) {
      const Element element = element_of(cell_particles);
      thread_local std::vector<Tensor<1, dim>> u, v_new, v_start;
      gather(element, state.displacement, u);
      gather(element, state.new_velocity, v_new);
      if (flip)
        gather(element, state.velocity, v_start);
      for (auto &particle : cell_particles)
        {
          typename CoarseGrid<dim>::FineStencil B;
          const Point<dim>                      x = particle.get_location();
          grid.fine_stencil(Point<dim>(x - element.corner), B);
          Tensor<1, dim> v_pic, v_old, delta;
          Tensor<2, dim> grad_u;
          for (unsigned int q = 0; q < CoarseGrid<dim>::n_stencil; ++q)
            {
              const unsigned int k = B.node[q];
              v_pic += B.value[q] * v_new[k];
              if (flip)
                v_old += B.value[q] * v_start[k];
              delta += B.value[q] * u[k];
              grad_u += outer_product(u[k], B.gradient[q]);
            }
          const ArrayView<double> p       = particle.get_properties();
          Tensor<1, dim>          v_new_p = v_pic;
          if (flip)
            v_new_p =
              transfer.pic_blend * v_pic +
              (1. - transfer.pic_blend) *
                (Layout::get_vector(p, Layout::velocity) + v_pic - v_old);
          Layout::set_vector(p, Layout::velocity, v_new_p);
          Layout::set_tensor(
            p,
            Layout::deformation_gradient,
            (identity + grad_u) *
              Layout::get_tensor(p, Layout::deformation_gradient));
          particle.set_location(x + delta);
        }
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
