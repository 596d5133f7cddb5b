#ifndef bfemp_particles_shape_h
#define bfemp_particles_shape_h

#include <bfemp/particles/shape_primitive.h>

#include <vector>

namespace bfemp
{
  /**
   * A body's region as a constructive solid geometry sequence: start empty,
   * then unite each "add" primitive and cut each "subtract" primitive, in
   * the order the prm lists them.
   */
  template <int dim>
  class Shape
  {
  public:
    explicit Shape(const std::vector<ShapePrimitive<dim>> &primitives);

    bool
    contains(const Point<dim> &x) const;

    /** True if x is strictly inside the region (away from its surface). */
    bool
    contains_strictly(const Point<dim> &x) const;

    /** Union of the boxes of the added primitives. */
    BoundingBox<dim>
    bounding_box() const;

  private:
    std::vector<ShapePrimitive<dim>> primitives;
  };
} // namespace bfemp

#endif
