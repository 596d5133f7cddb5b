#ifndef bfemp_particles_shape_primitive_h
#define bfemp_particles_shape_primitive_h

#include <bfemp/particles/voxel_image.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

namespace bfemp
{
  using namespace dealii;

  /**
   * One primitive of a body's shape, prm subsection "primitive j" of a body:
   * a box, a ball (disk in 2D), an ellipsoid (ellipse in 2D), an elliptic
   * cylinder (3D), a shell (ring in 2D), a half shell (semi-ring) or the
   * voxels of an image that hold one value (type "image", VoxelImage). Bodies
   * combine primitives in order: "add" unites, "subtract" removes. Any
   * primitive may be rotated ("rotation angle", in 3D about "rotation axis")
   * about its own centre or about a common "rotation center", which rotates a
   * whole CSG body when its primitives share it.
   */
  template <int dim>
  struct ShapePrimitive
  {
    enum class Type
    {
      box,
      ball,
      ellipsoid,
      elliptic_cylinder,
      shell,
      semi_shell,
      image
    };

    Type       type     = Type::box;
    bool       subtract = false;
    Point<dim> lower_corner;
    Point<dim> upper_corner;
    Point<dim> center;
    /** Ellipsoid: semi-axes along x, y (, z); elliptic cylinder (3D): a, b
     *  of the ellipse in the x-y plane and the half-length along z. */
    Point<dim> semi_axes;
    /** Image: the voxel image and the value its voxels must hold. */
    std::shared_ptr<const VoxelImage<dim>> image;
    double                                 image_value  = 0.;
    double                                 inner_radius = 0.;
    double                                 outer_radius = 0.;
    /** The semi-shell keeps the half with (x - center) . direction >= 0. */
    Tensor<1, dim> direction;
    /** The rotation R applied to the primitive about pivot (identity if
     *  none): a point x belongs to it if pivot + R^T (x - pivot) belongs to
     *  the unrotated primitive. */
    Tensor<2, dim> rotation = unit_symmetric_tensor<dim>();
    Point<dim>     pivot;

    static void
    declare_parameters(ParameterHandler &prm);

    /** @p where names the subsection path for messages; a relative 'image
     *  file' is relative to @p prm_directory (empty: the working directory). */
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &where,
                     const std::string &prm_directory = "");

    /** Closed-set membership (points on the surface count as inside). */
    bool
    contains(const Point<dim> &x) const;

    /** Strict interior, for the overlap check between bodies at t = 0. */
    bool
    contains_strictly(const Point<dim> &x) const;

    BoundingBox<dim>
    bounding_box() const;

  private:
    /** Reads the image entries (type image). */
    void
    parse_image(ParameterHandler  &prm,
                const std::string &where,
                const std::string &prm_directory);

    /** The centre of the image's extent (its default pivot). */
    Point<dim>
    image_center() const;

    /** The unrotated bounding box. */
    BoundingBox<dim>
    unrotated_bounding_box() const;

    /** Signed measure that is <= 0 inside and > 0 outside. */
    double
    outside_measure(const Point<dim> &x) const;
  };
} // namespace bfemp

#endif
