#include <bfemp/base/parallel_sum.h>
#include <bfemp/cmpm/element_assembly.h>
#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/material/tangent_projection.h>
#include <bfemp/solver/determinant_bound.h>
#include <bfemp/solver/mpm_elasticity_term.h>
#include <bfemp/solver/node_blocks.h>
#include <bfemp/solver/particle_block_kernels.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <array>
#include <vector>

namespace bfemp
{
  namespace
  {
    /** The displacement of node @p node in the field @p u: unified nodes
     *  of the unknowns, or an element's fine nodes (cMPM). */
    template <int dim>
    Tensor<1, dim>
    nodal(const Vector<double> &u, const unsigned int node)
    {
      return DofSpace<dim>::get(u, node);
    }

    template <int dim>
    const Tensor<1, dim> &
    nodal(const std::vector<Tensor<1, dim>> &u, const unsigned int node)
    {
      return u[node];
    }



    /**
     * What the potential needs of one particle whose displacement is a sum
     * of scalar functions times nodal values, u_p = sum_i w_ip u_i (the
     * scalar case of the particle-to-unknowns map, N_ip = w_ip I): the
     * stencil's nodes, g^_ip = (F_p^n)^T grad w_ip, so that
     * dF_p/du_i = e_c g^_ip^T per component c, F_p^n, V_p^0 and the
     * material. The nodes are unified nodes (the B-spline grid) or the fine
     * nodes of a cMPM element, whose values are then q = p Q
     * (CmpmElementAssembly).
     */
    template <int dim, unsigned int max_n>
    struct ScalarStencil
    {
      using Layout                            = ParticleLayout<dim>;
      static constexpr unsigned int max_nodes = max_n;

      template <typename ParticleAccessor>
      void
      set_particle(const ParticleAccessor &particle)
      {
        const auto properties = particle.get_properties();
        start_F  = Layout::get_tensor(properties, Layout::deformation_gradient);
        volume   = properties[Layout::rest_volume];
        material = static_cast<unsigned int>(properties[Layout::material_id]);
      }

      /** Adds node @p node with kernel weight @p weight and gradient
       *  @p gradient. */
      void
      add_node(const unsigned int    node,
               const double          weight,
               const Tensor<1, dim> &gradient)
      {
        nodes[n]              = node;
        weights[n]            = weight;
        mapped_gradients[n++] = transpose(start_F) * gradient;
      }

      /** sum_i w_ip p_i: the particle's displacement along p. */
      template <typename Field>
      Tensor<1, dim>
      displacement(const Field &p) const
      {
        Tensor<1, dim> u_p;
        for (unsigned int k = 0; k < n; ++k)
          u_p += weights[k] * nodal<dim>(p, nodes[k]);
        return u_p;
      }

      /** F_p(u) = F_p^n + sum_i u_i g^_ip^T (eq. 25 in displacements). */
      template <typename Field>
      Tensor<2, dim>
      deformation_gradient(const Field &u) const
      {
        Tensor<2, dim> F = start_F;
        for (unsigned int k = 0; k < n; ++k)
          F += outer_product(nodal<dim>(u, nodes[k]), mapped_gradients[k]);
        return F;
      }

      /** dF_p along the nodal direction p. */
      template <typename Field>
      Tensor<2, dim>
      direction(const Field &p) const
      {
        Tensor<2, dim> dF;
        for (unsigned int k = 0; k < n; ++k)
          dF += outer_product(nodal<dim>(p, nodes[k]), mapped_gradients[k]);
        return dF;
      }

      /** dE/du_k for the weighted stress P: P g^_k. */
      Tensor<1, dim>
      force(const unsigned int k, const Tensor<2, dim> &P) const
      {
        return P * mapped_gradients[k];
      }

      unsigned int   n = 0;
      unsigned int   nodes[max_n];
      double         weights[max_n];
      Tensor<1, dim> mapped_gradients[max_n];
      Tensor<2, dim> start_F;
      double         volume   = 0.;
      unsigned int   material = 0;
    };



