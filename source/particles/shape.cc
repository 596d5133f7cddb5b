#include <bfemp/particles/shape.h>

namespace bfemp
{
  template <int dim>
  Shape<dim>::Shape(const std::vector<ShapePrimitive<dim>> &primitives)
    : primitives(primitives)
  {}



  template <int dim>
  bool
  Shape<dim>::contains(const Point<dim> &x) const
  {
    bool inside = false;
    for (const auto &primitive : primitives)
      if (primitive.subtract)
        inside = inside && !primitive.contains_strictly(x);
      else
        inside = inside || primitive.contains(x);
    return inside;
  }



  template <int dim>
  bool
  Shape<dim>::contains_strictly(const Point<dim> &x) const
  {
    bool inside = false;
    for (const auto &primitive : primitives)
      if (primitive.subtract)
        inside = inside && !primitive.contains(x);
      else
        inside = inside || primitive.contains_strictly(x);
    return inside;
  }



  template <int dim>
  BoundingBox<dim>
  Shape<dim>::bounding_box() const
  {
    bool             first = true;
    BoundingBox<dim> box;
    for (const auto &primitive : primitives)
      if (!primitive.subtract)
        {
          if (first)
            box = primitive.bounding_box();
          else
            box.merge_with(primitive.bounding_box());
          first = false;
        }
    return box;
  }



  template class Shape<2>;
  template class Shape<3>;
} // namespace bfemp
