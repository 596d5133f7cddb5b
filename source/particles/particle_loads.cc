#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/particles/particle_loads.h>

#include <limits>

namespace bfemp
{
  template <int dim>
  bool
  ParticleLoads<dim>::Load::carries(const Point<dim> &x) const
  {
    const double coordinate = x[parameters->direction];
    return parameters->upper ? coordinate > bound : coordinate < bound;
  }



  template <int dim>
  ParticleLoads<dim>::ParticleLoads(
    const std::vector<BodyParameters<dim>> &bodies,
    const double                            cell_size,
    const ParticleSystem<dim>              &particles)
  {
    using Layout = ParticleLayout<dim>;
    // the bounding box of every body's particles at t = 0
    std::vector<Point<dim>> lower(bodies.size()), upper(bodies.size());
    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[b][d] = std::numeric_limits<double>::max();
          upper[b][d] = std::numeric_limits<double>::lowest();
        }
    for (const auto &particle : particles.handler())
      {
        const auto       p = particle.get_properties();
        const auto       b = static_cast<unsigned int>(p[Layout::body_id]);
        const Point<dim> x(Layout::get_vector(p, Layout::initial_position));
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[b][d] = std::min(lower[b][d], x[d]);
            upper[b][d] = std::max(upper[b][d], x[d]);
          }
      }

    for (unsigned int b = 0; b < bodies.size(); ++b)
      for (unsigned int k = 0; k < bodies[b].surface_loads.size(); ++k)
        {
          const SurfaceLoad<dim> &parameters = bodies[b].surface_loads[k];
          const double       h = cell_size / bodies[b].particles_per_direction;
          const unsigned int n = parameters.direction;
          const double       depth =
            parameters.layer_depth > 0. ? parameters.layer_depth : h;
          Load load;
          load.parameters = &parameters;
          load.body       = b;
          load.index      = k;
          // the face: the outermost particles' sub-cells end h/2 beyond them
          load.bound = parameters.upper ? upper[b][n] + h / 2 - depth
                                        : lower[b][n] - h / 2 + depth;
          load.area  = 1.;
          for (unsigned int d = 0; d < dim; ++d)
            if (d != n)
              load.area *= upper[b][d] - lower[b][d] + h;
          loads.push_back(load);
        }

    for (const auto &particle : particles.handler())
      {
        const auto       p = particle.get_properties();
        const auto       b = static_cast<unsigned int>(p[Layout::body_id]);
        const Point<dim> x(Layout::get_vector(p, Layout::initial_position));
        for (Load &load : loads)
          if (load.body == b && load.carries(x))
            ++load.n_particles;
      }
    for (const Load &load : loads)
      require_input(load.n_particles > 0,
                    parameter_tools::numbered("body", load.body) + "/" +
                      parameter_tools::numbered("surface load", load.index),
                    "layer depth",
                    std::to_string(load.parameters->layer_depth),
                    "no particle of the body lies within the layer below "
                    "face " +
                      load.parameters->face +
                      "; make the layer at least half a particle spacing "
                      "deep");
  }



  template <int dim>
  bool
  ParticleLoads<dim>::empty() const
  {
    return loads.empty();
  }



  template <int dim>
  void
  ParticleLoads<dim>::set_time(const double t)
  {
    for (Load &load : loads)
      load.force =
        load.parameters->traction(t) * (load.area / load.n_particles);
  }



  template <int dim>
  Tensor<1, dim>
  ParticleLoads<dim>::force(const ArrayView<const double> &properties) const
  {
    using Layout = ParticleLayout<dim>;
    Tensor<1, dim> f;
    if (loads.empty())
      return f;
    const auto       b = static_cast<unsigned int>(properties[Layout::body_id]);
    const Point<dim> x(
      Layout::get_vector(properties, Layout::initial_position));
    for (const Load &load : loads)
      if (load.body == b && load.carries(x))
        f += load.force;
    return f;
  }



  template <int dim>
  void
  ParticleLoads<dim>::add_to_grid(const BackgroundGrid<dim>   &grid,
                                  ParticleSystem<dim>         &particles,
                                  std::vector<Tensor<1, dim>> &grid_force) const
  {
    if (loads.empty())
      return;
    dispatch_kernel_degree(grid.kernel_degree(), [&](auto degree) {
      particles.for_each_scattering([&](const auto &particle) {
        const Tensor<1, dim> f = force(particle.get_properties());
        if (f.norm_square() == 0.)
          return;
        KernelStencil<dim, decltype(degree)::value> kernel;
        kernel.reinit(grid.lattice(), particle.get_location());
        for (unsigned int k = 0; k < kernel.n_nodes; ++k)
          grid_force[kernel.node[k]] += kernel.weight[k] * f;
      });
    });
  }



  template <int dim>
  unsigned int
  ParticleLoads<dim>::n_particles(const unsigned int k) const
  {
    return loads[k].n_particles;
  }



  template <int dim>
  double
  ParticleLoads<dim>::area(const unsigned int k) const
  {
    return loads[k].area;
  }



  template class ParticleLoads<2>;
  template class ParticleLoads<3>;
} // namespace bfemp
