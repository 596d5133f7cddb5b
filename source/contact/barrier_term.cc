#include <bfemp/base/parallel_sum.h>
#include <bfemp/contact/barrier.h>
#include <bfemp/contact/barrier_term.h>
#include <bfemp/contact/distance.h>
#include <bfemp/solver/positive_semidefinite.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace bfemp
{
  namespace
  {
    /**
     * Adds weight * b(s(y)) and its derivatives to a particle's local
     * stencil, where the squared distance s depends on the particle and the
     * primitive nodes at local indices @p local (particle first).
     */
    template <int dim, int n_points>
    void
    add_barrier(const double                              weight,
                const SquaredDistance<n_points * dim>    &s,
                const std::array<unsigned int, n_points> &local,
                const double                              dhat,
                const double                              kappa,
                double                                   &energy,
                Vector<double>                           &gradient,
                FullMatrix<double>                       *hessian)
    {
      const BarrierDerivatives b =
        barrier_of_squared_distance(s.value, dhat, kappa);
      energy += weight * b.value;
      for (unsigned int i = 0; i < n_points * dim; ++i)
        gradient[dim * local[i / dim] + i % dim] +=
          weight * b.first * s.gradient[i];
      if (hessian != nullptr)
        for (unsigned int i = 0; i < n_points * dim; ++i)
          {
            const unsigned int row = dim * local[i / dim] + i % dim;
            for (unsigned int j = 0; j < n_points * dim; ++j)
              (*hessian)(row, dim * local[j / dim] + j % dim) +=
                weight * (b.second * s.gradient[i] * s.gradient[j] +
                          b.first * s.hessian[i][j]);
          }
    }
  } // namespace



  template <int dim>
  BarrierTerm<dim>::BarrierTerm(ContactGeometry<dim>    &geometry,
                                const ContactParameters &parameters)
    : contact_geometry(geometry)
    , parameters(parameters)
  {}



  template <int dim>
  void
  BarrierTerm<dim>::set_scale(const double s)
  {
    scale = s;
  }



  template <int dim>
  std::string
  BarrierTerm<dim>::name() const
  {
    return "contact barrier";
  }



  template <int dim>
  bool
  BarrierTerm<dim>::is_contact() const
  {
    return true;
  }



  template <int dim>
  const ContactGeometry<dim> &
  BarrierTerm<dim>::geometry() const
  {
    return contact_geometry;
  }



  template <int dim>
  typename BarrierTerm<dim>::ParticleContact
  BarrierTerm<dim>::evaluate(
    const typename ContactGeometry<dim>::NearPairs &near,
    const unsigned int                              k,
    const std::vector<std::vector<Point<dim>>>     &x,
    const Vector<double>                           &u,
    const std::optional<HessianKind>               &hessian_kind) const
  {
    using FacetReference  = typename ContactGeometry<dim>::FacetReference;
    const double    dhat  = parameters.activation_distance;
    const double    kappa = parameters.barrier_stiffness;
    const double    dhat2 = dhat * dhat;
    ParticleContact result;
    result.particle = near.particles[k];
    const Point<dim> xq =
      contact_geometry.particle_position(result.particle, u);
    const double omega = contact_geometry.particle_weight(result.particle);

    // The local stencil: the particle (0), then each FEM node once.
    const auto local = [&](const unsigned int s, const unsigned int a) {
      for (unsigned int i = 0; i < result.nodes.size(); ++i)
        if (result.nodes[i].first == s && result.nodes[i].second == a)
          return i + 1;
      result.nodes.emplace_back(s, a);
      return static_cast<unsigned int>(result.nodes.size());
    };
    for (unsigned int j = near.offsets[k]; j < near.offsets[k + 1]; ++j)
      for (const unsigned int a :
           contact_geometry.surface(near.facets[j].surface)
             .facets()[near.facets[j].facet])
        local(near.facets[j].surface, a);
    const unsigned int n = (1 + result.nodes.size()) * dim;
    result.gradient.reinit(n);
    if (hessian_kind)
      result.hessian.reinit(n, n);
    FullMatrix<double> *hessian = hessian_kind ? &result.hessian : nullptr;

    double nearest = std::numeric_limits<double>::infinity();
    // Each term's share of the force on the particle, by surface.
    Vector<double> before(n);
    const auto     book_force = [&](const unsigned int s) {
      Tensor<1, dim> f;
      for (unsigned int d = 0; d < dim; ++d)
        f[d] = -(result.gradient[d] - before[d]);
      before = result.gradient;
      for (auto &entry : result.surfaces)
        if (entry.surface == s)
          {
            entry.force += f;
            return;
          }
      result.surfaces.push_back(
        {s, f, 0, std::numeric_limits<double>::infinity()});
    };
    const auto book_facet = [&](const FacetReference &r, const double s2) {
      nearest = std::min(nearest, s2);
      book_force(r.surface);
      for (auto &entry : result.surfaces)
        if (entry.surface == r.surface && s2 < entry.nearest_squared_distance)
          {
            entry.nearest_facet            = r.facet;
            entry.nearest_squared_distance = s2;
          }
    };

    std::vector<std::pair<unsigned int, unsigned int>> vertices, edges;
    for (unsigned int j = near.offsets[k]; j < near.offsets[k + 1]; ++j)
      {
        const FacetReference &r = near.facets[j];
        const auto           &facet =
          contact_geometry.surface(r.surface).facets()[r.facet];
        const auto &xs = x[r.surface];
        if constexpr (dim == 2)
          {
            const auto s =
              point_edge_squared_distance<2>(xq, xs[facet[0]], xs[facet[1]]);
            add_barrier<2, 3>(
              omega,
              s,
              {{0, local(r.surface, facet[0]), local(r.surface, facet[1])}},
              dhat,
              kappa,
              result.energy,
              result.gradient,
              hessian);
            book_facet(r, s.value);
          }
        else
          {
            const auto s = point_triangle_squared_distance(xq,
                                                           xs[facet[0]],
                                                           xs[facet[1]],
                                                           xs[facet[2]]);
            add_barrier<3, 4>(omega,
                              s,
                              {{0,
                                local(r.surface, facet[0]),
                                local(r.surface, facet[1]),
                                local(r.surface, facet[2])}},
                              dhat,
                              kappa,
                              result.energy,
                              result.gradient,
                              hessian);
            book_facet(r, s.value);
            for (const unsigned int e :
                 contact_geometry.surface(r.surface).facet_edges(r.facet))
              edges.emplace_back(r.surface, e);
          }
        for (const unsigned int a : facet)
          vertices.emplace_back(r.surface, a);
      }
    result.distance = std::sqrt(nearest);

    // Duplicate subtraction (eqs. 31, 32) over the lower-dimensional
    // primitives of the facets near the particle: every primitive within
    // dhat of it belongs to such a facet.
    const auto unique =
      [](std::vector<std::pair<unsigned int, unsigned int>> &v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
      };
    if constexpr (dim == 3)
      {
        unique(edges);
        for (const auto &[s, e] : edges)
          {
            const ContactSurface<dim> &surface = contact_geometry.surface(s);
            const double               weight  = surface.edge_weight(e);
            const auto                &edge    = surface.edges()[e];
            if (weight == 0.)
              continue;
            const auto d =
              point_edge_squared_distance<3>(xq, x[s][edge[0]], x[s][edge[1]]);
            if (d.value >= dhat2)
              continue;
            add_barrier<3, 3>(omega * weight,
                              d,
                              {{0, local(s, edge[0]), local(s, edge[1])}},
                              dhat,
                              kappa,
                              result.energy,
                              result.gradient,
                              hessian);
            book_force(s);
          }
      }
    unique(vertices);
    for (const auto &[s, a] : vertices)
      {
        const ContactSurface<dim> &surface = contact_geometry.surface(s);
        const double weight = surface.vertex_weight(surface.vertex_index(a));
        if (weight == 0.)
          continue;
        const auto d = point_point_squared_distance<dim>(xq, x[s][a]);
        if (d.value >= dhat2)
          continue;
        add_barrier<dim, 2>(omega * weight,
                            d,
                            {{0, local(s, a)}},
                            dhat,
                            kappa,
                            result.energy,
                            result.gradient,
                            hessian);
        book_force(s);
      }
    if (hessian_kind)
      filter_eigenvalues(result.hessian, eigenvalue_filter(*hessian_kind));
    return result;
  }



  template <int dim>
  std::vector<typename BarrierTerm<dim>::ParticleContact>
  BarrierTerm<dim>::contacts(const Vector<double>             &u,
                             const std::optional<HessianKind> &hessian) const
  {
    const auto near =
      contact_geometry.near_pairs(u, parameters.activation_distance);
    const auto                   x = contact_geometry.surface_positions(u);
    std::vector<ParticleContact> result(near.size());
    parallel::apply_to_subranges(
      0u,
      near.size(),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int k = begin; k < end; ++k)
          result[k] = evaluate(near, k, x, u, hessian);
      },
      16);
    return result;
  }



  template <int dim>
  void
  BarrierTerm<dim>::begin_step(const Vector<double> &u)
  {
    registered.assign(contact_geometry.n_particles(), {});
    stencil_registered.assign(contact_geometry.n_particles(), false);
    // Pairs a little farther than dhat join the pattern at once, so that
    // the first approach within the step does not rebuild it.
    const auto near =
      contact_geometry.near_pairs(u, 2. * parameters.activation_distance);
    for (unsigned int k = 0; k < near.size(); ++k)
      {
        auto &nodes                           = registered[near.particles[k]];
        stencil_registered[near.particles[k]] = true;
        for (unsigned int j = near.offsets[k]; j < near.offsets[k + 1]; ++j)
          for (const unsigned int a :
               contact_geometry.surface(near.facets[j].surface)
                 .facets()[near.facets[j].facet])
            {
              const unsigned int node =
                contact_geometry.node_dof(near.facets[j].surface, a);
              if (node != DofSpace<dim>::invalid)
                nodes.push_back(node);
            }
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      }
  }



  template <int dim>
  void
  BarrierTerm<dim>::add_couplings(NodeSparsity &sparsity) const
  {
    for (unsigned int q = 0; q < registered.size(); ++q)
      if (stencil_registered[q])
        {
          const auto                stencil = contact_geometry.stencil_nodes(q);
          std::vector<unsigned int> nodes(stencil.begin(), stencil.end());
          nodes.insert(nodes.end(), registered[q].begin(), registered[q].end());
          sparsity.add_clique(nodes.data(),
                              static_cast<unsigned int>(nodes.size()));
        }
  }



  template <int dim>
  bool
  BarrierTerm<dim>::register_couplings(
    const unsigned int               particle,
    const std::vector<unsigned int> &fem_nodes) const
  {
    auto &list                   = registered[particle];
    bool  added                  = !stencil_registered[particle];
    stencil_registered[particle] = true;
    for (const unsigned int node : fem_nodes)
      if (node != DofSpace<dim>::invalid &&
          !std::binary_search(list.begin(), list.end(), node))
        {
          list.insert(std::upper_bound(list.begin(), list.end(), node), node);
          added = true;
        }
    return added;
  }



  template <int dim>
  bool
  BarrierTerm<dim>::couplings_missing(const Vector<double> &u,
                                      const SparsityPattern &) const
  {
    // The pattern holds every registered clique (a registration that adds
    // something makes the potential rebuild it), so comparing with the
    // registry is enough.
    const auto near =
      contact_geometry.near_pairs(u, parameters.activation_distance);
    bool                      missing = false;
    std::vector<unsigned int> nodes;
    for (unsigned int k = 0; k < near.size(); ++k)
      {
        nodes.clear();
        for (unsigned int j = near.offsets[k]; j < near.offsets[k + 1]; ++j)
          for (const unsigned int a :
               contact_geometry.surface(near.facets[j].surface)
                 .facets()[near.facets[j].facet])
            nodes.push_back(
              contact_geometry.node_dof(near.facets[j].surface, a));
        missing = register_couplings(near.particles[k], nodes) || missing;
      }
    return missing;
  }



  template <int dim>
  double
  BarrierTerm<dim>::value(const Vector<double> &u) const
  {
    const auto near =
      contact_geometry.near_pairs(u, parameters.activation_distance);
    const auto x   = contact_geometry.surface_positions(u);
    double energy  = chunked_sum<double>(near.size(), [&](const std::size_t k) {
      return evaluate(near, static_cast<unsigned int>(k), x, u, std::nullopt)
        .energy;
    });
    last_magnitude = scale * energy;
    return scale * energy;
  }



  template <int dim>
  double
  BarrierTerm<dim>::magnitude() const
  {
    return std::abs(last_magnitude);
  }



  template <int dim>
  void
  BarrierTerm<dim>::chain_rule(const ParticleContact &contact,
                               ChainRule<dim>        &rule) const
  {
    // Eq. 29: the particle (block 0) moves with its stencil, w_iq I or
    // cMPM's Phi_Iq; FEM node k of the contact (block k + 1) with the
    // identity; kinematic nodes are no unknowns.
    rule.clear();
    contact_geometry.add_particle_stencil(rule, contact.particle, 0);
    for (unsigned int k = 0; k < contact.nodes.size(); ++k)
      {
        const unsigned int node =
          contact_geometry.node_dof(contact.nodes[k].first,
                                    contact.nodes[k].second);
        if (node != DofSpace<dim>::invalid)
          rule.add(node, k + 1, 1.);
      }
  }



  template <int dim>
  void
  BarrierTerm<dim>::add_gradient(const Vector<double> &u,
                                 Vector<double>       &gradient) const
  {
    ChainRule<dim> rule;
    for (const ParticleContact &contact : contacts(u))
      {
        chain_rule(contact, rule);
        rule.add_gradient(
          [&](const unsigned int block) {
            Tensor<1, dim> g;
            for (unsigned int d = 0; d < dim; ++d)
              g[d] = scale * contact.gradient[dim * block + d];
            return g;
          },
          gradient);
      }
  }



  template <int dim>
  void
  BarrierTerm<dim>::add_hessian(const Vector<double> &u,
                                SparseMatrix<double> &hessian,
                                const HessianKind     kind) const
  {
    ChainRule<dim> rule;
    for (const ParticleContact &contact : contacts(u, kind))
      {
        chain_rule(contact, rule);
        rule.add_hessian(
          [&](const unsigned int row, const unsigned int column) {
            return contact.hessian(row, column);
          },
          scale,
          hessian);
      }
  }



  template <int dim>
  double
  BarrierTerm<dim>::step_bound(const Vector<double> &u,
                               const Vector<double> &p) const
  {
    return contact_geometry.time_of_impact(u, p);
  }



  template <int dim>
  void
  BarrierTerm<dim>::set_obstacle_path(const double from, const double to) const
  {
    contact_geometry.set_obstacle_path(from, to);
  }



  template <int dim>
  double
  BarrierTerm<dim>::minimum_distance(const Vector<double> &u) const
  {
    if (contact_geometry.particles_inside(u) > 0)
      return 0.;
    return contact_geometry.minimum_distance(u, parameters.activation_distance);
  }



  template <int dim>
  typename BarrierTerm<dim>::Measurement
  BarrierTerm<dim>::measure(const Vector<double> &u) const
  {
    Measurement m;
    m.minimum_distance = std::numeric_limits<double>::infinity();
    const auto near =
      contact_geometry.near_pairs(u, parameters.activation_distance);
    m.pairs = near.facets.size();
    for (const ParticleContact &contact : contacts(u))
      {
        ++m.particles;
        m.energy += contact.energy;
        m.minimum_distance = std::min(m.minimum_distance, contact.distance);
        const unsigned int body =
          contact_geometry.particle_body(contact.particle);
        for (const auto &entry : contact.surfaces)
          m.force[{body, entry.surface}] -= entry.force; // on the FEM body
      }
    return m;
  }



  template class BarrierTerm<2>;
  template class BarrierTerm<3>;
} // namespace bfemp
