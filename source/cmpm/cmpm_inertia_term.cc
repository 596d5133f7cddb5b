#include <bfemp/cmpm/cmpm_inertia_term.h>
#include <bfemp/cmpm/element_assembly.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/solver/node_sparsity.h>

#include <deal.II/lac/sparsity_pattern.h>

#include <algorithm>

namespace bfemp
{
  template <int dim>
  CmpmInertiaTerm<dim>::CmpmInertiaTerm(ParticleSystem<dim> &particles,
                                        const CmpmDiscretization<dim> &cmpm,
                                        const DofSpace<dim>           &dofs)
    : particles(particles)
    , cmpm(cmpm)
    , dofs(dofs)
  {}



  template <int dim>
  void
  CmpmInertiaTerm<dim>::reinit(const double          dt,
                               const double          gravity_weight,
                               const Tensor<1, dim> &gravity)
  {
    this->dt             = dt;
    this->gravity_weight = gravity_weight;
    this->gravity        = gravity;
    // the particles and control matrices of a new step (or pass)
    mass_assembled = false;
  }



  template <int dim>
  std::string
  CmpmInertiaTerm<dim>::name() const
  {
    return "cMPM inertia";
  }



  template <int dim>
  template <typename ParticleAccessor>
  Tensor<1, dim>
  CmpmInertiaTerm<dim>::target(const ParticleAccessor &particle) const
  {
    using Layout = ParticleLayout<dim>;
    return dt *
             Layout::get_vector(particle.get_properties(), Layout::velocity) +
           gravity_weight * gravity;
  }



  template <int dim>
  template <typename ParticleAccessor>
  Tensor<1, dim>
  CmpmInertiaTerm<dim>::residual(const ParticleAccessor &particle,
                                 const typename CoarseGrid<dim>::FineStencil &B,
                                 const std::vector<Tensor<1, dim>> &q) const
  {
    Tensor<1, dim> r = -target(particle);
    for (unsigned int k = 0; k < CoarseGrid<dim>::n_stencil; ++k)
      r += B.value[k] * q[B.node[k]];
    return r;
  }



