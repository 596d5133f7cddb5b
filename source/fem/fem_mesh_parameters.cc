#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/fem/fem_mesh_parameters.h>

#include <cmath>
#include <filesystem>

namespace bfemp
{
  namespace
  {
    /** At most this many elements: more is a typo in the edge length, not
     *  a mesh anyone can solve on one machine. */
    constexpr double max_elements = 1e7;
  } // namespace



  template <int dim>
  void
  FemMeshParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    using namespace parameter_tools;
    prm.declare_entry(
      "source",
      "rectangle",
      Patterns::Selection("rectangle|disk|ring|semi-ring|file"),
      "[-] Where the linear simplex mesh comes from. rectangle: the box "
      "[lower corner, upper corner] (a thin plate is a rectangle with one "
      "short side); disk: a disk of 'outer radius' about 'center'; ring: the "
      "annulus between 'inner radius' and 'outer radius'; semi-ring: the half "
      "of that ring with y >= center_y; file: the gmsh mesh or geometry in "
      "'file'. In 3D the same names mean box, ball, spherical shell and half "
      "spherical shell. disk, ring and semi-ring are meshed by the gmsh "
      "binary.");
    declare_point<dim>(prm,
                       "lower corner",
                       components<dim>(0, 0, 0),
                       "[m] rectangle: lower corner");
    declare_point<dim>(prm,
                       "upper corner",
                       components<dim>(1, 1, 1),
                       "[m] rectangle: upper corner (> lower corner in every "
                       "direction)");
    declare_point<dim>(prm,
                       "center",
                       components<dim>(0.5, 0.5, 0.5),
                       "[m] disk, ring, semi-ring: centre. For every source "
                       "also the pivot of 'rotation angle'");
    prm.declare_entry("inner radius",
                      "0.15",
                      Patterns::Double(),
                      "[m] ring, semi-ring: inner radius (> 0, < outer "
                      "radius).");
    prm.declare_entry("outer radius",
                      "0.25",
                      Patterns::Double(),
                      "[m] disk, ring, semi-ring: outer radius (> 0).");
    prm.declare_entry("target edge length",
                      "0.05",
                      Patterns::Double(),
                      "[m] Element edge length asked of the mesher (> 0): "
                      "rectangle: ceil(side / length) subdivisions per "
                      "direction, each square split into 2 triangles (each "
                      "cube into 5 tetrahedra); disk, ring, semi-ring and "
                      ".geo files: gmsh's -clmax. Ignored for .msh files.");
    prm.declare_entry("file",
                      "",
                      Patterns::Anything(),
                      "[-] file: a gmsh mesh (.msh, ASCII format 2 or 4, "
                      "triangles in 2D or tetrahedra in 3D) or a gmsh "
                      "geometry (.geo, meshed by the gmsh binary with "
                      "-clmax = 'target edge length'). Physical groups of "
                      "boundary lines/faces become boundary ids. A relative "
                      "path is relative to the directory of the prm file "
                      "that sets this entry (also when that file is "
                      "included from elsewhere).");
    prm.declare_entry("rotation angle",
                      "0",
                      Patterns::Double(),
                      "[rad] Rotation of the mesh after generation or "
                      "reading, counter-clockwise about 'center' (3D: about "
                      "'rotation axis' through 'center', right-hand rule).");
    if (dim == 3)
      declare_point<dim>(prm,
                         "rotation axis",
                         components<dim>(0, 0, 1),
                         "[-] 3D: axis of 'rotation angle' (any nonzero "
                         "vector)");
    declare_point<dim>(prm,
                       "translation",
                       components<dim>(0, 0, 0),
                       "[m] Shift of the mesh, applied after the rotation");
  }



  template <int dim>
  void
  FemMeshParameters<dim>::parse_parameters(ParameterHandler  &prm,
                                           const std::string &where,
                                           const std::string &prm_directory)
  {
    using namespace parameter_tools;
    const std::string name = prm.get("source");
    source                 = (name == "rectangle")   ? Source::rectangle
                             : (name == "disk")      ? Source::disk
                             : (name == "ring")      ? Source::ring
                             : (name == "semi-ring") ? Source::semi_ring
                                                     : Source::file;
    lower_corner           = get_point<dim>(prm, "lower corner");
    upper_corner           = get_point<dim>(prm, "upper corner");
    center                 = get_point<dim>(prm, "center");
    inner_radius           = prm.get_double("inner radius");
    outer_radius           = prm.get_double("outer radius");
    target_edge_length     = prm.get_double("target edge length");
    rotation_angle         = prm.get_double("rotation angle");
    rotation_axis          = Tensor<1, dim>();
    rotation_axis[dim - 1] = 1.;
    if (dim == 3)
      rotation_axis = get_vector<dim>(prm, "rotation axis");
    translation = get_vector<dim>(prm, "translation");
    file.clear();

    require_input(target_edge_length > 0. && std::isfinite(target_edge_length),
                  where,
                  "target edge length",
                  to_input_string(target_edge_length),
                  "must be > 0 [m]");
    require_input(std::isfinite(rotation_angle),
                  where,
                  "rotation angle",
                  prm.get("rotation angle"),
                  "must be a finite number [rad]");
    require_input(rotation_axis.norm() > 0.,
                  where,
                  "rotation axis",
                  to_input_string(Point<dim>(rotation_axis)),
                  "must be a nonzero vector");

    switch (source)
      {
        case Source::rectangle:
          for (unsigned int d = 0; d < dim; ++d)
            require_input(upper_corner[d] > lower_corner[d],
                          where,
                          "upper corner",
                          to_input_string(upper_corner),
                          "must exceed 'lower corner' (" +
                            to_input_string(lower_corner) +
                            ") in every direction");
          break;
        case Source::disk:
        case Source::ring:
        case Source::semi_ring:
          require_input(outer_radius > 0.,
                        where,
                        "outer radius",
                        to_input_string(outer_radius),
                        "must be > 0 [m]");
          if (source != Source::disk)
            require_input(inner_radius > 0. && inner_radius < outer_radius,
                          where,
                          "inner radius",
                          to_input_string(inner_radius),
                          "must be > 0 and < the outer radius (" +
                            to_input_string(outer_radius) + ") for a " +
                            source_name());
          break;
        case Source::file:
          {
            const std::string entry = prm.get("file");
            require_input(!entry.empty(),
                          where,
                          "file",
                          "''",
                          "source = file needs the path of a gmsh .msh or "
                          ".geo file");
            std::filesystem::path path(entry);
            if (path.is_relative() && !prm_directory.empty())
              path = std::filesystem::path(prm_directory) / path;
            file                        = path.string();
            const std::string extension = path.extension().string();
            require_input(extension == ".msh" || extension == ".geo",
                          where,
                          "file",
                          file,
                          "must end in .msh (a gmsh mesh) or .geo (a gmsh "
                          "geometry)");
            require_input(std::filesystem::is_regular_file(path),
                          where,
                          "file",
                          file,
                          "no such file (a relative path is relative to the "
                          "directory of the prm file that sets it, '" +
                            prm_directory + "')");
            break;
          }
      }

    if (source != Source::file)
      {
        const double n = estimated_number_of_elements();
        require_input(n <= max_elements,
                      where,
                      "target edge length",
                      to_input_string(target_edge_length),
                      "gives about " + to_input_string(std::round(n)) +
                        " elements for this " + source_name() +
                        "; at most 1e7 are allowed, use a larger length");
      }
  }



  template <int dim>
  std::string
  FemMeshParameters<dim>::source_name() const
  {
    switch (source)
      {
        case Source::rectangle:
          return dim == 2 ? "rectangle" : "box";
        case Source::disk:
          return dim == 2 ? "disk" : "ball";
        case Source::ring:
          return dim == 2 ? "ring" : "spherical shell";
        case Source::semi_ring:
          return dim == 2 ? "semi-ring" : "half spherical shell";
        case Source::file:
          return "file '" + file + "'";
      }
    return "";
  }



  template <int dim>
  std::vector<unsigned int>
  FemMeshParameters<dim>::rectangle_subdivisions() const
  {
    std::vector<unsigned int> result(dim);
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double ratio =
          (upper_corner[d] - lower_corner[d]) / target_edge_length;
        result[d] = static_cast<unsigned int>(
          std::max(1., std::min(std::ceil(ratio * (1. - 1e-12)), 1e9)));
      }
    return result;
  }



  template <int dim>
  double
  FemMeshParameters<dim>::exact_measure() const
  {
    const double ball_factor = dim == 2 ? M_PI : 4. / 3. * M_PI;
    switch (source)
      {
        case Source::rectangle:
          {
            double measure = 1.;
            for (unsigned int d = 0; d < dim; ++d)
              measure *= upper_corner[d] - lower_corner[d];
            return measure;
          }
        case Source::disk:
          return ball_factor * std::pow(outer_radius, dim);
        case Source::ring:
          return ball_factor *
                 (std::pow(outer_radius, dim) - std::pow(inner_radius, dim));
        case Source::semi_ring:
          return 0.5 * ball_factor *
                 (std::pow(outer_radius, dim) - std::pow(inner_radius, dim));
        case Source::file:
          break;
      }
    return 0.;
  }



  template <int dim>
  double
  FemMeshParameters<dim>::estimated_number_of_elements() const
  {
    if (source == Source::rectangle)
      {
        // Counted in double: the product may not fit an unsigned int.
        double n = (dim == 2 ? 2. : 5.);
        for (unsigned int d = 0; d < dim; ++d)
          n *= std::max(1.,
                        std::ceil((upper_corner[d] - lower_corner[d]) /
                                  target_edge_length));
        return n;
      }
    // Equilateral triangle sqrt(3)/4 h^2, regular tetrahedron h^3/(6 sqrt 2).
    const double element =
      dim == 2 ? std::sqrt(3.) / 4. * std::pow(target_edge_length, 2)
               : std::pow(target_edge_length, 3) / (6. * std::sqrt(2.));
    return exact_measure() / element;
  }



  template struct FemMeshParameters<2>;
  template struct FemMeshParameters<3>;
} // namespace bfemp