    /** A particle on the B-spline grid: the kernel's nodes that are
     *  unknowns (nodes without mass carry w = 0 and are skipped). */
    template <int dim, int degree>
    struct ParticleStencil
      : ScalarStencil<dim, KernelStencil<dim, degree>::n_nodes>
    {
      using Kernel = KernelStencil<dim, degree>;

      template <typename ParticleAccessor>
      ParticleStencil(const Lattice<dim>     &lattice,
                      const DofSpace<dim>    &dofs,
                      const ParticleAccessor &particle)
      {
        this->set_particle(particle);
        kernel.reinit(lattice, particle.get_location());
        for (unsigned int k = 0; k < Kernel::n_nodes; ++k)
          {
            const unsigned int node = dofs.grid_node(kernel.node[k]);
            if (node != DofSpace<dim>::invalid)
              this->add_node(node, kernel.weight[k], kernel.gradient[k]);
          }
      }

      /** Particles with the same key have the same nodes (couplings). */
      std::size_t
      key() const
      {
        return kernel.node[0];
      }

      Kernel kernel;
    };



    /**
     * A particle of a cMPM element on the element's fine patch: its 3^dim
     * fine functions B_k, whose nodal values are the element's fine control
     * values q = p Q (Phi_I = sum_k B_k p_kI, seed 002 eq. 15), so that
     * F_p(u) = (I + sum_I grad(Phi_I u_I)) F_p^n = F_p^n + sum_k q_k g^_k^T.
     */
    template <int dim>
    struct FineParticleStencil : ScalarStencil<dim, CoarseGrid<dim>::n_stencil>
    {
      template <typename ParticleAccessor>
      FineParticleStencil(const CmpmElementAssembly<dim> &element,
                          const ParticleAccessor         &particle)
      {
        this->set_particle(particle);
        typename CoarseGrid<dim>::FineStencil fine;
        element.fine_stencil(particle.get_location(), fine);
        for (unsigned int k = 0; k < CoarseGrid<dim>::n_stencil; ++k)
          this->add_node(fine.node[k], fine.value[k], fine.gradient[k]);
      }
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
        for (const auto &particle : cell_particles)
          stencils.push_back(make_stencil(particle));
        // The particles of a cell share a few distinct stencils (8 of 27
        // with three particles per direction and quadratic B-splines; one
        // per knot span, 125 of 1000 particles, on a cMPM element): group
        // them first, so that the union, the positions and the couplings
        // below are formed per group, not per particle (sorting the nodes
        // of all of a cMPM element's particles was 4 % of its step).
        n_groups = 0;
        for (unsigned int p = 0; p < stencils.size(); ++p)
          {
            const Stencil &s      = stencils[p];
            const auto same_nodes = [&](const std::vector<unsigned int> &g) {
              const Stencil &t = stencils[g[0]];
              return t.n == s.n && std::equal(std::begin(s.nodes),
                                              std::begin(s.nodes) + s.n,
                                              std::begin(t.nodes));
            };
            const auto group = std::find_if(groups.begin(),
                                            groups.begin() + n_groups,
                                            same_nodes);
            if (group != groups.begin() + n_groups)
              {
                group->push_back(p);
                continue;
              }
            if (groups.size() == n_groups)
              groups.emplace_back();
            groups[n_groups].assign(1, p);
            ++n_groups;
          }
        nodes.clear();
        for (unsigned int g = 0; g < n_groups; ++g)
          {
            const Stencil &s = stencils[groups[g][0]];
            nodes.insert(nodes.end(),
                         std::begin(s.nodes),
                         std::begin(s.nodes) + s.n);
          }
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        // Only the union node pairs a stencil couples are marked, and only
        // their blocks are zeroed: the others are never read (add_to(),
        // CoarsenedShapeFunctions::condense()). On a cMPM element the
        // union has up to 7^3 nodes and these are a fifth of its m^2
        // blocks (zeroing all 8.5 MB of them was 3 % of the step).
        const std::size_t m = nodes.size();
        positions.resize(stencils.size() * Stencil::max_nodes);
        blocks.resize(m * m);
        coupled.assign(m * m, 0);
        for (unsigned int g = 0; g < n_groups; ++g)
          {
            const unsigned int p     = groups[g][0];
            unsigned int      *local = &positions[p * Stencil::max_nodes];
            for (unsigned int k = 0; k < stencils[p].n; ++k)
              local[k] = std::lower_bound(nodes.begin(),
                                          nodes.end(),
                                          stencils[p].nodes[k]) -
                         nodes.begin();
            for (unsigned int k = 0; k < stencils[p].n; ++k)
              for (unsigned int l = k; l < stencils[p].n; ++l)
                {
                  const std::size_t ij = local[k] * m + local[l];
                  if (coupled[ij] == 0)
                    blocks[ij] = Tensor<2, dim>();
                  coupled[ij] = 1;
                }
          }
        // the kernels' layout: node data by component
        // (particle_block_kernels.h)
        gradients.assign(stencils.size() * dim * L, 0.);
        for (unsigned int p = 0; p < stencils.size(); ++p)
          for (unsigned int l = 0; l < stencils[p].n; ++l)
            for (unsigned int d = 0; d < dim; ++d)
              gradients[(p * dim + d) * L + l] =
                stencils[p].mapped_gradients[l][d];
        contractions.resize(stencils.size() * dim * dim * dim * L);
      }

