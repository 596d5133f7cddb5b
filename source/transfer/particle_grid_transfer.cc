#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/transfer/particle_grid_transfer.h>

namespace bfemp
{
  template <int dim>
  ParticleGridTransfer<dim>::ParticleGridTransfer(
    const BackgroundGrid<dim>                         &grid,
    const TransferParameters                          &parameters,
    const std::vector<std::unique_ptr<Material<dim>>> &materials)
    : grid(grid)
    , transfer_parameters(parameters)
    , materials(materials)
  {}



  template <int dim>
  template <int degree>
  void
  ParticleGridTransfer<dim>::scatter(ParticleSystem<dim> &particles,
                                     GridState<dim>      &grid_state,
                                     const bool           with_momentum,
                                     const bool           with_stress) const
  {
    using Layout                = ParticleLayout<dim>;
    const Lattice<dim> &lattice = grid.lattice();
    const bool          affine =
      transfer_parameters.scheme == TransferParameters::Scheme::apic;

    particles.for_each_scattering([&](auto &particle) {
      const ArrayView<const double> p = particle.get_properties();
      const Point<dim>              x = particle.get_location();
      KernelStencil<dim, degree>    stencil;
      stencil.reinit(lattice, x);

      const double         m = p[Layout::mass];
      const Tensor<1, dim> v = Layout::get_vector(p, Layout::velocity);
      Tensor<2, dim>       C;
      if (affine)
        C = Layout::get_tensor(p, Layout::affine_velocity);
      // -V^0 P F^T: the Kirchhoff stress times the rest volume.
      Tensor<2, dim> stress;
      if (with_stress)
        {
          const Tensor<2, dim> F =
            Layout::get_tensor(p, Layout::deformation_gradient);
          const auto &material =
            *materials[static_cast<unsigned int>(p[Layout::material_id])];
          stress = -p[Layout::rest_volume] * material.first_piola_kirchhoff(F) *
                   transpose(F);
        }

      for (unsigned int k = 0; k < stencil.n_nodes; ++k)
        {
          const std::size_t node = stencil.node[k];
          if (with_momentum)
            {
              const double mass_k = stencil.weight[k] * m;
              grid_state.mass[node] += mass_k;
              grid_state.velocity[node] +=
                mass_k * (affine ? v + C * stencil.offset[k] : v);
            }
          if (with_stress)
            grid_state.force[node] += stress * stencil.gradient[k];
        }
    });
  }



