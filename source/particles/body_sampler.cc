#include <bfemp/particles/body_sampler.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace bfemp
{
  template <int dim>
  BodySampler<dim>::BodySampler(const BodyParameters<dim> &body,
                                const Lattice<dim>        &lattice)
    : body(body)
    , lattice(lattice)
    , shape(body.primitives)
  {}



  template <int dim>
  double
  BodySampler<dim>::particle_volume() const
  {
    return std::pow(lattice.dx / body.particles_per_direction, dim);
  }



  template <int dim>
  std::vector<Point<dim>>
  BodySampler<dim>::sample() const
  {
    const unsigned int n   = body.particles_per_direction;
    const double       sub = lattice.dx / n;

    // Sub-cell index range covering the shape's bounding box.
    const BoundingBox<dim> box = shape.bounding_box();
    std::array<long, dim>  first, count;
    long                   total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        first[d] = static_cast<long>(
          std::floor((box.lower_bound(d) - lattice.origin[d]) / sub));
        const long last = static_cast<long>(
          std::ceil((box.upper_bound(d) - lattice.origin[d]) / sub));
        count[d] = std::max(last - first[d], 0L);
        total *= count[d];
      }

    std::mt19937                           random(body.jitter_seed);
    std::uniform_real_distribution<double> unit(0., 1.);
    std::vector<Point<dim>>                points;
    for (long k = 0; k < total; ++k)
      {
        long       rest = k;
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const long i = first[d] + rest % count[d];
            rest /= count[d];
            const double where = body.jittered ? unit(random) : 0.5;
            x[d]               = lattice.origin[d] + (i + where) * sub;
          }
        if (shape.contains(x))
          points.push_back(x);
      }
    return points;
  }



  template class BodySampler<2>;
  template class BodySampler<3>;
} // namespace bfemp