      /** Sets particle @p p's tangent @p A and weight s V_p^0: the first
       *  contractions of its blocks (sum_blocks() adds them). */
      void
      add_particle(const unsigned int    p,
                   const Tensor<4, dim> &A,
                   const double          weight)
      {
        first_contractions<dim>(A.begin_raw(),
                                weight,
                                &gradients[p * dim * L],
                                L,
                                &contractions[p * dim * dim * dim * L]);
      }

      /**
       * Sums the blocks of all particles, group by group: each block row of
       * a group's stencil gathers its particles' terms in registers
       * (sum_block_row, several columns at once) before it is added to the
       * union's blocks, so that each block is written once per group.
       */
      void
      sum_blocks()
      {
        constexpr unsigned int W = particle_block_width;
        const std::size_t      m = nodes.size();
        row.resize(dim * dim * L);
        for (unsigned int g = 0; g < n_groups; ++g)
          {
            const std::vector<unsigned int> &members = groups[g];
            const unsigned int               n       = stencils[members[0]].n;
            const unsigned int              *local =
              &positions[members[0] * Stencil::max_nodes];
            member_gradients.resize(members.size());
            member_contractions.resize(members.size());
            for (unsigned int i = 0; i < members.size(); ++i)
              member_gradients[i] = &gradients[members[i] * dim * L];
            for (unsigned int k = 0; k < n; ++k)
              {
                for (unsigned int i = 0; i < members.size(); ++i)
                  member_contractions[i] =
                    &contractions[members[i] * dim * dim * dim * L + k];
                // from the columns' vector that holds l = k: blocks k <= l
                sum_block_row<dim>(member_contractions.data(),
                                   member_gradients.data(),
                                   members.size(),
                                   L,
                                   k / W * W,
                                   row.data());
                // Stencil nodes are sorted: k <= l means local[k] <= local[l].
                for (unsigned int l = k; l < n; ++l)
                  {
                    Tensor<2, dim> &block = blocks[local[k] * m + local[l]];
                    for (unsigned int a = 0; a < dim; ++a)
                      for (unsigned int b = 0; b < dim; ++b)
                        block[a][b] += row[(a * dim + b) * L + l];
                  }
              }
          }
      }

      /** Adds the coupled blocks of the union nodes, the lower ones
       *  mirrored (union nodes of different stencils need not couple, nor
       *  be in the pattern together). */
      void
      add_to(SparseMatrix<double> &hessian) const
      {
        const std::size_t m = nodes.size();
        add_node_blocks<dim>(
          nodes,
          [&](const unsigned int i, const unsigned int j) {
            return j >= i ? coupled[i * m + j] : coupled[j * m + i];
          },
          [&](const unsigned int i, const unsigned int j) {
            return j >= i ? blocks[i * m + j] : transpose(blocks[j * m + i]);
          },
          hessian);
      }