  template <int dim>
  void
  ParticleGridTransfer<dim>::particles_to_grid(ParticleSystem<dim> &particles,
                                               GridState<dim>      &grid_state,
                                               const bool with_stress) const
  {
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      scatter<decltype(degree)::value>(particles,
                                       grid_state,
                                       true,
                                       with_stress);
    });
  }



  template <int dim>
  void
  ParticleGridTransfer<dim>::stress_to_grid(ParticleSystem<dim> &particles,
                                            GridState<dim> &grid_state) const
  {
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      scatter<decltype(degree)::value>(particles, grid_state, false, true);
    });
  }



  template <int dim>
  template <int degree, bool explicit_step>
  void
  ParticleGridTransfer<dim>::gather(ParticleSystem<dim>  &particles,
                                    const GridState<dim> &grid_state,
                                    const bool   update_deformation_gradient,
                                    const double explicit_dt) const
  {
    using Layout                  = ParticleLayout<dim>;
    using Scheme                  = TransferParameters::Scheme;
    const Lattice<dim>  &lattice  = grid.lattice();
    const Scheme         scheme   = transfer_parameters.scheme;
    const double         theta    = transfer_parameters.pic_blend;
    const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();
    // D_p^-1 of Table 1 is a constant multiple of I for degree 2 and 3.
    const double inverse_inertia = degree == 2 ? 4. / (lattice.dx * lattice.dx)
                                               : 3. / (lattice.dx * lattice.dx);
    const bool   affine_from_moments = scheme == Scheme::apic && degree > 1;

    particles.for_each([&](auto &particle) {
      const ArrayView<double>    p = particle.get_properties();
      const Point<dim>           x = particle.get_location();
      KernelStencil<dim, degree> stencil;
      stencil.reinit(lattice, x);

      // Sums over the stencil: v_PIC = sum w v~, the FLIP increment, the
      // position change delta = sum w u, grad u = sum u grad w^T, and the two
      // halves of B_p in Table 1 (with x~_i - x_p^{n+1} = r + u - delta).
      Tensor<1, dim> v_pic, v_old, delta;
      Tensor<2, dim> grad_u, B_first, B_second, grad_v;
      for (unsigned int k = 0; k < stencil.n_nodes; ++k)
        {
          const std::size_t     node  = stencil.node[k];
          const double          w     = stencil.weight[k];
          const Tensor<1, dim> &v_new = grid_state.new_velocity[node];
          v_pic += w * v_new;
          grad_v += outer_product(v_new, stencil.gradient[k]);
          if (scheme == Scheme::flip)
            v_old += w * grid_state.velocity[node];
          if constexpr (explicit_step)
            {
              if (affine_from_moments)
                B_first += outer_product(w * v_new, stencil.offset[k]);
            }
          else
            {
              const Tensor<1, dim> &u = grid_state.displacement[node];
              delta += w * u;
              grad_u += outer_product(u, stencil.gradient[k]);
              if (affine_from_moments)
                {
                  B_first +=
                    outer_product(w * v_new, 2. * stencil.offset[k] + u);
                  B_second += outer_product(w * u, v_new);
                }
            }
        }

      Tensor<2, dim> B;
      if constexpr (explicit_step)
        {
          // u_i = dt v~_i: then delta = dt v_PIC, grad u = dt grad v, and
          // Table 1's B_p reduces to sum_i w_ip v~_i (x_i - x_p)^T, because
          // the dt-terms cancel once sum_i w_ip v~_i = v_PIC is used.
          delta  = explicit_dt * v_pic;
          grad_u = explicit_dt * grad_v;
          B      = B_first;
        }
      else
        B = 0.5 * (B_first - outer_product(v_pic, delta) - B_second +
                   outer_product(delta, v_pic));

      Tensor<1, dim> v_new = v_pic;
      if (scheme == Scheme::flip)
        {
          const Tensor<1, dim> v_flip =
            Layout::get_vector(p, Layout::velocity) + v_pic - v_old;
          v_new = theta * v_pic + (1. - theta) * v_flip;
        }
      else if (scheme == Scheme::apic)
        // Multilinear kernels: B D^-1 reduces to the velocity gradient
        // (Jiang et al. 2015), which stays finite where D_p is singular.
        Layout::set_tensor(p,
                           Layout::affine_velocity,
                           degree == 1 ? grad_v : B * inverse_inertia);
      Layout::set_vector(p, Layout::velocity, v_new);
      if (update_deformation_gradient)
        Layout::set_tensor(p,
                           Layout::deformation_gradient,
                           (identity + grad_u) *
                             Layout::get_tensor(p,
                                                Layout::deformation_gradient));
      particle.set_location(x + delta);
    });
  }



  template <int dim>
  void
  ParticleGridTransfer<dim>::grid_to_particles(
    ParticleSystem<dim>  &particles,
    const GridState<dim> &grid_state,
    const bool            update_deformation_gradient,
    const double          explicit_dt) const
  {
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      constexpr int d = decltype(degree)::value;
      if (explicit_dt > 0.)
        gather<d, true>(particles,
                        grid_state,
                        update_deformation_gradient,
                        explicit_dt);
      else
        gather<d, false>(particles,
                         grid_state,
                         update_deformation_gradient,
                         0.);
    });
  }



  template <int dim>
  void
  ParticleGridTransfer<dim>::update_deformation_gradient(
    ParticleSystem<dim>               &particles,
    const std::vector<Tensor<1, dim>> &grid_displacement) const
  {
    using Layout                = ParticleLayout<dim>;
    const Lattice<dim> &lattice = grid.lattice();
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree_constant) {
      constexpr int degree = decltype(degree_constant)::value;
      particles.for_each([&](auto &particle) {
        const ArrayView<double>    p = particle.get_properties();
        const Point<dim>           x = particle.get_location();
        KernelStencil<dim, degree> stencil;
        stencil.reinit(lattice, x);
        Tensor<2, dim> F_increment = unit_symmetric_tensor<dim>();
        for (unsigned int k = 0; k < stencil.n_nodes; ++k)
          F_increment += outer_product(grid_displacement[stencil.node[k]],
                                       stencil.gradient[k]);
        Layout::set_tensor(p,
                           Layout::deformation_gradient,
                           F_increment *
                             Layout::get_tensor(p,
                                                Layout::deformation_gradient));
      });
    });
  }



  template <int dim>
  Tensor<2, dim>
  ParticleGridTransfer<dim>::apic_inertia(const Point<dim> &x) const
  {
    const double   dx2 = grid.lattice().dx * grid.lattice().dx;
    Tensor<2, dim> D;
    for (unsigned int d = 0; d < dim; ++d)
      if (grid.kernel_degree() == 2)
        D[d][d] = dx2 / 4.;
      else if (grid.kernel_degree() == 3)
        D[d][d] = dx2 / 3.;
      else
        {
          const double xi =
            (x[d] - grid.lattice().origin[d]) * grid.lattice().inverse_dx;
          const double t = xi - std::floor(xi);
          D[d][d]        = dx2 * t * (1. - t);
        }
    return D;
  }



  template <int dim>
  const TransferParameters &
  ParticleGridTransfer<dim>::parameters() const
  {
    return transfer_parameters;
  }



  template class ParticleGridTransfer<2>;
  template class ParticleGridTransfer<3>;
} // namespace bfemp
