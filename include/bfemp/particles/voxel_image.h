#ifndef bfemp_particles_voxel_image_h
#define bfemp_particles_voxel_image_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * A voxel image of a material map (a CT scan, a segmented micrograph): a
   * regular lattice of samples with origin, spacing and one scalar value per
   * sample, read from
   * - a legacy VTK file (DATASET STRUCTURED_POINTS, ASCII or BINARY, one
   *   scalar component of type unsigned_char, char, unsigned_short, short,
   *   unsigned_int, int, float or double, as ParaView and ITK write them), or
   * - a raw file of unsigned 8-bit values, x fastest, whose dimensions,
   *   origin and spacing the prm file gives.
   * Sample i stands for the voxel [origin + (i - 1/2) spacing, origin +
   * (i + 1/2) spacing]. In 2D the image has one layer (a third dimension of
   * 1 in the VTK file).
   */
  template <int dim>
  class VoxelImage
  {
  public:
    /** Reads @p file (.vtk or .raw); throws an InputError naming the file
     *  and what is wrong. @p raw_size, @p raw_origin and @p raw_spacing
     *  describe a .raw file and are ignored for .vtk. */
    static VoxelImage
    read(const std::string                   &file,
         const std::array<unsigned int, dim> &raw_size,
         const Point<dim>                    &raw_origin,
         const Point<dim>                    &raw_spacing);

    /** The value of the voxel containing @p x; NaN outside the image. */
    double
    value(const Point<dim> &x) const;

    /** The voxels' extent. */
    BoundingBox<dim>
    bounding_box() const;

    /** Number of samples per direction. */
    const std::array<unsigned int, dim> &
    size() const;

  private:
    static VoxelImage
    read_vtk(const std::string &file);

    static VoxelImage
    read_raw(const std::string                   &file,
             const std::array<unsigned int, dim> &size,
             const Point<dim>                    &origin,
             const Point<dim>                    &spacing);

    std::array<unsigned int, dim> n;
    Point<dim>                    origin;
    Point<dim>                    spacing;
    /** Sample values, x fastest. */
    std::vector<double> values;
  };
} // namespace bfemp

#endif