      std::vector<Stencil> stencils;
      /** The union of the stencils' unified nodes, sorted. */
      std::vector<unsigned int> nodes;
      /** Index into nodes of stencil node k of particle p, for the first
       *  particle p of each group. */
      std::vector<unsigned int> positions;
      /** Block (i, j) of union nodes i <= j at i * nodes.size() + j;
       *  set only where coupled. */
      std::vector<Tensor<2, dim>> blocks;
      /** Whether a stencil couples union nodes i <= j, at i * nodes.size()
       *  + j. */
      std::vector<char> coupled;
      /** The particles of each distinct stencil of the cell (the first
       *  n_groups entries; the vectors keep their memory). */
      std::vector<std::vector<unsigned int>> groups;
      unsigned int                           n_groups = 0;
      /** The kernels' row length: Stencil::max_nodes rounded up to
       *  particle_block_width. */
      static constexpr unsigned int L =
        (Stencil::max_nodes + particle_block_width - 1) / particle_block_width *
        particle_block_width;
      /** Particle p's mapped gradients from p dim L and its first
       *  contractions from p dim^3 L (particle_block_kernels.h). */
      std::vector<double> gradients;
      std::vector<double> contractions;
      /** sum_blocks()'s buffers: a group's particles' data, one block
       *  row. */
      std::vector<const double *> member_gradients;
      std::vector<const double *> member_contractions;
      std::vector<double>         row;
    };



    /** The B-spline stencil of a particle: from the step's cache
     *  (MpmElasticityTerm::begin_step()), or computed. */
    template <int dim, int degree>
    struct KernelStencilMaker
    {
      using Stencil = ScalarStencil<dim, KernelStencil<dim, degree>::n_nodes>;

      template <typename ParticleAccessor>
      Stencil
      operator()(const ParticleAccessor &particle) const
      {
        if (cache != nullptr)
          {
            AssertIndexRange(particle.get_local_index(), cache->size());
            return (*cache)[particle.get_local_index()];
          }
        return kernel_stencil(particle);
      }

      /** The stencil with its kernel (and key()), computed. */
      template <typename ParticleAccessor>
      ParticleStencil<dim, degree>
      kernel_stencil(const ParticleAccessor &particle) const
      {
        return ParticleStencil<dim, degree>(lattice, dofs, particle);
      }

      /** The range of Stencil::key(). */
      std::size_t
      n_keys() const
      {
        return lattice.n_nodes;
      }

