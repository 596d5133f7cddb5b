#ifndef bfemp_particles_body_sampler_h
#define bfemp_particles_body_sampler_h

#include <bfemp/grid/lattice.h>
#include <bfemp/particles/body_parameters.h>
#include <bfemp/particles/shape.h>

#include <vector>

namespace bfemp
{
  /**
   * Places a body's particles: every grid cell is split into
   * (particles per cell)^dim sub-cells, and each sub-cell whose sample point
   * lies in the body's shape gets one particle with the sub-cell's volume as
   * rest volume. The sample point is the sub-cell centre (regular) or a
   * uniformly random point of the sub-cell (jittered, seeded).
   */
  template <int dim>
  class BodySampler
  {
  public:
    BodySampler(const BodyParameters<dim> &body, const Lattice<dim> &lattice);

    /** Sample points inside the shape, in lattice order. */
    std::vector<Point<dim>>
    sample() const;

    /** Rest volume of each particle: (dx / particles per cell)^dim. */
    double
    particle_volume() const;

  private:
    const BodyParameters<dim> &body;
    const Lattice<dim>        &lattice;
    Shape<dim>                 shape;
  };
} // namespace bfemp

#endif
