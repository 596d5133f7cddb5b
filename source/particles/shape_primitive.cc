#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/base/rotation.h>
#include <bfemp/particles/shape_primitive.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

namespace bfemp
{
  template <int dim>
  void
  ShapePrimitive<dim>::declare_parameters(ParameterHandler &prm)
  {
    using namespace parameter_tools;
    prm.declare_entry("type",
                      "box",
                      Patterns::Selection(
                        "box|ball|disk|ellipse|ellipsoid|elliptic "
                        "cylinder|shell|ring|semi-ring|semi-shell|image"),
                      "[-] Primitive: box; ball (= disk in 2D); ellipsoid (= "
                      "ellipse in 2D) with 'semi-axes' along x, y (, z); "
                      "elliptic cylinder (3D: an ellipse of semi-axes a, b in "
                      "the x-y plane, half-length c along z; 2D: the "
                      "ellipse); shell (= ring in 2D) between inner and outer "
                      "radius; semi-ring (= semi-shell) is the half of a shell "
                      "on the side of 'direction'; image: the voxels of "
                      "'image file' that hold 'image value'. Tilt any of them "
                      "with 'rotation angle'.");
    prm.declare_entry("image file",
                      "",
                      Patterns::Anything(),
                      "[-] Image: a legacy VTK file (.vtk, DATASET "
                      "STRUCTURED_POINTS, ASCII or BINARY, one scalar of "
                      "type (unsigned) char/short/int, float or double, "
                      "POINT_DATA or CELL_DATA; 2D: one layer) or a raw file "
                      "(.raw, unsigned 8-bit, x fastest, with 'image size', "
                      "'image origin' and 'image spacing'). A relative path "
                      "is relative to the directory of the prm file that "
                      "sets it.");
    prm.declare_entry("image value",
                      "1",
                      Patterns::Double(),
                      "[-] Image: the value (label) of the voxels that belong "
                      "to the primitive (matched within 1/2).");
    declare_point<dim>(prm,
                       "image size",
                       components<dim>(1, 1, 1),
                       "[-] Raw image: voxels per direction");
    declare_point<dim>(prm,
                       "image origin",
                       components<dim>(0, 0, 0),
                       "[m] Raw image: centre of the first voxel");
    declare_point<dim>(prm,
                       "image spacing",
                       components<dim>(1, 1, 1),
                       "[m] Raw image: voxel size per direction");
    prm.declare_entry("operation",
                      "add",
                      Patterns::Selection("add|subtract"),
                      "[-] Unite with (add) or cut from (subtract) the "
                      "primitives before it.");
    declare_point<dim>(prm,
                       "lower corner",
                       components<dim>(0.4, 0.4, 0.4),
                       "[m] Box: lower corner");
    declare_point<dim>(prm,
                       "upper corner",
                       components<dim>(0.6, 0.6, 0.6),
                       "[m] Box: upper corner");
    declare_point<dim>(prm,
                       "center",
                       components<dim>(0.5, 0.5, 0.5),
                       "[m] Ball, shell, semi-ring: centre");
    declare_point<dim>(prm,
                       "semi-axes",
                       components<dim>(0.1, 0.05, 0.05),
                       "[m] Ellipsoid, elliptic cylinder: semi-axes a, b (, "
                       "c) along x, y (, z) before rotation, each > 0");
    prm.declare_entry("inner radius",
                      "0",
                      Patterns::Double(),
                      "[m] Shell, semi-ring: inner radius (>= 0, < outer).");
    prm.declare_entry("outer radius",
                      "0.1",
                      Patterns::Double(),
                      "[m] Ball, shell, semi-ring: outer radius (> 0).");
    declare_point<dim>(prm,
                       "direction",
                       components<dim>(0, 1, 0),
                       "[-] Semi-ring: the kept half is where (x - center) . "
                       "direction >= 0");
    prm.declare_entry("rotation angle",
                      "0",
                      Patterns::Double(),
                      std::string("[rad] Rotation of the primitive, "
                                  "counter-clockwise ") +
                        (dim == 2 ? "in the plane"
                                  : "about 'rotation axis' (right-hand rule)") +
                        ", about 'rotation center': a tilted box, an oriented "
                        "semi-ring.");
    if (dim == 3)
      declare_point<dim>(prm,
                         "rotation axis",
                         components<dim>(0, 0, 1),
                         "[-] 3D: axis of 'rotation angle' (any nonzero "
                         "vector)");
    prm.declare_entry("rotation center",
                      "",
                      Patterns::Anything(),
                      "[m] Pivot of 'rotation angle'; empty: the primitive's "
                      "own centre (box: the midpoint of its corners). Give the "
                      "primitives of a body one pivot to rotate the whole "
                      "body.");
  }