      const Lattice<dim>  &lattice;
      const DofSpace<dim> &dofs;
      /** The stencils by the particles' local index, or nullptr. */
      const std::vector<Stencil> *cache;
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
  MpmElasticityTerm<dim>::with_kernel(const Function &f) const
  {
    return dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      using Maker = KernelStencilMaker<dim, decltype(degree)::value>;
      return f(Maker{grid.lattice(),
                     dofs,
                     static_cast<const std::vector<typename Maker::Stencil> *>(
                       stencil_cache.get())});
    });
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::begin_step()
  {
    stencil_cache.reset();
    if (cmpm != nullptr)
      return;
    with_kernel([&](const auto &make_stencil) {
      using Stencil = typename std::decay_t<decltype(make_stencil)>::Stencil;
      auto cache    = std::make_shared<std::vector<Stencil>>(
        particles.handler().get_max_local_particle_index());
      particles.for_each([&](const auto &particle) {
        (*cache)[particle.get_local_index()] = make_stencil(particle);
      });
      stencil_cache = cache;
    });
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::end_step()
  {
    stencil_cache.reset();
  }

  template <int dim>
  template <typename Function>
  void
  MpmElasticityTerm<dim>::for_each_element(const Vector<double> &u,
                                           const Function       &f) const
  {
    particles.for_each_cell_scattering([&](const auto &cell_particles) {
      const CmpmElementAssembly<dim>
        element(*cmpm, dofs, cell_particles.begin()->get_location());
      thread_local std::vector<Tensor<1, dim>> q;
      element.gather(u, q);
      f(element, q, cell_particles);
    });
  }

  template <int dim>
  template <typename Result, typename Function>
  Result
  MpmElasticityTerm<dim>::sum_over_elements(const Vector<double> &u,
                                            const Function       &f) const
  {
    return particles.template sum_over_cells<Result>(
      [&](const auto &cell_particles) {
        const CmpmElementAssembly<dim>
          element(*cmpm, dofs, cell_particles.begin()->get_location());
        thread_local std::vector<Tensor<1, dim>> q;
        element.gather(u, q);
        Result result = Result();
        for (const auto &particle : cell_particles)
          result += f(FineParticleStencil<dim>(element, particle), q);
        return result;
      });
  }

  template <int dim>
  template <typename Stencil, typename Field>
  double
  MpmElasticityTerm<dim>::particle_energy(const Stencil &s,
                                          const Field   &u) const
  {
    const Tensor<2, dim> F = s.deformation_gradient(u);
    if (!(determinant(F) > 0.))
      return std::numeric_limits<double>::infinity();
    return s.volume * materials[s.material]->energy_density(F);
  }

  template <int dim>
  template <typename Stencil, typename Field, typename Sink>
  void
  MpmElasticityTerm<dim>::add_particle_forces(const Stencil &s,
                                              const Field   &u,
                                              const Sink    &sink) const
  {
    // dE/du_k = s V_p^0 P(F_p) : dF_p/du_k.
    const Tensor<2, dim> weighted_P =
      scale * s.volume *
      materials[s.material]->first_piola_kirchhoff(s.deformation_gradient(u));
    for (unsigned int k = 0; k < s.n; ++k)
      sink(s.nodes[k], s.force(k, weighted_P));
  }

  template <int dim>
  template <typename Cell, typename Field>
  void
  MpmElasticityTerm<dim>::add_particle_blocks(Cell             &cell,
                                              const Field      &u,
                                              const HessianKind kind) const
  {
    for (unsigned int p = 0; p < cell.stencils.size(); ++p)
      {
        const auto &s = cell.stencils[p];
        cell.add_particle(
          p,
          materials[s.material]->tangent(s.deformation_gradient(u),
                                         eigenvalue_filter(kind)),
          scale * s.volume);
      }
    cell.sum_blocks();
  }

  template <int dim>
  void
  MpmElasticityTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    if (cmpm != nullptr)
      {
        // every particle of a cMPM element couples all its unknowns
        particles.for_each_cell_scattering([&](const auto &cell_particles) {
          const CmpmElementAssembly<dim>
            element(*cmpm, dofs, cell_particles.begin()->get_location());
          for (const unsigned int node : element.unknowns())
            sparsity.add_row_entries(node, element.unknowns());
        });
        return;
      }
    with_kernel([&](const auto &make_stencil) {
      // Particles with the same stencil add the same clique; add each once.
      // Stencil nodes of particles in stripes two apart never coincide, so
      // the scattering loop may mark and fill rows without locks.
      std::vector<char> done(make_stencil.n_keys(), 0);
      particles.for_each_scattering([&](const auto &particle) {
        const auto        s     = make_stencil.kernel_stencil(particle);
        const std::size_t first = s.key();
        if (done[first])
          return;
        done[first] = 1;
        const std::vector<unsigned int> clique(std::begin(s.nodes),
                                               std::begin(s.nodes) + s.n);
        for (unsigned int k = 0; k < s.n; ++k)
          sparsity.add_row_entries(s.nodes[k], clique);
      });
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::value(const Vector<double> &u) const
  {
    if (cmpm != nullptr)
      return scale *
             sum_over_elements<double>(u, [&](const auto &s, const auto &q) {
               return particle_energy(s, q);
             });
    return with_kernel([&](const auto &make_stencil) {
      return scale * particles.template sum<double>([&](const auto &particle) {
        return particle_energy(make_stencil(particle), u);
      });
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
  void
  MpmElasticityTerm<dim>::add_gradient(const Vector<double> &u,
                                       Vector<double>       &gradient) const
  {
    const auto add_to_gradient = [&](const unsigned int    node,
                                     const Tensor<1, dim> &f) {
      for (unsigned int c = 0; c < dim; ++c)
        gradient[dim * node + c] += f[c];
    };
    if (cmpm != nullptr)
      {
        // the particles' forces on the element's fine nodes, condensed
        // to the coarse nodes once per element (f_alpha = p^T f)
        for_each_element(
          u,
          [&](const auto &element, const auto &q, const auto &cell_particles) {
            thread_local std::vector<Tensor<1, dim>> fine_forces;
            fine_forces.assign(element.n_fine(), Tensor<1, dim>());
            for (const auto &particle : cell_particles)
              add_particle_forces(FineParticleStencil<dim>(element, particle),
                                  q,
                                  [&](const unsigned int    k,
                                      const Tensor<1, dim> &f) {
                                    fine_forces[k] += f;
                                  });
            element.add_forces(fine_forces, gradient);
          });
        return;
      }
    with_kernel([&](const auto &make_stencil) {
      particles.for_each_scattering([&](const auto &particle) {
        add_particle_forces(make_stencil(particle), u, add_to_gradient);
      });
    });
  }

  template <int dim>
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
    if (cmpm != nullptr)
      {
        // on the element's fine patch, condensed once per element
        // (K_alpha = p^T K p)
        for_each_element(
          u,
          [&](const auto &element, const auto &q, const auto &cell_particles) {
            thread_local CellHessian<dim, FineParticleStencil<dim>> cell;
            cell.reinit(
              [&](const auto &particle) {
                return FineParticleStencil<dim>(element, particle);
              },
              cell_particles);
            add_particle_blocks(cell, q, kind);
            element.add_stiffness(cell.nodes,
                                  cell.blocks,
                                  cell.coupled,
                                  hessian);
          });
        return;
      }
    with_kernel([&](const auto &make_stencil) {
      using Stencil = typename std::decay_t<decltype(make_stencil)>::Stencil;
      particles.for_each_cell_scattering([&](const auto &cell_particles) {
        thread_local CellHessian<dim, Stencil> cell;
        cell.reinit(make_stencil, cell_particles);
        add_particle_blocks(cell, u, kind);
        cell.add_to(hessian);
      });
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::step_bound(const Vector<double> &u,
                                     const Vector<double> &p) const
  {
    // det F_p(u + t p) = det(F_p(u) + t dF_p(p)): F_p is linear in u, so a
    // polynomial of degree dim in t.
    const auto bound = [](const auto &s, const auto &u_s, const auto &p_s) {
      Minimum m;
      m += determinant_step_bound<dim>(s.deformation_gradient(u_s),
                                       s.direction(p_s));
      return m;
    };
    if (cmpm != nullptr)
      return particles
        .template sum_over_cells<Minimum>([&](const auto &cell_particles) {
          const CmpmElementAssembly<dim>
            element(*cmpm, dofs, cell_particles.begin()->get_location());
          thread_local std::vector<Tensor<1, dim>> q, q_p;
          element.gather(u, q);
          element.gather(p, q_p);
          Minimum m;
          for (const auto &particle : cell_particles)
            m += bound(FineParticleStencil<dim>(element, particle), q, q_p);
          return m;
        })
        .value;
    return with_kernel([&](const auto &make_stencil) {
      return particles
        .template sum<Minimum>([&](const auto &particle) {
          return bound(make_stencil(particle), u, p);
        })
        .value;
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::minimum_determinant(const Vector<double> &u) const
  {
    const auto det = [](const auto &s, const auto &u_s) {
      Minimum m;
      m += determinant(s.deformation_gradient(u_s));
      return m;
    };
    if (cmpm != nullptr)
      return sum_over_elements<Minimum>(u, det).value;
    return with_kernel([&](const auto &make_stencil) {
      return particles
        .template sum<Minimum>(
          [&](const auto &particle) { return det(make_stencil(particle), u); })
        .value;
    });
  }

  template <int dim>
  double
  MpmElasticityTerm<dim>::material_increment(const Vector<double> &p,
                                             const double          length) const
  {
    // A particle's state after the step is x_p + u_p and (I + grad u) F_p^n
    // (G2P, Tables 1-3): the increment of both, the second over @p length.
    const auto increment = [length](const auto &s, const auto &p_s) {
      Maximum m;
      m += s.displacement(p_s).norm();
      m += length * s.direction(p_s).norm();
      return m;
    };
    if (cmpm != nullptr)
      return sum_over_elements<Maximum>(p, increment).value;
    return with_kernel([&](const auto &make_stencil) {
      return particles
        .template sum<Maximum>([&](const auto &particle) {
          return increment(make_stencil(particle), p);
        })
        .value;
    });
  }

  template class MpmElasticityTerm<2>;
  template class MpmElasticityTerm<3>;
} // namespace bfemp
