#ifndef bfemp_particles_shape_primitive_h
#define bfemp_particles_shape_primitive_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>

namespace bfemp
{
  using namespace dealii;

  /**
   * One primitive of a body's shape, prm subsection "primitive j" of a body:
   * a box, a ball (disk in 2D), a shell (ring in 2D) or a half shell
   * (semi-ring). Bodies combine primitives in order: "add" unites, "subtract"
   * removes.
   */
  template <int dim>
  struct ShapePrimitive
  {
    enum class Type
    {
      box,
      ball,
      shell,
      semi_shell
    };

    Type       type     = Type::box;
    bool       subtract = false;
    Point<dim> lower_corner;
    Point<dim> upper_corner;
    Point<dim> center;
    double     inner_radius = 0.;
    double     outer_radius = 0.;
    /** The semi-shell keeps the half with (x - center) . direction >= 0. */
    Tensor<1, dim> direction;

    static void
    declare_parameters(ParameterHandler &prm);

    /** @p where names the subsection path for messages. */
    void
    parse_parameters(ParameterHandler &prm, const std::string &where);

    /** Closed-set membership (points on the surface count as inside). */
    bool
    contains(const Point<dim> &x) const;

    /** Strict interior, for the overlap check between bodies at t = 0. */
    bool
    contains_strictly(const Point<dim> &x) const;

    BoundingBox<dim>
    bounding_box() const;

  private:
    /** Signed measure that is <= 0 inside and > 0 outside. */
    double
    outside_measure(const Point<dim> &x) const;
  };
} // namespace bfemp

#endif
