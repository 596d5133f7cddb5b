#include <bfemp/cmpm/cmpm_inertia_term.h>
#include <bfemp/particles/particle_layout.h>

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
  }



  template <int dim>
  std::string
  CmpmInertiaTerm<dim>::name() const
  {
    return "cMPM inertia";
  }



  template <int dim>
  template <typename ParticleAccessor>
  void
  CmpmInertiaTerm<dim>::evaluate(const ParticleAccessor      &particle,
                                 std::vector<unsigned int>   &nodes,
                                 std::vector<Tensor<2, dim>> &phi,
                                 double                      &mass,
                                 Tensor<1, dim>              &target) const
  {
    using Layout = ParticleLayout<dim>;
    thread_local std::vector<CoarseShapeValue<dim>> values;
    cmpm.evaluate(particle.get_location(), values);
    nodes.clear();
    phi.clear();
    for (const CoarseShapeValue<dim> &value : values)
      {
        // nodes left out of the step (negligible mass) stay at u = 0
        const unsigned int node = dofs.grid_node(value.node);
        if (node == DofSpace<dim>::invalid)
          continue;
        nodes.push_back(node);
        phi.push_back(value.value);
      }
    const auto p = particle.get_properties();
    mass         = p[Layout::mass];
    target =
      dt * Layout::get_vector(p, Layout::velocity) + gravity_weight * gravity;
  }



  template <int dim>
  void
  CmpmInertiaTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    // All particles of a cell (= coarse element) share its coarse nodes.
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      std::vector<unsigned int>   nodes;
      std::vector<Tensor<2, dim>> phi;
      double                      mass;
      Tensor<1, dim>              target;
      evaluate(*cell_particles.begin(), nodes, phi, mass, target);
      for (const unsigned int node : nodes)
        sparsity.add_row_entries(node, nodes);
    });
  }



  template <int dim>
  template <typename ParticleAccessor>
  Tensor<1, dim>
  CmpmInertiaTerm<dim>::residual(const ParticleAccessor      &particle,
                                 const Vector<double>        &u,
                                 std::vector<unsigned int>   &nodes,
                                 std::vector<Tensor<2, dim>> &phi,
                                 double                      &mass) const
  {
    Tensor<1, dim> target;
    evaluate(particle, nodes, phi, mass, target);
    Tensor<1, dim> r = -target;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      r += phi[k] * DofSpace<dim>::get(u, nodes[k]);
    return r;
  }



  template <int dim>
  double
  CmpmInertiaTerm<dim>::value(const Vector<double> &u) const
  {
    return particles.template sum<double>([&](const auto &particle) {
      thread_local std::vector<unsigned int>   nodes;
      thread_local std::vector<Tensor<2, dim>> phi;
      double                                   mass;
      const Tensor<1, dim> r = residual(particle, u, nodes, phi, mass);
      return 0.5 * mass * r.norm_square();
    });
  }



  template <int dim>
  double
  CmpmInertiaTerm<dim>::magnitude() const
  {
    // the terms summed in value() are of the size of m_p |u^_p|^2
    return particles.template sum<double>([&](const auto &particle) {
      thread_local std::vector<unsigned int>   nodes;
      thread_local std::vector<Tensor<2, dim>> phi;
      double                                   mass;
      Tensor<1, dim>                           target;
      evaluate(particle, nodes, phi, mass, target);
      return 0.5 * mass * target.norm_square();
    });
  }



  template <int dim>
  void
  CmpmInertiaTerm<dim>::add_gradient(const Vector<double> &u,
                                     Vector<double>       &gradient) const
  {
    particles.for_each_scattering([&](const auto &particle) {
      thread_local std::vector<unsigned int>   nodes;
      thread_local std::vector<Tensor<2, dim>> phi;
      double                                   mass;
      const Tensor<1, dim> r = residual(particle, u, nodes, phi, mass);
      for (unsigned int k = 0; k < nodes.size(); ++k)
        {
          const Tensor<1, dim> g = mass * (transpose(phi[k]) * r);
          for (unsigned int c = 0; c < dim; ++c)
            gradient[dim * nodes[k] + c] += g[c];
        }
    });
  }



  template <int dim>
  void
  CmpmInertiaTerm<dim>::add_hessian(const Vector<double> &,
                                    SparseMatrix<double> &hessian,
                                    const HessianKind) const
  {
    // sum_p m_p Phi_Ip^T Phi_Jp, summed densely per cell (its particles share
    // the coarse nodes) and added row by row once per cell
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      std::vector<unsigned int>   nodes;
      std::vector<Tensor<2, dim>> phi, blocks;
      double                      mass;
      Tensor<1, dim>              target;
      for (const auto &particle : cell_particles)
        {
          evaluate(particle, nodes, phi, mass, target);
          const std::size_t r = nodes.size();
          blocks.resize(r * r);
          for (unsigned int k = 0; k < r; ++k)
            for (unsigned int l = 0; l < r; ++l)
              blocks[k * r + l] += mass * transpose(phi[k]) * phi[l];
        }
      const std::size_t                    r = nodes.size();
      std::vector<types::global_dof_index> columns(r * dim);
      std::vector<double>                  row(r * dim);
      for (unsigned int l = 0; l < r; ++l)
        for (unsigned int b = 0; b < dim; ++b)
          columns[dim * l + b] = dim * nodes[l] + b;
      for (unsigned int k = 0; k < r; ++k)
        for (unsigned int a = 0; a < dim; ++a)
          {
            for (unsigned int l = 0; l < r; ++l)
              for (unsigned int b = 0; b < dim; ++b)
                row[dim * l + b] = blocks[k * r + l][a][b];
            hessian.add(dim * nodes[k] + a,
                        r * dim,
                        columns.data(),
                        row.data(),
                        false,
                        true);
          }
    });
  }



  template class CmpmInertiaTerm<2>;
  template class CmpmInertiaTerm<3>;
} // namespace bfemp