  template <int dim>
  void
  CmpmInertiaTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    // All particles of a cell (= coarse element) share its coarse nodes.
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      const CmpmElementAssembly<dim>
        element(cmpm, dofs, cell_particles.begin()->get_location());
      for (const unsigned int node : element.unknowns())
        sparsity.add_row_entries(node, element.unknowns());
    });
  }



  template <int dim>
  double
  CmpmInertiaTerm<dim>::value(const Vector<double> &u) const
  {
    using Layout = ParticleLayout<dim>;
    return particles.template sum_over_cells<double>(
      [&](const auto &cell_particles) {
        const CmpmElementAssembly<dim>
          element(cmpm, dofs, cell_particles.begin()->get_location());
        thread_local std::vector<Tensor<1, dim>> q;
        element.gather(u, q);
        double energy = 0.;
        for (const auto &particle : cell_particles)
          {
            typename CoarseGrid<dim>::FineStencil B;
            element.fine_stencil(particle.get_location(), B);
            energy += 0.5 * particle.get_properties()[Layout::mass] *
                      residual(particle, B, q).norm_square();
          }
        return energy;
      });
  }



  template <int dim>
  double
  CmpmInertiaTerm<dim>::magnitude() const
  {
    using Layout = ParticleLayout<dim>;
    // the terms summed in value() are of the size of m_p |u^_p|^2
    return particles.template sum<double>([&](const auto &particle) {
      return 0.5 * particle.get_properties()[Layout::mass] *
             target(particle).norm_square();
    });
  }



  template <int dim>
  void
  CmpmInertiaTerm<dim>::add_gradient(const Vector<double> &u,
                                     Vector<double>       &gradient) const
  {
    using Layout = ParticleLayout<dim>;
    // m_p B_kp r_p on the fine nodes, condensed once per element
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      const CmpmElementAssembly<dim>
        element(cmpm, dofs, cell_particles.begin()->get_location());
      thread_local std::vector<Tensor<1, dim>> q, fine_forces;
      element.gather(u, q);
      fine_forces.assign(element.n_fine(), Tensor<1, dim>());
      for (const auto &particle : cell_particles)
        {
          typename CoarseGrid<dim>::FineStencil B;
          element.fine_stencil(particle.get_location(), B);
          const Tensor<1, dim> m_r =
            particle.get_properties()[Layout::mass] * residual(particle, B, q);
          for (unsigned int k = 0; k < CoarseGrid<dim>::n_stencil; ++k)
            fine_forces[B.node[k]] += B.value[k] * m_r;
        }
      element.add_forces(fine_forces, gradient);
    });
  }



  template <int dim>
  void
  CmpmInertiaTerm<dim>::add_hessian(const Vector<double> &,
                                    SparseMatrix<double> &hessian,
                                    const HessianKind) const
  {
    if (!mass_assembled)
      {
        NodeSparsity couplings(dofs.n_nodes());
        add_couplings(couplings);
        SparsityPattern      pattern;
        SparseMatrix<double> mass;
        couplings.build(dim, pattern);
        mass.reinit(pattern);
        assemble_mass(mass);
        // by rows, columns ascending (deal.II stores the diagonal first)
        mass_row_start.assign(1, 0);
        mass_columns.clear();
        mass_values.clear();
        for (unsigned int row = 0; row < mass.m(); ++row)
          {
            const std::size_t first = mass_columns.size();
            for (auto entry = mass.begin(row); entry != mass.end(row); ++entry)
              {
                mass_columns.push_back(entry->column());
                mass_values.push_back(entry->value());
              }
            for (std::size_t k = first + 1;
                 k < mass_columns.size() && mass_columns[k] < row;
                 ++k)
              {
                std::swap(mass_columns[k - 1], mass_columns[k]);
                std::swap(mass_values[k - 1], mass_values[k]);
              }
            mass_row_start.push_back(mass_columns.size());
          }
        mass_assembled = true;
      }
    for (unsigned int row = 0; row + 1 < mass_row_start.size(); ++row)
      hessian.add(row,
                  mass_row_start[row + 1] - mass_row_start[row],
                  &mass_columns[mass_row_start[row]],
                  &mass_values[mass_row_start[row]],
                  false,
                  true);
  }



  template <int dim>
  void
  CmpmInertiaTerm<dim>::assemble_mass(SparseMatrix<double> &hessian) const
  {
    using Layout = ParticleLayout<dim>;
    // the fine consistent mass sum_p m_p B_kp B_lp I over the fine nodes the
    // element's particles touch, condensed once per element
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      const CmpmElementAssembly<dim>
        element(cmpm, dofs, cell_particles.begin()->get_location());
      thread_local std::vector<int>                                   position;
      thread_local std::vector<unsigned int>                          nodes;
      thread_local std::vector<Tensor<2, dim>>                        upper;
      thread_local std::vector<char>                                  coupled;
      thread_local std::vector<typename CoarseGrid<dim>::FineStencil> stencils;
      thread_local std::vector<double>                                masses;
      stencils.clear();
      masses.clear();
      position.assign(element.n_fine(), -1);
      for (const auto &particle : cell_particles)
        {
          stencils.emplace_back();
          element.fine_stencil(particle.get_location(), stencils.back());
          masses.push_back(particle.get_properties()[Layout::mass]);
          for (const unsigned int k : stencils.back().node)
            position[k] = 0;
        }
      nodes.clear();
      for (unsigned int k = 0; k < position.size(); ++k)
        if (position[k] == 0)
          {
            position[k] = nodes.size();
            nodes.push_back(k);
          }
      const std::size_t m = nodes.size();
      upper.assign(m * m, Tensor<2, dim>());
      coupled.assign(m * m, 1); // all of upper is set
      for (unsigned int p = 0; p < stencils.size(); ++p)
        {
          const auto &B = stencils[p];
          for (unsigned int k = 0; k < CoarseGrid<dim>::n_stencil; ++k)
            for (unsigned int l = 0; l < CoarseGrid<dim>::n_stencil; ++l)
              {
                const unsigned int i = position[B.node[k]];
                const unsigned int j = position[B.node[l]];
                if (i > j)
                  continue;
                const double m_BB = masses[p] * B.value[k] * B.value[l];
                for (unsigned int a = 0; a < dim; ++a)
                  upper[i * m + j][a][a] += m_BB;
              }
        }
      element.add_stiffness(nodes, upper, coupled, hessian);
    });
  }



  template class CmpmInertiaTerm<2>;
  template class CmpmInertiaTerm<3>;
} // namespace bfemp
