#include <bfemp/base/parallel_sum.h>
#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/material/tangent_projection.h>
#include <bfemp/solver/determinant_bound.h>
#include <bfemp/solver/mpm_elasticity_term.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <array>
#include <vector>

namespace bfemp
{
  namespace
  {
    /**
     * What the potential needs of one particle: its stencil's unified
     * nodes (nodes without mass carry w = 0 and are skipped), g^_ip =
     * (F_p^n)^T grad w_ip, F_p^n, V_p^0 and the material.
     */
    template <int dim, int degree>
    struct ParticleStencil
    {
      using Kernel = KernelStencil<dim, degree>;
      using Layout = ParticleLayout<dim>;

      template <typename ParticleAccessor>
      ParticleStencil(const Lattice<dim>     &lattice,
                      const DofSpace<dim>    &dofs,
                      const ParticleAccessor &particle)
      {
        const auto properties = particle.get_properties();
        start_F  = Layout::get_tensor(properties, Layout::deformation_gradient);
        volume   = properties[Layout::rest_volume];
        material = static_cast<unsigned int>(properties[Layout::material_id]);
        kernel.reinit(lattice, particle.get_location());
        const Tensor<2, dim> start_F_transpose = transpose(start_F);
        for (unsigned int k = 0; k < Kernel::n_nodes; ++k)
          {
            const unsigned int node = dofs.grid_node(kernel.node[k]);
            if (node == DofSpace<dim>::invalid)
              continue;
            nodes[n]              = node;
            mapped_gradients[n++] = start_F_transpose * kernel.gradient[k];
          }
      }

      /** F_p(u) = F_p^n + sum_i u_i g^_ip^T (eq. 25 in displacements). */
      Tensor<2, dim>
      deformation_gradient(const Vector<double> &u) const
      {
        Tensor<2, dim> F = start_F;
        for (unsigned int k = 0; k < n; ++k)
          F +=
            outer_product(DofSpace<dim>::get(u, nodes[k]), mapped_gradients[k]);
        return F;
      }

      Kernel         kernel;
      unsigned int   n = 0;
      unsigned int   nodes[Kernel::n_nodes];
      Tensor<1, dim> mapped_gradients[Kernel::n_nodes];
      Tensor<2, dim> start_F;
      double         volume   = 0.;
      unsigned int   material = 0;
    };

    /**
     * The Hessian of the MPM elasticity (eq. 25) of the particles of one
     * cell: blocks H_kl = w_p sum_jd A_p[a][j][b][d] g^_kj g^_ld for the
     * stencil nodes k, l of each particle p, summed densely over the union
     * of the cell's stencils. dP/dF has major symmetry, so only blocks with
     * k <= l are formed; add_to() mirrors them, which also makes the
     * assembled matrix symmetric to the last bit.
     */
    template <int dim, int degree>
    struct CellHessian
    {
      using Stencil = ParticleStencil<dim, degree>;

      /**
       * Starts the cell of @p cell_particles. The buffers keep their
       * memory from cell to cell (one CellHessian per thread), so that
       * cells with few particles do not pay for allocations.
       */
      template <typename ParticleRange>
      void
      reinit(const Lattice<dim>  &lattice,
             const DofSpace<dim> &dofs,
             const ParticleRange &cell_particles)
      {
        stencils.clear();
        nodes.clear();
        for (const auto &particle : cell_particles)
          stencils.emplace_back(lattice, dofs, particle);
        for (const Stencil &s : stencils)
          nodes.insert(nodes.end(), s.nodes, s.nodes + s.n);
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        positions.resize(stencils.size() * Stencil::Kernel::n_nodes);
        for (unsigned int p = 0; p < stencils.size(); ++p)
          for (unsigned int k = 0; k < stencils[p].n; ++k)
            positions[p * Stencil::Kernel::n_nodes + k] =
              std::lower_bound(nodes.begin(),
                               nodes.end(),
                               stencils[p].nodes[k]) -
              nodes.begin();
        blocks.assign(nodes.size() * nodes.size(), Tensor<2, dim>());
      }

