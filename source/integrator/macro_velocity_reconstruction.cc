#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/integrator/macro_velocity_reconstruction.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

namespace bfemp
{
  template <int dim>
  MacroVelocityReconstruction<dim>::MacroVelocityReconstruction(
    const BackgroundGrid<dim>         &grid,
    const TimeParameters::Substepping &parameters)
    : grid(grid)
    , parameters(parameters)
  {}



  template <int dim>
  double
  MacroVelocityReconstruction<dim>::gradient_weight() const
  {
    // D of the APIC inertia matrix D_p = D I: dx^2 / 4 for the quadratic
    // B-spline, dx^2 / 3 for the cubic; the linear kernel's D_p varies with
    // the position and its cell-average dx^2 / 6 ... dx^2 / 4 range is
    // represented by dx^2 / 4.
    const double dx2 = grid.lattice().dx * grid.lattice().dx;
    const double D   = grid.kernel_degree() == 3 ? dx2 / 3. : dx2 / 4.;
    return parameters.least_squares_weight * D;
  }



  template <int dim>
  template <int degree>
  void
  MacroVelocityReconstruction<dim>::apic_closed_form(
    ParticleSystem<dim>                  &particles,
    const std::vector<SecantTarget<dim>> &targets,
    const std::vector<double>            &mass,
    std::vector<Tensor<1, dim>>          &velocity) const
  {
    using Layout                          = ParticleLayout<dim>;
    const Lattice<dim>          &lattice  = grid.lattice();
    std::vector<Tensor<1, dim>> &momentum = velocity;
    momentum.assign(mass.size(), Tensor<1, dim>());
    particles.for_each_scattering([&](auto &particle) {
      const SecantTarget<dim>   &target = targets[particle.get_id()];
      const double               m = particle.get_properties()[Layout::mass];
      KernelStencil<dim, degree> stencil;
      stencil.reinit(lattice, particle.get_location());
      for (unsigned int k = 0; k < stencil.n_nodes; ++k)
        momentum[stencil.node[k]] +=
          (m * stencil.weight[k]) *
          (target.velocity + target.velocity_gradient * stencil.offset[k]);
    });
    for (std::size_t k = 0; k < momentum.size(); ++k)
      momentum[k] = mass[k] > 0. ? momentum[k] / mass[k] : Tensor<1, dim>();
  }



  template <int dim>
  template <int degree>
  void
  MacroVelocityReconstruction<dim>::make_sparsity(
    ParticleSystem<dim>             &particles,
    const std::vector<unsigned int> &unknown_of_node,
    const unsigned int               n_unknowns)
  {
    DynamicSparsityPattern               pattern(n_unknowns, n_unknowns);
    KernelStencil<dim, degree>           stencil;
    std::vector<types::global_dof_index> row;
    for (const auto &particle : particles.handler())
      {
        stencil.reinit(grid.lattice(), particle.get_location());
        row.clear();
        for (unsigned int k = 0; k < stencil.n_nodes; ++k)
          if (unknown_of_node[stencil.node[k]] != numbers::invalid_unsigned_int)
            row.push_back(unknown_of_node[stencil.node[k]]);
        std::sort(row.begin(), row.end());
        for (const auto r : row)
          pattern.add_entries(r, row.begin(), row.end(), true);
      }
    sparsity.copy_from(pattern);
    matrix.reinit(sparsity);
  }



  template <int dim>
  template <int degree>
  void
  MacroVelocityReconstruction<dim>::least_squares(
    ParticleSystem<dim>                  &particles,
    const std::vector<SecantTarget<dim>> &targets,
    const std::vector<double>            &mass,
    std::vector<Tensor<1, dim>>          &velocity)
  {
    using Layout = ParticleLayout<dim>;
    std::vector<unsigned int> unknown_of_node(mass.size(),
                                              numbers::invalid_unsigned_int);
    unsigned int              n_unknowns = 0;
    for (std::size_t k = 0; k < mass.size(); ++k)
      if (mass[k] > 0.)
        unknown_of_node[k] = n_unknowns++;
    make_sparsity<degree>(particles, unknown_of_node, n_unknowns);

    // Eq. 4, assembled stripe-parallel: particles running concurrently
    // never share a stencil node, hence never a matrix row.
    const double                lambda = gradient_weight();
    std::vector<Vector<double>> rhs(dim, Vector<double>(n_unknowns));
    particles.for_each_scattering([&](auto &particle) {
      const SecantTarget<dim>   &target = targets[particle.get_id()];
      const double               m = particle.get_properties()[Layout::mass];
      KernelStencil<dim, degree> stencil;
      stencil.reinit(grid.lattice(), particle.get_location());
      for (unsigned int k = 0; k < stencil.n_nodes; ++k)
        {
          const unsigned int row = unknown_of_node[stencil.node[k]];
          if (row == numbers::invalid_unsigned_int)
            continue;
          const Tensor<1, dim> load =
            m * (stencil.weight[k] * target.velocity +
                 lambda * target.velocity_gradient * stencil.gradient[k]);
          for (unsigned int d = 0; d < dim; ++d)
            rhs[d][row] += load[d];
          for (unsigned int j = 0; j < stencil.n_nodes; ++j)
            {
              const unsigned int column = unknown_of_node[stencil.node[j]];
              if (column != numbers::invalid_unsigned_int)
                matrix.add(row,
                           column,
                           m * (stencil.weight[k] * stencil.weight[j] +
                                lambda *
                                  (stencil.gradient[k] * stencil.gradient[j])));
            }
        }
    });

    solver.factorize(matrix);
    Vector<double> component;
    velocity.assign(mass.size(), Tensor<1, dim>());
    for (unsigned int d = 0; d < dim; ++d)
      {
        solver.solve(rhs[d], component);
        for (std::size_t k = 0; k < unknown_of_node.size(); ++k)
          if (unknown_of_node[k] != numbers::invalid_unsigned_int)
            velocity[k][d] = component[unknown_of_node[k]];
      }
  }



  template <int dim>
  void
  MacroVelocityReconstruction<dim>::reconstruct(
    ParticleSystem<dim>                  &particles,
    const std::vector<SecantTarget<dim>> &targets,
    const std::vector<double>            &mass,
    std::vector<Tensor<1, dim>>          &velocity)
  {
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      constexpr int p = decltype(degree)::value;
      if (parameters.reconstruction ==
          TimeParameters::Substepping::Reconstruction::apic)
        this->template apic_closed_form<p>(particles, targets, mass, velocity);
      else
        this->template least_squares<p>(particles, targets, mass, velocity);
    });
  }



  template class MacroVelocityReconstruction<2>;
  template class MacroVelocityReconstruction<3>;
} // namespace bfemp
