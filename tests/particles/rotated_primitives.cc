// Rotated shape primitives ('rotation angle', 'rotation axis', 'rotation
// center' of a primitive), as read from prm text:
// - a 2D box 0.4 x 0.1 tilted by 30 degrees about its centre: its rotated
//   corners are its corners, a point beyond a rotated end is not, the unrotated
//   corner is not; its bounding box is that of the rotated corners; the
//   sampled particles all lie in it and their volume is the box's (0.04)
//   within the sampling error;
// - a 3D box rotated by 45 degrees about the axis (1, 1, 0): sampled volume;
// - a CSG body (a box minus a disk) rotated by 90 degrees about one common
//   pivot: the hole moves with the box;
// - a zero rotation axis is refused, naming the entry.

#include <bfemp/base/input_error.h>
#include <bfemp/grid/lattice.h>
#include <bfemp/particles/body_sampler.h>
#include <bfemp/particles/shape_primitive.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  template <int dim>
  ShapePrimitive<dim>
  read(const std::string &entries)
  {
    ParameterHandler prm;
    ShapePrimitive<dim>::declare_parameters(prm);
    prm.parse_input_from_string(entries);
    ShapePrimitive<dim> primitive;
    primitive.parse_parameters(prm, "body 0/primitive 0");
    return primitive;
  }

  template <int dim>
  double
  sampled_volume(const std::vector<ShapePrimitive<dim>> &primitives,
                 const unsigned int                      n_cells,
                 bool                                   &all_inside)
  {
    BodyParameters<dim> body;
    body.primitives              = primitives;
    body.particles_per_direction = 2;
    std::array<unsigned int, dim> cells;
    cells.fill(n_cells);
    const Lattice<dim>     lattice(Point<dim>(), 1. / n_cells, cells);
    const BodySampler<dim> sampler(body, lattice);
    const Shape<dim>       shape(primitives);
    const auto             particles = sampler.sample();
    all_inside                       = true;
    for (const Point<dim> &x : particles)
      all_inside = all_inside && shape.contains(x);
    return particles.size() * sampler.particle_volume();
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  {
    const ShapePrimitive<2> box =
      read<2>("set type = box\n"
              "set lower corner = 0.3, 0.45\n"
              "set upper corner = 0.7, 0.55\n"
              "set rotation angle = 0.5235987755982988\n");
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    const auto   rotated = [&](const double x, const double y) {
      return Point<2>(0.5 + c * x - s * y, 0.5 + s * x + c * y);
    };
    bool corners = true;
    for (const double x : {-0.2, 0.2})
      for (const double y : {-0.05, 0.05})
        corners = corners && box.contains(rotated(0.999 * x, 0.99 * y)) &&
                  !box.contains(rotated(1.001 * x, 1.01 * y));
    bfemp_tests::check(corners,
                       "2D: the rotated corners are the box's (inside by "
                       "0.1 %, outside beyond)");
    bfemp_tests::check(!box.contains(rotated(0.21, 0.)) &&
                         box.contains(rotated(0.19, 0.)) &&
                         !box.contains(Point<2>(0.3, 0.45)),
                       "2D: beyond a rotated end and the unrotated corner are "
                       "outside, inside the end is inside");
    const auto b = box.bounding_box().get_boundary_points();
    bfemp_tests::check(std::abs(b.first[0] - rotated(-0.2, 0.05)[0]) < 1e-14 &&
                         std::abs(b.second[1] - rotated(0.2, 0.05)[1]) < 1e-14,
                       "2D: the bounding box is that of the rotated corners");
    bool         inside = false;
    const double volume = sampled_volume<2>({box}, 256, inside);
    deallog << "2D tilted box: sampled area " << std::setprecision(4) << volume
            << " (exact 0.04)" << std::setprecision(8) << std::endl;
    bfemp_tests::check(inside && std::abs(volume - 0.04) < 0.02 * 0.04,
                       "2D: the particles lie in the tilted box, area within "
                       "2 %");
  }

  {
    const ShapePrimitive<3> box =
      read<3>("set type = box\n"
              "set lower corner = 0.3, 0.4, 0.4\n"
              "set upper corner = 0.7, 0.6, 0.6\n"
              "set rotation angle = 0.7853981633974483\n"
              "set rotation axis = 1, 1, 0\n");
    bool         inside = false;
    const double volume = sampled_volume<3>({box}, 64, inside);
    deallog << "3D rotated box: sampled volume " << std::setprecision(4)
            << volume << " (exact 0.016)" << std::setprecision(8) << std::endl;
    bfemp_tests::check(inside && std::abs(volume - 0.016) < 0.05 * 0.016,
                       "3D: the particles lie in the rotated box, volume "
                       "within 5 %");
  }

  {
    // a plate with a hole at its right end, turned upright about (0.5, 0.5)
    const ShapePrimitive<2> plate =
      read<2>("set type = box\n"
              "set lower corner = 0.3, 0.45\n"
              "set upper corner = 0.7, 0.55\n"
              "set rotation angle = 1.5707963267948966\n"
              "set rotation center = 0.5, 0.5\n");
    const ShapePrimitive<2> hole =
      read<2>("set type = disk\n"
              "set operation = subtract\n"
              "set center = 0.65, 0.5\n"
              "set outer radius = 0.03\n"
              "set rotation angle = 1.5707963267948966\n"
              "set rotation center = 0.5, 0.5\n");
    const Shape<2> shape({plate, hole});
    bfemp_tests::check(!shape.contains(Point<2>(0.5, 0.65)) &&
                         shape.contains(Point<2>(0.5, 0.35)) &&
                         !shape.contains(Point<2>(0.65, 0.5)),
                       "2D CSG: plate and hole turn together about the common "
                       "pivot");
  }

  try
    {
      read<3>("set rotation angle = 1\nset rotation axis = 0, 0, 0\n");
      bfemp_tests::check(false, "a zero rotation axis is refused");
    }
  catch (const InputError &error)
    {
      deallog << error.what() << std::endl;
      bfemp_tests::check(std::string(error.what()).find("rotation axis") !=
                           std::string::npos,
                         "a zero rotation axis is refused, naming the entry");
    }
}
