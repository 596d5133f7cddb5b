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
     * What the potential needs of one particle on the B-spline grid (the
     * scalar case of the particle-to-unknowns map, N_ip = w_ip I): its
     * stencil's unified nodes (nodes without mass carry w = 0 and are
     * skipped), g^_ip = (F_p^n)^T grad w_ip, so that dF_p/du_i = e_c g^_ip^T
     * per component c, F_p^n, V_p^0 and the material.
     */
    template <int dim, int degree>
    struct ParticleStencil
    {
      using Kernel                            = KernelStencil<dim, degree>;
      using Layout                            = ParticleLayout<dim>;
      static constexpr unsigned int max_nodes = Kernel::n_nodes;

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

      /** Particles with the same key have the same nodes (couplings). */
      std::size_t
      key() const
      {
        return kernel.node[0];
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

      /** dF_p along the nodal direction p. */
      Tensor<2, dim>
      direction(const Vector<double> &p) const
      {
        Tensor<2, dim> dF;
        for (unsigned int k = 0; k < n; ++k)
          dF +=
            outer_product(DofSpace<dim>::get(p, nodes[k]), mapped_gradients[k]);
        return dF;
      }

      /** dE/du_k for the weighted stress P: P g^_k. */
      Tensor<1, dim>
      force(const unsigned int k, const Tensor<2, dim> &P) const
      {
        return P * mapped_gradients[k];
      }

      /** A_k[a][b][d] = w sum_j A[a][j][b][d] g^_k[j]: the first contraction
       *  of the Hessian blocks of row node k. */
      Tensor<3, dim>
      first_contraction(const unsigned int    k,
                        const Tensor<4, dim> &A,
                        const double          weight) const
      {
        Tensor<3, dim> A_k;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int d = 0; d < dim; ++d)
              {
                double sum = 0.;
                for (unsigned int j = 0; j < dim; ++j)
                  sum += A[a][j][b][d] * mapped_gradients[k][j];
                A_k[a][b][d] = weight * sum;
              }
        return A_k;
      }

      /** Adds the block of nodes (k, l) from k's first contraction. */
      void
      add_block(const Tensor<3, dim> &A_k,
                const unsigned int    l,
                Tensor<2, dim>       &block) const
      {
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            block[a][b] += A_k[a][b] * mapped_gradients[l];
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
     * The same for cMPM (seed 002), the matrix-valued case of the
     * particle-to-unknowns map: u_p = sum_I Phi_I Q_I, so
     * F_p(u) = (I + sum_I grad(Phi_I u_I)) F_p^n and
     * dF_ab/du_Ic = D_I[a][b][c] = sum_e d(Phi_I)_ac/dx_e (F_p^n)_eb.
     */
    template <int dim>
    struct CmpmParticleStencil
    {
      using Layout                            = ParticleLayout<dim>;
      static constexpr unsigned int max_nodes = dim == 2 ? 25 : 125;

      template <typename ParticleAccessor>
      CmpmParticleStencil(const CmpmDiscretization<dim> &cmpm,
                          const DofSpace<dim>           &dofs,
                          const ParticleAccessor        &particle)
      {
        const auto properties = particle.get_properties();
        start_F  = Layout::get_tensor(properties, Layout::deformation_gradient);
        volume   = properties[Layout::rest_volume];
        material = static_cast<unsigned int>(properties[Layout::material_id]);
        thread_local std::vector<CoarseShapeValue<dim>> values;
        cmpm.evaluate(particle.get_location(), values);
        first_node = values.front().node;
        nodes.reserve(values.size());
        D.reserve(values.size());
        for (const CoarseShapeValue<dim> &value : values)
          {
            const unsigned int node = dofs.grid_node(value.node);
            if (node == DofSpace<dim>::invalid)
              continue;
            Tensor<3, dim> D_I;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const Tensor<1, dim> g =
                    transpose(start_F) * value.gradient[a][c];
                  for (unsigned int b = 0; b < dim; ++b)
                    D_I[a][b][c] = g[b];
                }
            nodes.push_back(node);
            D.push_back(D_I);
          }
        n = nodes.size();
      }

      std::size_t
      key() const
      {
        return first_node;
      }

      Tensor<2, dim>
      deformation_gradient(const Vector<double> &u) const
      {
        return start_F + direction(u);
      }

      Tensor<2, dim>
      direction(const Vector<double> &p) const
      {
        Tensor<2, dim> dF;
        for (unsigned int k = 0; k < n; ++k)
          dF += D[k] * DofSpace<dim>::get(p, nodes[k]);
        return dF;
      }

      /** f_c = sum_ab P_ab D_k[a][b][c]. */
      Tensor<1, dim>
      force(const unsigned int k, const Tensor<2, dim> &P) const
      {
        Tensor<1, dim> f;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            f += P[a][b] * D[k][a][b];
        return f;
      }

      /** A_k[c][a'][b'] = w sum_ab D_k[a][b][c] A[a][b][a'][b']. */
      Tensor<3, dim>
      first_contraction(const unsigned int    k,
                        const Tensor<4, dim> &A,
                        const double          weight) const
      {
        Tensor<3, dim> A_k;
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              if (D[k][a][b][c] != 0.)
                A_k[c] += (weight * D[k][a][b][c]) * A[a][b];
        return A_k;
      }

      /** block[c][d] += sum_ab A_k[c][a][b] D_l[a][b][d]. */
      void
      add_block(const Tensor<3, dim> &A_k,
                const unsigned int    l,
                Tensor<2, dim>       &block) const
      {
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              block[c] += A_k[c][a][b] * D[l][a][b];
      }

      std::size_t                 first_node = 0;
      unsigned int                n          = 0;
      std::vector<unsigned int>   nodes;
      std::vector<Tensor<3, dim>> D;
      Tensor<2, dim>              start_F;
      double                      volume   = 0.;
      unsigned int                material = 0;
    };



    /**
     * The Hessian of the MPM elasticity (eq. 25) of the particles of one
     * cell: blocks H_kl = w_p dF/du_k : A_p : dF/du_l for the stencil nodes
     * k, l of each particle p, summed densely over the union of the cell's
     * stencils. dP/dF has major symmetry, so only blocks with k <= l are
     * formed; add_to() mirrors them, which also makes the assembled matrix
     * symmetric to the last bit. Stencil is ParticleStencil (B-spline
     * kernel) or CmpmParticleStencil.
     */
    template <int dim, typename Stencil>
    struct CellHessian
    {
      /**
       * Starts the cell of @p cell_particles. The buffers keep their
       * memory from cell to cell (one CellHessian per thread), so that
       * cells with few particles do not pay for allocations.
       */
      template <typename MakeStencil, typename ParticleRange>
      void
      reinit(const MakeStencil   &make_stencil,
             const ParticleRange &cell_particles)
      {
        stencils.clear();
        nodes.clear();
        for (const auto &particle : cell_particles)
          stencils.push_back(make_stencil(particle));
        for (const Stencil &s : stencils)
          nodes.insert(nodes.end(),
                       std::begin(s.nodes),
                       std::begin(s.nodes) + s.n);
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        positions.resize(stencils.size() * Stencil::max_nodes);
        for (unsigned int p = 0; p < stencils.size(); ++p)
          for (unsigned int k = 0; k < stencils[p].n; ++k)
            positions[p * Stencil::max_nodes + k] =
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
        const unsigned int *local = &positions[p * Stencil::max_nodes];
        // the first contraction, shared by all blocks of row node k
        A_k.resize(s.n);
        for (unsigned int k = 0; k < s.n; ++k)
          A_k[k] = s.first_contraction(k, A, weight);
        // Stencil nodes are sorted, so k <= l means local[k] <= local[l].
        for (unsigned int k = 0; k < s.n; ++k)
          for (unsigned int l = k; l < s.n; ++l)
            s.add_block(A_k[k], l, blocks[local[k] * nodes.size() + local[l]]);
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
      std::vector<Tensor<3, dim>> A_k;
      /** One matrix row of the cell, as passed to SparseMatrix::add. */
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  values;
    };



    /** Builds the B-spline stencil of a particle. */
    template <int dim, int degree>
    struct KernelStencilMaker
    {
      using Stencil = ParticleStencil<dim, degree>;

      template <typename ParticleAccessor>
      Stencil
      operator()(const ParticleAccessor &particle) const
      {
        return Stencil(lattice, dofs, particle);
      }

      /** The range of Stencil::key(). */
      std::size_t
      n_keys() const
      {
        return lattice.n_nodes;
      }

      const Lattice<dim>  &lattice;
      const DofSpace<dim> &dofs;
    };



    /** Builds the cMPM stencil of a particle. */
    template <int dim>
    struct CmpmStencilMaker
    {
      using Stencil = CmpmParticleStencil<dim>;

      template <typename ParticleAccessor>
      Stencil
      operator()(const ParticleAccessor &particle) const
      {
        return Stencil(cmpm, dofs, particle);
      }

      std::size_t
      n_keys() const
      {
        return cmpm.node_lattice().n_nodes;
      }

      const CmpmDiscretization<dim> &cmpm;
      const DofSpace<dim>           &dofs;
    };
  } // namespace

  template <int dim>
  MpmElasticityTerm<dim>::MpmElasticityTerm(
    const BackgroundGrid<dim>                         &grid,
    ParticleSystem<dim>                               &particles,
    const std::vector<std::unique_ptr<Material<dim>>> &materials,
    const DofSpace<dim>                               &dofs,
    const CmpmDiscretization<dim>                     *cmpm)
    : grid(grid)
    , particles(particles)
    , materials(materials)
    , dofs(dofs)
    , cmpm(cmpm)
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
  template <typename Function>
  decltype(auto)
  MpmElasticityTerm<dim>::with_stencil(const Function &f) const
  {
    // The particle-to-unknowns map: cMPM's matrix-valued Phi or the grid's
    // B-spline kernel. Everything below is written once for both.
    if (cmpm != nullptr)
      return f(CmpmStencilMaker<dim>{*cmpm, dofs});
    return dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      return f(
        KernelStencilMaker<dim, decltype(degree)::value>{grid.lattice(), dofs});
    });
  }

  template <int dim>
  template <typename Maker>
  void
  MpmElasticityTerm<dim>::add_couplings(const Maker  &make_stencil,
                                        NodeSparsity &sparsity) const
  {
    // Particles with the same stencil add the same clique; add each once.
    // Stencil nodes of particles in stripes two apart never coincide, so
    // the scattering loop may mark and fill rows without locks.
    std::vector<char> done(make_stencil.n_keys(), 0);
    particles.for_each_scattering([&](const auto &particle) {
      const auto        s     = make_stencil(particle);
      const std::size_t first = s.key();
      if (done[first])
        return;
      done[first] = 1;
      const std::vector<unsigned int> clique(std::begin(s.nodes),
                                             std::begin(s.nodes) + s.n);
      for (unsigned int k = 0; k < s.n; ++k)
        sparsity.add_row_entries(s.nodes[k], clique);
    });
  }

  template <int dim>
  template <typename Maker>
  double
  MpmElasticityTerm<dim>::value(const Maker          &make_stencil,
                                const Vector<double> &u) const
  {
    return scale * particles.template sum<double>([&](const auto &particle) {
      const auto           s = make_stencil(particle);
      const Tensor<2, dim> F = s.deformation_gradient(u);
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
  template <typename Maker>
  void
  MpmElasticityTerm<dim>::add_gradient(const Maker          &make_stencil,
                                       const Vector<double> &u,
                                       Vector<double>       &gradient) const
  {
    // dE/du_k = s V_p^0 P(F_p) : dF_p/du_k.
    particles.for_each_scattering([&](const auto &particle) {
      const auto           s = make_stencil(particle);
      const Tensor<2, dim> weighted_P =
        scale * s.volume *
        materials[s.material]->first_piola_kirchhoff(s.deformation_gradient(u));
      for (unsigned int k = 0; k < s.n; ++k)
        {
          const Tensor<1, dim> f = s.force(k, weighted_P);
          for (unsigned int c = 0; c < dim; ++c)
            gradient[dim * s.nodes[k] + c] += f[c];
        }
    });
  }

  template <int dim>
  template <typename Maker>
  void
  MpmElasticityTerm<dim>::add_hessian(const Maker          &make_stencil,
                                      const Vector<double> &u,
                                      SparseMatrix<double> &hessian,
                                      const HessianKind     kind) const
  {
    // The particles of one cell share most of their stencil nodes, so their
    // blocks are summed in a dense matrix over the union of the stencils and
    // each of its rows is added to the sparse matrix once per cell: a
    // sparse row add walks the whole matrix row, whatever the number of
    // entries added (per particle it was the dominant cost in 3D).
    using Stencil = typename Maker::Stencil;
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      thread_local CellHessian<dim, Stencil> cell;
      cell.reinit(make_stencil, cell_particles);
      for (unsigned int p = 0; p < cell.stencils.size(); ++p)
        {
          const Stencil &s = cell.stencils[p];
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
  template <typename Maker>
  double
  MpmElasticityTerm<dim>::step_bound(const Maker          &make_stencil,
                                     const Vector<double> &u,
                                     const Vector<double> &p) const
  {
    // det F_p(u + t p) = det(F_p(u) + t dF_p(p)): F_p is linear in u, so a
    // polynomial of degree dim in t.
    return particles
      .template sum<Minimum>([&](const auto &particle) {
        const auto s = make_stencil(particle);
        Minimum    m;
        m += determinant_step_bound<dim>(s.deformation_gradient(u),
                                         s.direction(p));
        return m;
      })
      .value;
  }

  template <int dim>
  template <typename Maker>
  double
  MpmElasticityTerm<dim>::minimum_determinant(const Maker &make_stencil,
                                              const Vector<double> &u) const
  {
    return particles
      .template sum<Minimum>([&](const auto &particle) {
        Minimum m;
        m += determinant(make_stencil(particle).deformation_gradient(u));
        return m;
      })
      .value;
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    with_stencil([&](const auto &make) { add_couplings(make, sparsity); });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::value(const Vector<double> &u) const
  {
    return with_stencil([&](const auto &make) { return value(make, u); });
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::add_gradient(const Vector<double> &u,
                                       Vector<double>       &gradient) const
  {
    with_stencil([&](const auto &make) { add_gradient(make, u, gradient); });
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::add_hessian(const Vector<double> &u,
                                      SparseMatrix<double> &hessian,
                                      const HessianKind     kind) const
  {
    with_stencil(
      [&](const auto &make) { add_hessian(make, u, hessian, kind); });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::step_bound(const Vector<double> &u,
                                     const Vector<double> &p) const
  {
    return with_stencil(
      [&](const auto &make) { return step_bound(make, u, p); });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::minimum_determinant(const Vector<double> &u) const
  {
    return with_stencil(
      [&](const auto &make) { return minimum_determinant(make, u); });
  }

  template class MpmElasticityTerm<2>;
  template class MpmElasticityTerm<3>;
} // namespace bfemp
