#include <bfemp/cmpm/element_assembly.h>
#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/solver/particle_load_term.h>

namespace bfemp
{
  template <int dim>
  ParticleLoadTerm<dim>::ParticleLoadTerm(const BackgroundGrid<dim> &grid,
                                          ParticleSystem<dim>       &particles,
                                          ParticleLoads<dim>        &loads,
                                          const DofSpace<dim>       &dofs,
                                          const CmpmDiscretization<dim> *cmpm)
    : grid(grid)
    , particles(particles)
    , loads(loads)
    , dofs(dofs)
    , cmpm(cmpm)
  {}

  template <int dim>
  void
  ParticleLoadTerm<dim>::set_scale(const double s)
  {
    scale = s;
  }

  template <int dim>
  void
  ParticleLoadTerm<dim>::set_time(const double t)
  {
    loads.set_time(t);
  }

  template <int dim>
  std::string
  ParticleLoadTerm<dim>::name() const
  {
    return "particle loads";
  }

  template <int dim>
  void
  ParticleLoadTerm<dim>::add_couplings(NodeSparsity &) const
  {
    // linear in u: no Hessian
  }

  template <int dim>
  double
  ParticleLoadTerm<dim>::value(const Vector<double> &u) const
  {
    // -s sum_p f_p . u_p
    if (cmpm != nullptr)
      return -scale * particles.template sum_over_cells<double>(
                        [&](const auto &cell_particles) {
                          const CmpmElementAssembly<dim> element(
                            *cmpm,
                            dofs,
                            cell_particles.begin()->get_location());
                          thread_local std::vector<Tensor<1, dim>> q;
                          element.gather(u, q);
                          double work = 0.;
                          for (const auto &particle : cell_particles)
                            {
                              const Tensor<1, dim> f =
                                loads.force(particle.get_properties());
                              if (f.norm_square() == 0.)
                                continue;
                              typename CoarseGrid<dim>::FineStencil B;
                              element.fine_stencil(particle.get_location(), B);
                              for (unsigned int k = 0;
                                   k < CoarseGrid<dim>::n_stencil;
                                   ++k)
                                work += B.value[k] * (f * q[B.node[k]]);
                            }
                          return work;
                        });
    return dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      return -scale * particles.template sum<double>([&](const auto &particle) {
        const Tensor<1, dim> f = loads.force(particle.get_properties());
        if (f.norm_square() == 0.)
          return 0.;
        KernelStencil<dim, decltype(degree)::value> kernel;
        kernel.reinit(grid.lattice(), particle.get_location());
        double work = 0.;
        for (unsigned int k = 0; k < kernel.n_nodes; ++k)
          {
            const unsigned int node = dofs.grid_node(kernel.node[k]);
            if (node != DofSpace<dim>::invalid)
              work += kernel.weight[k] * (f * DofSpace<dim>::get(u, node));
          }
        return work;
      });
    });
  }

  template <int dim>
  void
  ParticleLoadTerm<dim>::add_gradient(const Vector<double> &,
                                      Vector<double> &gradient) const
  {
    // -s N_p^T f_p, the same at every u
    if (cmpm != nullptr)
      {
        particles.for_each_cell_scattering([&](const auto &cell_particles) {
          thread_local std::vector<Tensor<1, dim>> fine_forces;
          bool                                     loaded = false;
          for (const auto &particle : cell_particles)
            loaded = loaded ||
                     loads.force(particle.get_properties()).norm_square() > 0.;
          if (!loaded)
            return;
          const CmpmElementAssembly<dim>
            element(*cmpm, dofs, cell_particles.begin()->get_location());
          fine_forces.assign(element.n_fine(), Tensor<1, dim>());
          for (const auto &particle : cell_particles)
            {
              const Tensor<1, dim> f =
                -scale * loads.force(particle.get_properties());
              typename CoarseGrid<dim>::FineStencil B;
              element.fine_stencil(particle.get_location(), B);
              for (unsigned int k = 0; k < CoarseGrid<dim>::n_stencil; ++k)
                fine_forces[B.node[k]] += B.value[k] * f;
            }
          element.add_forces(fine_forces, gradient);
        });
        return;
      }
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      particles.for_each_scattering([&](const auto &particle) {
        const Tensor<1, dim> f = loads.force(particle.get_properties());
        if (f.norm_square() == 0.)
          return;
        KernelStencil<dim, decltype(degree)::value> kernel;
        kernel.reinit(grid.lattice(), particle.get_location());
        for (unsigned int k = 0; k < kernel.n_nodes; ++k)
          {
            const unsigned int node = dofs.grid_node(kernel.node[k]);
            if (node != DofSpace<dim>::invalid)
              for (unsigned int c = 0; c < dim; ++c)
                gradient[dim * node + c] -= scale * kernel.weight[k] * f[c];
          }
      });
    });
  }

  template <int dim>
  void
  ParticleLoadTerm<dim>::add_hessian(const Vector<double> &,
                                     SparseMatrix<double> &,
                                     const HessianKind) const
  {}

  template class ParticleLoadTerm<2>;
  template class ParticleLoadTerm<3>;
} // namespace bfemp