  template <int dim>
  void
  ShapePrimitive<dim>::parse_parameters(ParameterHandler  &prm,
                                        const std::string &where,
                                        const std::string &prm_directory)
  {
    using namespace parameter_tools;
    const std::string name = prm.get("type");
    // the 2D and 3D names of one shape map to one type
    const std::map<std::string, Type> types = {{"box", Type::box},
                                               {"ball", Type::ball},
                                               {"disk", Type::ball},
                                               {"ellipse", Type::ellipsoid},
                                               {"ellipsoid", Type::ellipsoid},
                                               {"elliptic cylinder",
                                                dim == 2
                                                  ? Type::ellipsoid
                                                  : Type::elliptic_cylinder},
                                               {"shell", Type::shell},
                                               {"ring", Type::shell},
                                               {"semi-ring", Type::semi_shell},
                                               {"semi-shell", Type::semi_shell},
                                               {"image", Type::image}};
    type                                    = types.at(name);
    if (type == Type::image)
      parse_image(prm, where, prm_directory); // before its pivot is taken
    subtract     = prm.get("operation") == "subtract";
    lower_corner = get_point<dim>(prm, "lower corner");
    upper_corner = get_point<dim>(prm, "upper corner");
    center       = get_point<dim>(prm, "center");
    inner_radius = prm.get_double("inner radius");
    outer_radius = prm.get_double("outer radius");
    direction    = get_vector<dim>(prm, "direction");
    semi_axes    = get_point<dim>(prm, "semi-axes");

    // the rotation (Rodrigues in 3D) about the pivot
    const double   angle = prm.get_double("rotation angle");
    Tensor<1, dim> axis;
    axis[dim - 1] = 1.;
    if constexpr (dim == 3)
      {
        axis = get_vector<dim>(prm, "rotation axis");
        require_input(axis.norm() > 0.,
                      where,
                      "rotation axis",
                      to_input_string(Point<dim>(axis)),
                      "must be a nonzero vector");
      }
    rotation                     = rotation_matrix<dim>(angle, axis);
    const std::string pivot_text = Utilities::trim(prm.get("rotation center"));
    if (pivot_text.empty())
      pivot = type == Type::image ? image_center()
              : type == Type::box
                ? Point<dim>(0.5 * (lower_corner + upper_corner))
                : center;
    else
      {
        const auto numbers = Utilities::split_string_list(pivot_text, ',');
        require_input(numbers.size() == dim,
                      where,
                      "rotation center",
                      pivot_text,
                      "must be empty or " + std::to_string(dim) +
                        " comma-separated numbers [m]");
        for (unsigned int d = 0; d < dim; ++d)
          {
            char        *end   = nullptr;
            const double value = std::strtod(numbers[d].c_str(), &end);
            require_input(end != numbers[d].c_str() && *end == '\0' &&
                            std::isfinite(value),
                          where,
                          "rotation center",
                          pivot_text,
                          "must be empty or " + std::to_string(dim) +
                            " comma-separated numbers [m]");
            pivot[d] = value;
          }
      }

    if (type == Type::ellipsoid || type == Type::elliptic_cylinder)
      for (unsigned int d = 0; d < dim; ++d)
        require_input(semi_axes[d] > 0.,
                      where,
                      "semi-axes",
                      to_input_string(semi_axes),
                      "must be > 0 in every direction [m]");
    else if (type == Type::box)
      for (unsigned int d = 0; d < dim; ++d)
        require_input(upper_corner[d] > lower_corner[d],
                      where,
                      "upper corner",
                      to_input_string(upper_corner),
                      "must exceed 'lower corner' (" +
                        to_input_string(lower_corner) + ") in every direction");
    else
      {
        require_input(outer_radius > 0.,
                      where,
                      "outer radius",
                      to_input_string(outer_radius),
                      "must be > 0 [m]");
        if (type != Type::ball)
          require_input(inner_radius >= 0. && inner_radius < outer_radius,
                        where,
                        "inner radius",
                        to_input_string(inner_radius),
                        "must be >= 0 and < the outer radius (" +
                          to_input_string(outer_radius) + ")");
        if (type == Type::semi_shell)
          require_input(direction.norm() > 0.,
                        where,
                        "direction",
                        to_input_string(Point<dim>(direction)),
                        "must be a nonzero vector");
      }
  }



