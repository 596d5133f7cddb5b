#ifndef bfemp_fem_fem_mesh_parameters_h
#define bfemp_fem_fem_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * prm subsection "mesh" of an FEM body: where its linear simplex mesh comes
   * from and where it is placed. The caller enters the subsection; this
   * struct declares and reads the entries inside it.
   *
   * The generated shapes have 2D names; in 3D the same names mean the 3D
   * analogue (rectangle = box, disk = ball, ring = spherical shell,
   * semi-ring = half spherical shell), so a scene switches dimension without
   * renaming. A thin plate is a rectangle (box) with one short side.
   *
   * After generation or reading, the mesh is rotated by "rotation angle"
   * about "center" (3D: about the z axis through "center") and then moved by
   * "translation", so a mesh file written in its own coordinates can be
   * placed in the scene.
   */
  template <int dim>
  struct FemMeshParameters
  {
    enum class Source
    {
      /** A box [lower corner, upper corner] (entry value "rectangle"). */
      rectangle,
      /** A disk (2D) or ball (3D) of "outer radius" about "center". */
      disk,
      /** A ring (2D) or spherical shell (3D) between the two radii. */
      ring,
      /** The half of a ring or shell with y >= center_y. */
      semi_ring,
      /** A gmsh .msh or .geo file. */
      file
    };

    /** Entry "source". */
    Source source = Source::rectangle;

    /** Entries "lower corner" and "upper corner" (rectangle/box). */
    Point<dim> lower_corner;
    Point<dim> upper_corner;

    /** Entry "center": of disk, ring, semi-ring, and the rotation pivot. */
    Point<dim> center;

    /** Entries "inner radius" (ring, semi-ring) and "outer radius". */
    double inner_radius = 0.;
    double outer_radius = 0.;

    /** Entry "target edge length" [m]: the element size asked of the
     *  generator (rectangle subdivisions, gmsh -clmax). */
    double target_edge_length = 0.;

    /** Entry "file", resolved against the directory of the prm file that
     *  sets it: the path that is opened. Empty unless source == file. */
    std::string file;

    /** Entry "rotation angle" [rad]. */
    double rotation_angle = 0.;

    /** Entry "rotation axis" (3D; the z axis in 2D). */
    Tensor<1, dim> rotation_axis;

    /** Entry "translation" [m]. */
    Tensor<1, dim> translation;

    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Reads the entries of the current subsection and checks them. @p where
     * names the subsection path for messages (e.g. "fem body 0/mesh");
     * @p prm_directory is the directory of the prm file that sets "file",
     * against which a relative "file" is resolved. Throws an InputError naming
     * subsection, entry, value and what is allowed.
     */
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &where,
                     const std::string &prm_directory);

    /** The user's name of the source in this dimension ("disk", "ball"). */
    std::string
    source_name() const;

    /** Rectangle/box: elements per direction, ceil(length / target edge
     *  length) (at least 1; a ratio within 1e-12 of an integer counts as
     *  that integer, so 1/0.1 gives 10). */
    std::vector<unsigned int>
    rectangle_subdivisions() const;

    /** The exact area/volume of a generated shape (not for files). */
    double
    exact_measure() const;

    /** A rough number of elements a generated shape gets with the target
     *  edge length (not for files): to refuse absurd requests early. */
    double
    estimated_number_of_elements() const;
  };
} // namespace bfemp

#endif