      /** Adds particle @p p's blocks with tangent @p A and weight s V_p^0. */
      void
      add_particle(const unsigned int    p,
                   const Tensor<4, dim> &A,
                   const double          weight)
      {
        const Stencil      &s     = stencils[p];
        const unsigned int *local = &positions[p * Stencil::Kernel::n_nodes];
        // A_k[a][b][d] = w sum_j A[a][j][b][d] g^_k[j]: the first
        // contraction, shared by all blocks of row node k.
        std::array<Tensor<3, dim>, Stencil::Kernel::n_nodes> A_k;
        for (unsigned int k = 0; k < s.n; ++k)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              for (unsigned int d = 0; d < dim; ++d)
                {
                  double sum = 0.;
                  for (unsigned int j = 0; j < dim; ++j)
                    sum += A[a][j][b][d] * s.mapped_gradients[k][j];
                  A_k[k][a][b][d] = weight * sum;
                }
        // Stencil nodes are sorted, so k <= l means local[k] <= local[l].
        for (unsigned int k = 0; k < s.n; ++k)
          for (unsigned int l = k; l < s.n; ++l)
            {
              Tensor<2, dim> &block =
                blocks[local[k] * nodes.size() + local[l]];
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  block[a][b] += A_k[k][a][b] * s.mapped_gradients[l];
            }
      }

      /** Adds the rows of all union nodes, the lower blocks mirrored. */
      void
      add_to(SparseMatrix<double> &hessian)
      {
        const std::size_t m = nodes.size();
        columns.resize(m * dim);
        values.resize(m * dim);
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int b = 0; b < dim; ++b)
            columns[dim * j + b] = dim * nodes[j] + b;
        // Union nodes that no particle couples have zero blocks, which
        // SparseMatrix::add accepts outside the pattern.
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int a = 0; a < dim; ++a)
            {
              for (unsigned int j = 0; j < m; ++j)
                for (unsigned int b = 0; b < dim; ++b)
                  values[dim * j + b] =
                    j >= i ? blocks[i * m + j][a][b] : blocks[j * m + i][b][a];
              hessian.add(dim * nodes[i] + a,
                          m * dim,
                          columns.data(),
                          values.data(),
                          false,
                          true);
            }
      }

