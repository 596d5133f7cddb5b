#include <bfemp/base/parallel_sum.h>
#include <bfemp/contact/collision_detection.h>
#include <bfemp/contact/contact_geometry.h>
#include <bfemp/contact/distance.h>
#include <bfemp/contact/spatial_hash.h>
#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/particles/particle_layout.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parallel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace bfemp
{
  namespace
  {
    template <int dim>
    BoundingBox<dim>
    box_of(const Point<dim> &x)
    {
      return BoundingBox<dim>(std::make_pair(x, x));
    }

    template <int dim>
    void
    include(BoundingBox<dim> &box, const Point<dim> &x)
    {
      box.merge_with(box_of(x));
    }

    template <int dim>
    BoundingBox<dim>
    inflated(BoundingBox<dim> box, const double margin)
    {
      if (margin > 0.)
        box.extend(margin);
      return box;
    }

    /**
     * omega_q of eq. 28: the largest cross-section of a sphere of the
     * particle's rest volume.
     */
    template <int dim>
    double
    cross_section_of(const double volume)
    {
      return dim == 2 ? 2. * std::sqrt(volume / numbers::PI)
                      : numbers::PI *
                          std::pow(3. * volume / (4. * numbers::PI), 2. / 3.);
    }

    /** Squared distance of x to facet f with node positions x_nodes. */
    template <int dim>
    double
    facet_squared_distance(const Point<dim>                          &x,
                           const typename ContactSurface<dim>::Facet &f,
                           const std::vector<Point<dim>>             &nodes)
    {
      if constexpr (dim == 2)
        return point_edge_squared_distance_value<2>(x,
                                                    nodes[f[0]],
                                                    nodes[f[1]]);
      else
        return point_triangle_squared_distance_value(x,
                                                     nodes[f[0]],
                                                     nodes[f[1]],
                                                     nodes[f[2]]);
    }
  } // namespace



  template <int dim>
  typename ContactGeometry<dim>::NearPairs &
  ContactGeometry<dim>::NearPairs::operator+=(const NearPairs &other)
  {
    const unsigned int shift = offsets.back();
    particles.insert(particles.end(),
                     other.particles.begin(),
                     other.particles.end());
    for (unsigned int k = 1; k < other.offsets.size(); ++k)
      offsets.push_back(shift + other.offsets[k]);
    facets.insert(facets.end(), other.facets.begin(), other.facets.end());
    return *this;
  }



  template <int dim>
  ContactGeometry<dim>::ContactGeometry(
    const BackgroundGrid<dim>                        &grid,
    ParticleSystem<dim>                              &particles,
    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies,
    const DofSpace<dim>                              &dofs,
    const CmpmDiscretization<dim>                    *cmpm)
    : grid(grid)
    , particles(particles)
    , bodies(bodies)
    , dofs(dofs)
    , cmpm(cmpm)
  {
    for (const auto &body : bodies)
      {
        surfaces.emplace_back(body->mesh());
        kinematic.push_back(body->is_kinematic());
      }
  }



  template <int dim>
  void
  ContactGeometry<dim>::gather_particles()
  {
    using Layout        = ParticleLayout<dim>;
    const std::size_t n = particles.n_particles();
    start_positions.resize(n);
    weights.resize(n);
    body_ids.resize(n);
    std::size_t q = 0;
    for (const auto &particle : particles.handler())
      {
        const auto properties = particle.get_properties();
        start_positions[q]    = particle.get_location();
        weights[q]  = cross_section_of<dim>(properties[Layout::rest_volume]);
        body_ids[q] = static_cast<unsigned int>(properties[Layout::body_id]);
        ++q;
      }
    // cMPM gathers stencils on demand (gather_stencils)
    stencil_start.assign(n, no_stencil);
    stencil_length.assign(n, 0);
    stencil_node_list.clear();
    stencil_weight_list.clear();
    stencil_matrix_list.clear();
    gathered_region.reset();
  }



  template <int dim>
  template <int degree>
  void
  ContactGeometry<dim>::gather_kernel_stencils()
  {
    KernelStencil<dim, degree> kernel;
    constexpr unsigned int stencil_size = KernelStencil<dim, degree>::n_nodes;
    const std::size_t      n            = start_positions.size();
    stencil_node_list.resize(n * stencil_size);
    stencil_weight_list.resize(n * stencil_size);
    for (std::size_t q = 0; q < n; ++q)
      {
        kernel.reinit(grid.lattice(), start_positions[q]);
        stencil_start[q] = q * stencil_size;
        unsigned int k   = 0;
        for (unsigned int a = 0; a < stencil_size; ++a)
          {
            const unsigned int node = dofs.grid_node(kernel.node[a]);
            // Nodes left out of the step carry a negligible weight (see
            // ImplicitIntegrator::particles_to_grid); the G2P skips them too.
            if (node == DofSpace<dim>::invalid)
              continue;
            stencil_node_list[q * stencil_size + k]   = node;
            stencil_weight_list[q * stencil_size + k] = kernel.weight[a];
            ++k;
          }
        stencil_length[q] = k;
      }
  }



  template <int dim>
  void
  ContactGeometry<dim>::gather_stencils(const BoundingBox<dim> &reachable) const
  {
    if (cmpm == nullptr)
      return; // the kernel's stencils are all there
    if (gathered_region &&
        gathered_region->point_inside(reachable.get_boundary_points().first) &&
        gathered_region->point_inside(reachable.get_boundary_points().second))
      return;
    // One coarse element more than asked, so that a growing |u| during the
    // Newton solve does not gather again at every iteration.
    BoundingBox<dim> region = reachable;
    if (gathered_region)
      region.merge_with(*gathered_region);
    region.extend(cmpm->coarse_grid().element_size());

    std::vector<unsigned int> missing;
    for (unsigned int q = 0; q < start_positions.size(); ++q)
      if (stencil_start[q] == no_stencil &&
          region.point_inside(start_positions[q]))
        missing.push_back(q);
    // Phi at each missing particle on threads, appended in particle order
    // (the lists do not depend on the number of threads).
    struct Stencil
    {
      std::vector<unsigned int>   nodes;
      std::vector<Tensor<2, dim>> factors;
    };
    std::vector<Stencil> stencils(missing.size());
    parallel::apply_to_subranges(
      std::size_t(0),
      missing.size(),
      [&](const std::size_t begin, const std::size_t end) {
        std::vector<CoarseShapeValue<dim>> values;
        for (std::size_t k = begin; k < end; ++k)
          {
            cmpm->evaluate(start_positions[missing[k]], values);
            for (const CoarseShapeValue<dim> &value : values)
              {
                // as in the kernel's case: nodes left out of the step
                const unsigned int node = dofs.grid_node(value.node);
                if (node == DofSpace<dim>::invalid)
                  continue;
                stencils[k].nodes.push_back(node);
                stencils[k].factors.push_back(value.value);
              }
          }
      },
      64);
    for (std::size_t k = 0; k < missing.size(); ++k)
      {
        stencil_start[missing[k]]  = stencil_node_list.size();
        stencil_length[missing[k]] = stencils[k].nodes.size();
        stencil_node_list.insert(stencil_node_list.end(),
                                 stencils[k].nodes.begin(),
                                 stencils[k].nodes.end());
        stencil_matrix_list.insert(stencil_matrix_list.end(),
                                   stencils[k].factors.begin(),
                                   stencils[k].factors.end());
      }
    gathered_region = region;
  }



  template <int dim>
  double
  ContactGeometry<dim>::interpolation_bound() const
  {
    return cmpm == nullptr ? 1. : cmpm->interpolation_bound();
  }



  template <int dim>
  void
  ContactGeometry<dim>::begin_step(const double end_time)
  {
    gather_particles();
    if (particles.n_particles() > 0 && cmpm == nullptr)
      dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
        gather_kernel_stencils<decltype(degree)::value>();
      });
    node_start.resize(bodies.size());
    node_end.resize(bodies.size());
    for (unsigned int s = 0; s < bodies.size(); ++s)
      {
        node_start[s] = bodies[s]->positions();
        if (kinematic[s])
          {
            const auto &mesh = bodies[s]->mesh();
            node_end[s].resize(mesh.n_nodes());
            for (unsigned int a = 0; a < mesh.n_nodes(); ++a)
              node_end[s][a] =
                bodies[s]->motion(a).position(mesh.rest_position(a), end_time);
          }
      }
    progress_from = progress_to = 0.;
    cache.valid                 = false;
  }



  template <int dim>
  void
  ContactGeometry<dim>::set_obstacle_path(const double from, const double to)
  {
    progress_from = from;
    progress_to   = to;
  }



  template <int dim>
  double
  ContactGeometry<dim>::obstacle_progress() const
  {
    return progress_from;
  }



  template <int dim>
  unsigned int
  ContactGeometry<dim>::n_particles() const
  {
    return static_cast<unsigned int>(start_positions.size());
  }



  template <int dim>
  Point<dim>
  ContactGeometry<dim>::particle_position(const unsigned int    q,
                                          const Vector<double> &u) const
  {
    return start_positions[q] + particle_interpolation(q, u);
  }



  template <int dim>
  Tensor<1, dim>
  ContactGeometry<dim>::particle_interpolation(const unsigned int    q,
                                               const Vector<double> &v) const
  {
    Assert(stencil_start[q] != no_stencil,
           ExcMessage("particle_interpolation() of a particle whose cMPM "
                      "stencil was not gathered"));
    Tensor<1, dim>      result;
    const unsigned int *node = &stencil_node_list[stencil_start[q]];
    if (cmpm != nullptr)
      {
        const Tensor<2, dim> *Phi = &stencil_matrix_list[stencil_start[q]];
        for (unsigned int k = 0; k < stencil_length[q]; ++k)
          result += Phi[k] * DofSpace<dim>::get(v, node[k]);
        return result;
      }
    const double *weight = &stencil_weight_list[stencil_start[q]];
    for (unsigned int k = 0; k < stencil_length[q]; ++k)
      for (unsigned int d = 0; d < dim; ++d)
        result[d] += weight[k] * v[dim * node[k] + d];
    return result;
  }



  template <int dim>
  ArrayView<const unsigned int>
  ContactGeometry<dim>::stencil_nodes(const unsigned int q) const
  {
    Assert(stencil_start[q] != no_stencil, ExcInternalError());
    return {stencil_node_list.data() + stencil_start[q], stencil_length[q]};
  }



  template <int dim>
  void
  ContactGeometry<dim>::add_particle_stencil(ChainRule<dim>    &rule,
                                             const unsigned int q,
                                             const unsigned int block) const
  {
    Assert(stencil_start[q] != no_stencil, ExcInternalError());
    const std::size_t first = stencil_start[q];
    for (unsigned int k = 0; k < stencil_length[q]; ++k)
      if (cmpm != nullptr)
        rule.add(stencil_node_list[first + k],
                 block,
                 stencil_matrix_list[first + k]);
      else
        rule.add(stencil_node_list[first + k],
                 block,
                 stencil_weight_list[first + k]);
  }



  template <int dim>
  double
  ContactGeometry<dim>::particle_weight(const unsigned int q) const
  {
    return weights[q];
  }



  template <int dim>
  unsigned int
  ContactGeometry<dim>::particle_body(const unsigned int q) const
  {
    return body_ids[q];
  }



  template <int dim>
  unsigned int
  ContactGeometry<dim>::n_surfaces() const
  {
    return static_cast<unsigned int>(surfaces.size());
  }



  template <int dim>
  const ContactSurface<dim> &
  ContactGeometry<dim>::surface(const unsigned int s) const
  {
    return surfaces[s];
  }



  template <int dim>
  bool
  ContactGeometry<dim>::is_kinematic(const unsigned int s) const
  {
    return kinematic[s];
  }



  template <int dim>
  unsigned int
  ContactGeometry<dim>::node_dof(const unsigned int s,
                                 const unsigned int a) const
  {
    return kinematic[s] ? DofSpace<dim>::invalid : dofs.fem_node(s, a);
  }



  template <int dim>
  Point<dim>
  ContactGeometry<dim>::node_position(const unsigned int    s,
                                      const unsigned int    a,
                                      const Vector<double> &u) const
  {
    return node_start[s][a] + node_displacement(s, a, u);
  }



  template <int dim>
  Tensor<1, dim>
  ContactGeometry<dim>::node_displacement(const unsigned int    s,
                                          const unsigned int    a,
                                          const Vector<double> &u) const
  {
    if (kinematic[s])
      return progress_from * (node_end[s][a] - node_start[s][a]);
    return DofSpace<dim>::get(u, dofs.fem_node(s, a));
  }



  template <int dim>
  std::vector<std::vector<Point<dim>>>
  ContactGeometry<dim>::surface_positions(const Vector<double> &u) const
  {
    std::vector<std::vector<Point<dim>>> x(surfaces.size());
    for (unsigned int s = 0; s < surfaces.size(); ++s)
      {
        x[s].resize(node_start[s].size());
        for (const unsigned int a : surfaces[s].nodes())
          x[s][a] = node_position(s, a, u);
      }
    return x;
  }



  template <int dim>
  std::vector<std::vector<Tensor<1, dim>>>
  ContactGeometry<dim>::surface_motions(const Vector<double> &p) const
  {
    std::vector<std::vector<Tensor<1, dim>>> dx(surfaces.size());
    for (unsigned int s = 0; s < surfaces.size(); ++s)
      {
        dx[s].resize(node_start[s].size());
        for (const unsigned int a : surfaces[s].nodes())
          dx[s][a] = kinematic[s] ? (progress_to - progress_from) *
                                      (node_end[s][a] - node_start[s][a])
                                  : DofSpace<dim>::get(p, dofs.fem_node(s, a));
      }
    return dx;
  }



  template <int dim>
  typename ContactGeometry<dim>::NearPairs
  ContactGeometry<dim>::near_pairs(const Vector<double> &u,
                                   const double          distance) const
  {
    // Value, gradient, Hessian and coupling checks ask at the same u in
    // turn; the last answer is kept.
    if (cache.valid && cache.distance == distance &&
        cache.progress == progress_from && cache.u == u)
      return cache.near;

    const auto                    x = surface_positions(u);
    std::vector<FacetReference>   references;
    std::vector<BoundingBox<dim>> boxes;
    for (unsigned int s = 0; s < surfaces.size(); ++s)
      for (unsigned int f = 0; f < surfaces[s].facets().size(); ++f)
        {
          const auto      &facet = surfaces[s].facets()[f];
          BoundingBox<dim> box   = box_of(x[s][facet[0]]);
          for (const unsigned int a : facet)
            include(box, x[s][a]);
          boxes.push_back(inflated(box, distance));
          references.push_back({s, f});
        }
    NearPairs result;
    if (!boxes.empty() && !start_positions.empty())
      {
        BoundingBox<dim> everything = boxes[0];
        for (const auto &b : boxes)
          everything.merge_with(b);
        // |x_q(u) - x_q^n| <= C sqrt(dim) max |u_i| (interpolation_bound):
        // particles whose start is farther from every facet skip the
        // interpolation.
        const BoundingBox<dim> reachable =
          inflated(everything,
                   interpolation_bound() * std::sqrt(1. * dim) *
                     u.linfty_norm());
        gather_stencils(reachable);
        const SpatialHash<dim> hash(boxes);
        const double           distance_squared = distance * distance;

        constexpr std::size_t  chunk = 1024;
        const std::size_t      n     = start_positions.size();
        std::vector<NearPairs> partial((n + chunk - 1) / chunk);
        parallel::apply_to_subranges(
          std::size_t(0),
          partial.size(),
          [&](const std::size_t begin, const std::size_t end) {
            std::vector<unsigned int> candidates;
            for (std::size_t c = begin; c < end; ++c)
              for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk);
                   ++i)
                {
                  const unsigned int q = static_cast<unsigned int>(i);
                  if (!reachable.point_inside(start_positions[q]))
                    continue;
                  const Point<dim> xq = particle_position(q, u);
                  if (!everything.point_inside(xq))
                    continue;
                  hash.query(box_of(xq), candidates);
                  NearPairs &near  = partial[c];
                  const auto first = near.facets.size();
                  for (const unsigned int k : candidates)
                    {
                      const FacetReference &r = references[k];
                      if (facet_squared_distance<dim>(
                            xq,
                            surfaces[r.surface].facets()[r.facet],
                            x[r.surface]) < distance_squared)
                        near.facets.push_back(r);
                    }
                  if (near.facets.size() > first)
                    {
                      near.particles.push_back(q);
                      near.offsets.push_back(
                        static_cast<unsigned int>(near.facets.size()));
                    }
                }
          },
          1);
        for (const NearPairs &p : partial)
          result += p;
      }
    cache.valid    = true;
    cache.distance = distance;
    cache.progress = progress_from;
    cache.u        = u;
    cache.near     = result;
    return result;
  }



  template <int dim>
  double
  ContactGeometry<dim>::time_of_impact(const Vector<double> &u,
                                       const Vector<double> &p) const
  {
    const auto                    x  = surface_positions(u);
    const auto                    dx = surface_motions(p);
    std::vector<FacetReference>   references;
    std::vector<BoundingBox<dim>> boxes;
    for (unsigned int s = 0; s < surfaces.size(); ++s)
      for (unsigned int f = 0; f < surfaces[s].facets().size(); ++f)
        {
          const auto &facet = surfaces[s].facets()[f];
          if constexpr (dim == 2)
            boxes.push_back(swept_segment_box<dim>(x[s][facet[0]],
                                                   x[s][facet[1]],
                                                   dx[s][facet[0]],
                                                   dx[s][facet[1]]));
          else
            boxes.push_back(swept_triangle_box<dim>(x[s][facet[0]],
                                                    x[s][facet[1]],
                                                    x[s][facet[2]],
                                                    dx[s][facet[0]],
                                                    dx[s][facet[1]],
                                                    dx[s][facet[2]]));
          references.push_back({s, f});
        }
    if (boxes.empty() || start_positions.empty())
      return std::numeric_limits<double>::infinity();
    BoundingBox<dim> everything = boxes[0];
    for (const auto &b : boxes)
      everything.merge_with(b);
    // A particle's path from x_q(u) to x_q(u + p) stays within
    // sqrt(dim) (|u|_inf + |p|_inf) of its start (as in near_pairs).
    const BoundingBox<dim> reachable =
      inflated(everything,
               interpolation_bound() * std::sqrt(1. * dim) *
                 (u.linfty_norm() + p.linfty_norm()));
    gather_stencils(reachable);
    const SpatialHash<dim> hash(boxes);

    struct Result
    {
      Minimum       time;
      unsigned long queries = 0;
      Result &
      operator+=(const Result &other)
      {
        time += other.time;
        queries += other.queries;
        return *this;
      }
    };
    const Result result =
      chunked_sum<Result>(start_positions.size(), [&](const std::size_t i) {
        Result             r;
        const unsigned int q = static_cast<unsigned int>(i);
        if (!reachable.point_inside(start_positions[q]))
          return r;
        const Point<dim>       xq  = particle_position(q, u);
        const Tensor<1, dim>   dxq = particle_interpolation(q, p);
        const BoundingBox<dim> box = swept_point_box<dim>(xq, dxq);
        if (everything.get_neighbor_type(box) == NeighborType::not_neighbors)
          return r;
        thread_local std::vector<unsigned int> candidates;
        hash.query(box, candidates);
        for (const unsigned int c : candidates)
          {
            const FacetReference &ref = references[c];
            const auto &facet = surfaces[ref.surface].facets()[ref.facet];
            const auto &xs    = x[ref.surface];
            const auto &ds    = dx[ref.surface];
            ++r.queries;
            if constexpr (dim == 2)
              r.time += point_edge_time_of_impact<2>(xq,
                                                     xs[facet[0]],
                                                     xs[facet[1]],
                                                     dxq,
                                                     ds[facet[0]],
                                                     ds[facet[1]]);
            else
              r.time += point_triangle_time_of_impact(xq,
                                                      xs[facet[0]],
                                                      xs[facet[1]],
                                                      xs[facet[2]],
                                                      dxq,
                                                      ds[facet[0]],
                                                      ds[facet[1]],
                                                      ds[facet[2]]);
          }
        return r;
      });
    ccd_queries += result.queries;
    return result.time.value;
  }



  template <int dim>
  double
  ContactGeometry<dim>::minimum_distance(const Vector<double> &u,
                                         const double          reach) const
  {
    const NearPairs near = near_pairs(u, reach);
    const auto      x    = surface_positions(u);
    Minimum         d2;
    for (unsigned int k = 0; k < near.size(); ++k)
      {
        const Point<dim> xq = particle_position(near.particles[k], u);
        for (unsigned int j = near.offsets[k]; j < near.offsets[k + 1]; ++j)
          {
            const FacetReference &r = near.facets[j];
            d2 +=
              facet_squared_distance<dim>(xq,
                                          surfaces[r.surface].facets()[r.facet],
                                          x[r.surface]);
          }
      }
    return std::sqrt(d2.value);
  }



  template <int dim>
  std::vector<unsigned int>
  ContactGeometry<dim>::containing_bodies(const Vector<double> &u) const
  {
    std::vector<unsigned int> containing(start_positions.size(),
                                         numbers::invalid_unsigned_int);
    struct ElementReference
    {
      unsigned int body, element;
    };
    std::vector<ElementReference>        references;
    std::vector<BoundingBox<dim>>        boxes;
    std::vector<std::vector<Point<dim>>> x(bodies.size());
    for (unsigned int s = 0; s < bodies.size(); ++s)
      {
        const auto &mesh = bodies[s]->mesh();
        x[s].resize(mesh.n_nodes());
        for (unsigned int a = 0; a < mesh.n_nodes(); ++a)
          x[s][a] = node_position(s, a, u);
        for (unsigned int e = 0; e < mesh.n_elements(); ++e)
          {
            const auto      &element = mesh.elements()[e];
            BoundingBox<dim> box     = box_of(x[s][element[0]]);
            for (const unsigned int a : element)
              include(box, x[s][a]);
            boxes.push_back(box);
            references.push_back({s, e});
          }
      }
    if (boxes.empty() || start_positions.empty())
      return containing;
    const SpatialHash<dim> hash(boxes);
    BoundingBox<dim>       everything = boxes[0];
    for (const auto &b : boxes)
      everything.merge_with(b);
    // as in near_pairs: particles that cannot reach an element
    const BoundingBox<dim> reachable =
      inflated(everything,
               interpolation_bound() * std::sqrt(1. * dim) * u.linfty_norm());
    gather_stencils(reachable);

    const auto containing_body = [&](const unsigned int q) {
      if (!reachable.point_inside(start_positions[q]))
        return numbers::invalid_unsigned_int;
      const Point<dim>                       xq = particle_position(q, u);
      thread_local std::vector<unsigned int> candidates;
      hash.query(box_of(xq), candidates);
      for (const unsigned int c : candidates)
        {
          const auto &element = bodies[references[c].body]
                                  ->mesh()
                                  .elements()[references[c].element];
          const auto &xs = x[references[c].body];
          // Barycentric coordinates from the edge matrix of the simplex.
          Tensor<2, dim> edges;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int d = 0; d < dim; ++d)
              edges[d][a] = xs[element[a + 1]][d] - xs[element[0]][d];
          if (determinant(edges) == 0.)
            continue;
          const Tensor<1, dim> lambda = invert(edges) * (xq - xs[element[0]]);
          double               sum    = 0.;
          bool                 within = true;
          for (unsigned int d = 0; d < dim; ++d)
            {
              within = within && lambda[d] > 0.;
              sum += lambda[d];
            }
          if (within && sum < 1.)
            return references[c].body;
        }
      return numbers::invalid_unsigned_int;
    };
    parallel::apply_to_subranges(
      std::size_t(0),
      start_positions.size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t q = begin; q < end; ++q)
          containing[q] = containing_body(static_cast<unsigned int>(q));
      },
      256);
    return containing;
  }



  template <int dim>
  unsigned int
  ContactGeometry<dim>::particles_inside(const Vector<double> &u) const
  {
    const std::vector<unsigned int> containing = containing_bodies(u);
    return std::count_if(containing.begin(),
                         containing.end(),
                         [](const unsigned int s) {
                           return s != numbers::invalid_unsigned_int;
                         });
  }



  template <int dim>
  std::set<std::pair<unsigned int, unsigned int>>
  ContactGeometry<dim>::overlapping_bodies(const Vector<double> &u) const
  {
    const std::vector<unsigned int> containing = containing_bodies(u);
    std::set<std::pair<unsigned int, unsigned int>> pairs;
    for (unsigned int q = 0; q < containing.size(); ++q)
      if (containing[q] != numbers::invalid_unsigned_int)
        pairs.emplace(body_ids[q], containing[q]);
    return pairs;
  }



  template <int dim>
  unsigned long
  ContactGeometry<dim>::n_ccd_queries() const
  {
    return ccd_queries;
  }



  template class ContactGeometry<2>;
  template class ContactGeometry<3>;
} // namespace bfemp
