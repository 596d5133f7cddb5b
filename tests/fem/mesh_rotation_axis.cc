// FEM meshes rotate about any axis in 3D ('mesh/rotation axis'): a box mesh
// [0, 1] x [0, 0.2] x [0, 0.3] turned by 120 degrees about (1, 1, 1)
// through the origin maps (x, y, z) to (z, x, y), so its nodes span
// [0, 0.3] x [0, 1] x [0, 0.2]; turned by 90 degrees about the x axis through
// (0.5, 0.1, 0.15) it spans [0, 1] x [-0.05, 0.25] x [0.05, 0.25]; the
// default axis (z) keeps the earlier behaviour; a zero axis is refused.

#include <bfemp/base/input_error.h>
#include <bfemp/fem/fem_mesh.h>
#include <bfemp/fem/fem_mesh_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

#include "tests.h"

using namespace dealii;

namespace
{
  bfemp::FemMeshParameters<3>
  parameters(const std::string &entries)
  {
    ParameterHandler prm;
    prm.enter_subsection("mesh");
    bfemp::FemMeshParameters<3>::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string(
      "subsection mesh\nset source = rectangle\n"
      "set lower corner = 0, 0, 0\nset upper corner = 1, 0.2, 0.3\n"
      "set target edge length = 0.1\n" +
      entries + "\nend\n");
    bfemp::FemMeshParameters<3> result;
    prm.enter_subsection("mesh");
    result.parse_parameters(prm, "fem body 0/mesh", ".");
    prm.leave_subsection();
    return result;
  }

  /** Largest distance of the nodes' bounding box from [lower, upper]. */
  double
  box_error(const bfemp::FemMesh<3> &mesh,
            const Point<3>          &lower,
            const Point<3>          &upper)
  {
    Point<3> low = mesh.rest_position(0), high = mesh.rest_position(0);
    for (unsigned int a = 0; a < mesh.n_nodes(); ++a)
      for (unsigned int d = 0; d < 3; ++d)
        {
          low[d]  = std::min(low[d], mesh.rest_position(a)[d]);
          high[d] = std::max(high[d], mesh.rest_position(a)[d]);
        }
    // round-off below the printed digits must not print as -0.000000
    const auto clean = [](const double v) {
      return std::abs(v) < 5e-7 ? 0. : v;
    };
    char span[160];
    std::snprintf(span,
                  sizeof(span),
                  "nodes span %.6f %.6f %.6f .. %.6f %.6f %.6f",
                  clean(low[0]),
                  clean(low[1]),
                  clean(low[2]),
                  clean(high[0]),
                  clean(high[1]),
                  clean(high[2]));
    deallog << span << std::endl;
    return std::max(low.distance(lower), high.distance(upper));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  const bfemp::FemMesh<3> turned(
    parameters("set center = 0, 0, 0\n"
               "set rotation angle = 2.0943951023931953\n"
               "set rotation axis = 1, 1, 1"));
  bfemp_tests::check(box_error(turned,
                               Point<3>(0, 0, 0),
                               Point<3>(0.3, 1, 0.2)) < 1e-12,
                     "120 degrees about (1, 1, 1): (x, y, z) -> (z, x, y)");

  const bfemp::FemMesh<3> about_x(
    parameters("set center = 0.5, 0.1, 0.15\n"
               "set rotation angle = 1.5707963267948966\n"
               "set rotation axis = 1, 0, 0"));
  bfemp_tests::check(box_error(about_x,
                               Point<3>(0, -0.05, 0.05),
                               Point<3>(1, 0.25, 0.25)) < 1e-12,
                     "90 degrees about the x axis through the centre");

  const bfemp::FemMesh<3> about_z(
    parameters("set center = 0, 0, 0\n"
               "set rotation angle = 1.5707963267948966"));
  bfemp_tests::check(
    box_error(about_z, Point<3>(-0.2, 0, 0), Point<3>(0, 1, 0.3)) < 1e-12,
    "the default axis is z: 90 degrees maps (x, y) to (-y, x)");

  try
    {
      parameters("set rotation angle = 1\nset rotation axis = 0, 0, 0");
      bfemp_tests::check(false, "a zero rotation axis is refused");
    }
  catch (const bfemp::InputError &error)
    {
      deallog << error.what() << std::endl;
      bfemp_tests::check(std::string(error.what()).find("rotation axis") !=
                           std::string::npos,
                         "a zero rotation axis is refused, naming the entry");
    }
}