  template <int dim>
  void
  ShapePrimitive<dim>::parse_image(ParameterHandler  &prm,
                                   const std::string &where,
                                   const std::string &prm_directory)
  {
    using namespace parameter_tools;
    const std::string entry = Utilities::trim(prm.get("image file"));
    require_input(!entry.empty(),
                  where,
                  "image file",
                  "''",
                  "type = image needs the path of a .vtk or .raw file");
    std::filesystem::path path(entry);
    if (path.is_relative() && !prm_directory.empty())
      path = std::filesystem::path(prm_directory) / path;
    require_input(std::filesystem::is_regular_file(path),
                  where,
                  "image file",
                  path.string(),
                  "no such file (a relative path is relative to the directory "
                  "of the prm file that sets it)");
    const Point<dim>              size = get_point<dim>(prm, "image size");
    std::array<unsigned int, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      {
        require_input(size[d] >= 1. && size[d] == std::floor(size[d]),
                      where,
                      "image size",
                      to_input_string(size),
                      "must be whole numbers >= 1");
        n[d] = static_cast<unsigned int>(size[d]);
      }
    try
      {
        image = std::make_shared<const VoxelImage<dim>>(
          VoxelImage<dim>::read(path.string(),
                                n,
                                get_point<dim>(prm, "image origin"),
                                get_point<dim>(prm, "image spacing")));
      }
    catch (const InputError &error)
      {
        throw InputError("subsection '" + where +
                         "', entry 'image file': " + error.what());
      }
    image_value = prm.get_double("image value");
  }



  template <int dim>
  Point<dim>
  ShapePrimitive<dim>::image_center() const
  {
    const auto corners = image->bounding_box().get_boundary_points();
    return Point<dim>(0.5 * (corners.first + corners.second));
  }



  template <int dim>
  double
  ShapePrimitive<dim>::outside_measure(const Point<dim> &rotated_x) const
  {
    // back to the unrotated primitive: x = pivot + R^T (x' - pivot)
    const Point<dim> x = pivot + transpose(rotation) * (rotated_x - pivot);
    switch (type)
      {
        case Type::box:
          {
            double measure = -std::numeric_limits<double>::max();
            for (unsigned int d = 0; d < dim; ++d)
              measure = std::max(
                {measure, lower_corner[d] - x[d], x[d] - upper_corner[d]});
            return measure;
          }
        case Type::ball:
          return x.distance(center) - outer_radius;
        case Type::ellipsoid:
        case Type::elliptic_cylinder:
          {
            // (|A^-1 (x - c)| - 1) min a over the ellipse's axes: its sign
            // is membership, its size is a length
            const unsigned int n_axes = type == Type::ellipsoid ? dim : dim - 1;
            double             r2 = 0., smallest = semi_axes[0];
            for (unsigned int d = 0; d < n_axes; ++d)
              {
                r2 += std::pow((x[d] - center[d]) / semi_axes[d], 2);
                smallest = std::min(smallest, semi_axes[d]);
              }
            double measure = (std::sqrt(r2) - 1.) * smallest;
            if (type == Type::elliptic_cylinder)
              measure = std::max(measure,
                                 std::abs(x[dim - 1] - center[dim - 1]) -
                                   semi_axes[dim - 1]);
            return measure;
          }
        case Type::image:
          {
            // membership only: -1 inside, 1 outside (NaN outside the image)
            const double v = image->value(x);
            return std::abs(v - image_value) < 0.5 ? -1. : 1.;
          }
        case Type::shell:
        case Type::semi_shell:
          {
            const double r       = x.distance(center);
            double       measure = std::max(r - outer_radius, inner_radius - r);
            if (type == Type::semi_shell)
              measure =
                std::max(measure,
                         -((x - center) * direction) / direction.norm());
            return measure;
          }
      }
    return 1.;
  }



  template <int dim>
  bool
  ShapePrimitive<dim>::contains(const Point<dim> &x) const
  {
    return outside_measure(x) <= 0.;
  }



  template <int dim>
  bool
  ShapePrimitive<dim>::contains_strictly(const Point<dim> &x) const
  {
    return outside_measure(x) < 0.;
  }



  template <int dim>
  BoundingBox<dim>
  ShapePrimitive<dim>::bounding_box() const
  {
    // the box around the rotated corners of the unrotated box
    const BoundingBox<dim> box = unrotated_bounding_box();
    Point<dim>             lower, upper;
    for (unsigned int v = 0; v < (1u << dim); ++v)
      {
        Point<dim> corner;
        for (unsigned int d = 0; d < dim; ++d)
          corner[d] = (v >> d) & 1 ? box.get_boundary_points().second[d]
                                   : box.get_boundary_points().first[d];
        const Point<dim> x = pivot + rotation * (corner - pivot);
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = v == 0 ? x[d] : std::min(lower[d], x[d]);
            upper[d] = v == 0 ? x[d] : std::max(upper[d], x[d]);
          }
      }
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }



  template <int dim>
  BoundingBox<dim>
  ShapePrimitive<dim>::unrotated_bounding_box() const
  {
    if (type == Type::box)
      return BoundingBox<dim>(std::make_pair(lower_corner, upper_corner));
    if (type == Type::image)
      return image->bounding_box();
    const bool elliptic =
      type == Type::ellipsoid || type == Type::elliptic_cylinder;
    Point<dim> lower = center, upper = center;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] -= elliptic ? semi_axes[d] : outer_radius;
        upper[d] += elliptic ? semi_axes[d] : outer_radius;
      }
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }



  template struct ShapePrimitive<2>;
  template struct ShapePrimitive<3>;
} // namespace bfemp