      std::vector<Stencil> stencils;
      /** The union of the stencils' unified nodes, sorted. */
      std::vector<unsigned int> nodes;
      /** Index into nodes of stencil node k of particle p. */
      std::vector<unsigned int> positions;
      /** Block (i, j) of union nodes i <= j at i * nodes.size() + j. */
      std::vector<Tensor<2, dim>> blocks;
      /** One matrix row of the cell, as passed to SparseMatrix::add. */
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  values;
    };
  } // namespace

  template <int dim>
  MpmElasticityTerm<dim>::MpmElasticityTerm(
    const BackgroundGrid<dim>                         &grid,
    ParticleSystem<dim>                               &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const DofSpace<dim>                               &dofs)
    : grid(grid)
    , particles(particles)
    , materials(materials)
    , dofs(dofs)
  {}

  template <int dim>
  void
  MpmElasticityTerm<dim>::set_scale(const double s)
  {
    scale = s;
  }

  template <int dim>
  std::string
  MpmElasticityTerm<dim>::name() const
  {
    return "MPM elasticity";
  }

  template <int dim>
  template <int degree>
  void
  MpmElasticityTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    // Particles with the same stencil add the same clique; add each once.
    // Stencil nodes of particles in stripes two apart never coincide, so
    // the scattering loop may mark and fill rows without locks.
    std::vector<char> done(grid.lattice().n_nodes, 0);
    particles.for_each_scattering([&](const auto &particle) {
      const ParticleStencil<dim, degree> s(grid.lattice(), dofs, particle);
      const std::size_t                  first = s.kernel.node[0];
      if (done[first])
        return;
      done[first] = 1;
      const std::vector<unsigned int> clique(s.nodes, s.nodes + s.n);
      for (unsigned int k = 0; k < s.n; ++k)
        sparsity.add_row_entries(s.nodes[k], clique);
    });
  }

  template <int dim>
  template <int degree>
  double
  MpmElasticityTerm<dim>::value(const Vector<double> &u) const
  {
    return scale * particles.template sum<double>([&](const auto &particle) {
      const ParticleStencil<dim, degree> s(grid.lattice(), dofs, particle);
      const Tensor<2, dim>               F = s.deformation_gradient(u);
      if (!(determinant(F) > 0.))
        return std::numeric_limits<double>::infinity();
      return s.volume * materials[s.material]->energy_density(F);
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::magnitude() const
  {
    using Layout = ParticleLayout<dim>;
    return scale * particles.template sum<double>([&](const auto &particle) {
      const auto p = particle.get_properties();
      return p[Layout::rest_volume] *
             materials[static_cast<unsigned int>(p[Layout::material_id])]
               ->energy_scale();
    });
  }

  template <int dim>
  template <int degree>
  void
  MpmElasticityTerm<dim>::add_gradient(const Vector<double> &u,
                                       Vector<double>       &gradient) const
  {
    // dE/du_i = s V_p^0 P(F_p) g^_ip.
    particles.for_each_scattering([&](const auto &particle) {
      const ParticleStencil<dim, degree> s(grid.lattice(), dofs, particle);
      const Tensor<2, dim>               weighted_P =
        scale * s.volume *
        materials[s.material]->first_piola_kirchhoff(s.deformation_gradient(u));
      for (unsigned int k = 0; k < s.n; ++k)
        {
          const Tensor<1, dim> f = weighted_P * s.mapped_gradients[k];
          for (unsigned int c = 0; c < dim; ++c)
            gradient[dim * s.nodes[k] + c] += f[c];
        }
    });
  }

  template <int dim>
  template <int degree>
  void
  MpmElasticityTerm<dim>::add_hessian(const Vector<double> &u,
                                      SparseMatrix<double> &hessian,
                                      const HessianKind     kind) const
  {
    // The particles of one cell share most of their stencil nodes, so their
    // blocks are summed in a dense matrix over the union of the stencils and
    // each of its rows is added to the sparse matrix once per cell: a
    // sparse row add walks the whole matrix row, whatever the number of
    // entries added (per particle it was the dominant cost in 3D).
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      thread_local CellHessian<dim, degree> cell;
      cell.reinit(grid.lattice(), dofs, cell_particles);
      for (unsigned int p = 0; p < cell.stencils.size(); ++p)
        {
          const ParticleStencil<dim, degree> &s = cell.stencils[p];
          cell.add_particle(
            p,
            materials[s.material]->tangent(s.deformation_gradient(u),
                                           kind == HessianKind::projected),
            scale * s.volume);
        }
      cell.add_to(hessian);
    });
  }

  template <int dim>
  template <int degree>
  double
  MpmElasticityTerm<dim>::step_bound(const Vector<double> &u,
                                     const Vector<double> &p) const
  {
    // det F_p(u + t p) = det(F_p(u) + t sum_i p_i g^_ip^T): a polynomial
    // of degree dim in t.
    return particles
      .template sum<Minimum>([&](const auto &particle) {
        const ParticleStencil<dim, degree> s(grid.lattice(), dofs, particle);
        Tensor<2, dim>                     direction;
        for (unsigned int k = 0; k < s.n; ++k)
          direction += outer_product(DofSpace<dim>::get(p, s.nodes[k]),
                                     s.mapped_gradients[k]);
        Minimum m;
        m += determinant_step_bound<dim>(s.deformation_gradient(u), direction);
        return m;
      })
      .value;
  }

  template <int dim>
  template <int degree>
  double
  MpmElasticityTerm<dim>::minimum_determinant(const Vector<double> &u) const
  {
    return particles
      .template sum<Minimum>([&](const auto &particle) {
        const ParticleStencil<dim, degree> s(grid.lattice(), dofs, particle);
        Minimum                            m;
        m += determinant(s.deformation_gradient(u));
        return m;
      })
      .value;
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      add_couplings<decltype(degree)::value>(sparsity);
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::value(const Vector<double> &u) const
  {
    return dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      return value<decltype(degree)::value>(u);
    });
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::add_gradient(const Vector<double> &u,
                                       Vector<double>       &gradient) const
  {
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      add_gradient<decltype(degree)::value>(u, gradient);
    });
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::add_hessian(const Vector<double> &u,
                                      SparseMatrix<double> &hessian,
                                      const HessianKind     kind) const
  {
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      add_hessian<decltype(degree)::value>(u, hessian, kind);
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::step_bound(const Vector<double> &u,
                                     const Vector<double> &p) const
  {
    return dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      return step_bound<decltype(degree)::value>(u, p);
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::minimum_determinant(const Vector<double> &u) const
  {
    return dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      return minimum_determinant<decltype(degree)::value>(u);
    });
  }

  template class MpmElasticityTerm<2>;
  template class MpmElasticityTerm<3>;
} // namespace bfemp
