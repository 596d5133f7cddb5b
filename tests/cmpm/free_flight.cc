// A heterogeneous block on cMPM in free flight, 2D and 3D: two bodies of
// different stiffness (E 1e5 and 1e7, the soft one a ball inside the stiff
// one's cube), one initial velocity, gravity, no walls, backward Euler. The
// consistent inertia over the particles and the partition of unity of Phi
// keep the linear momentum: the centre-of-mass velocity must follow
// v_0 + g t to 1e-5 m/s (Newton tolerance 1e-7 m/s), and the block must not
// deform (a rigid translation is exact in cMPM's space, so the elastic energy
// stays at round-off).

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "diagnostics_csv.h"
#include "tests.h"

using namespace dealii;

namespace
{
  template <int dim>
  void
  test()
  {
    const std::string name = "free_flight_" + std::to_string(dim) + "d";
    const std::string v0   = dim == 2 ? "0.5, 1" : "0.5, 1, -0.25";
    const std::string g    = dim == 2 ? "0, -9.81" : "0, -9.81, 0";
    const std::string zero = dim == 2 ? "0, 0" : "0, 0, 0";
    const std::string one  = dim == 2 ? "1, 1" : "1, 1, 1";
    const std::string lo   = dim == 2 ? "0.25, 0.25" : "0.25, 0.25, 0.25";
    const std::string hi   = dim == 2 ? "0.75, 0.75" : "0.75, 0.75, 0.75";
    const std::string mid  = dim == 2 ? "0.5, 0.5" : "0.5, 0.5, 0.5";
    // one particle per fine knot span and direction in 3D, two in 2D
    const unsigned int ppc = dim == 2 ? 6 : 3;
    {
      std::ofstream prm(name + ".prm");
      prm << "set dimension = " << dim
          << "\nset number of bodies = 2\n"
             "subsection run\n  set name = "
          << name
          << "\n  set end time = 0.05\n  set quiet = true\nend\n"
             "subsection grid\n  set lower corner = "
          << zero << "\n  set upper corner = " << one
          << "\n  set cell size = 0.125\nend\n"
             "subsection cmpm\n  set enabled = true\n"
             "  set fine nodes per direction = 5\nend\n"
             "subsection time\n  set integrator = implicit backward Euler\n"
             "  set time step mode = fixed\n  set time step = 0.01\nend\n"
             "subsection transfer\n  set scheme = PIC\nend\n"
             "subsection gravity\n  set acceleration = "
          << g
          << "\nend\n"
             "subsection boundaries\n  set walls = none\nend\n"
             "subsection solver\n  set Newton tolerance = 1e-7\nend\n"
             "subsection output\n  set directory = results\n"
             "  set interval = 0.05\nend\n"
             "subsection body 0\n  set particles per cell = "
          << ppc
          << "\n"
             "  set initial velocity = "
          << v0
          << "\n  set number of primitives = 2\n"
             "  subsection primitive 0\n    set type = box\n"
             "    set lower corner = "
          << lo << "\n    set upper corner = " << hi
          << "\n  end\n"
             "  subsection primitive 1\n    set type = ball\n"
             "    set operation = subtract\n    set center = "
          << mid
          << "\n    set outer radius = 0.15\n  end\n"
             "  subsection material\n    set Young's modulus = 1e7\n"
             "    set density = 1000\n  end\nend\n"
             "subsection body 1\n  set particles per cell = "
          << ppc
          << "\n"
             "  set initial velocity = "
          << v0
          << "\n  subsection primitive 0\n    set type = ball\n"
             "    set center = "
          << mid
          << "\n    set outer radius = 0.15\n  end\n"
             "  subsection material\n    set Young's modulus = 1e5\n"
             "    set density = 500\n  end\nend\n";
    }
    bfemp::SceneParameters<dim> parameters;
    parameters.read(name + ".prm");
    std::ostringstream     console;
    bfemp::Simulation<dim> simulation(parameters, name + ".prm", console);
    simulation.run();

    std::vector<std::string> columns = {"time", "elastic_energy", "mass"};
    const std::string        axes[3] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      columns.push_back("momentum_" + axes[d]);
    const auto c =
      bfemp_tests::read_columns("results/" + name + "/diagnostics.csv",
                                columns);
    const std::size_t last  = c[0].size() - 1;
    const double      t     = c[0][last];
    const double      v[3]  = {0.5, 1., -0.25};
    double            error = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double expected = v[d] + (d == 1 ? -9.81 * t : 0.);
        error =
          std::max(error, std::abs(c[3 + d][last] / c[2][last] - expected));
      }
    std::string velocity;
    for (unsigned int d = 0; d < dim; ++d)
      {
        char number[32];
        std::snprintf(number,
                      sizeof(number),
                      " %.6f",
                      c[3 + d][last] / c[2][last]);
        velocity += number;
      }
    deallog << dim << "D: t = " << t << ", steps " << last
            << ", centre-of-mass velocity" << velocity << std::endl;
    bfemp_tests::check(error < 1e-5,
                       std::to_string(dim) +
                         "D: centre-of-mass velocity = v_0 + g t to 1e-5 m/s");
    bfemp_tests::check(c[1][last] < 1e-8,
                       std::to_string(dim) +
                         "D: the block does not deform (elastic energy < "
                         "1e-8 J)");
    std::cout << dim << "D: velocity error " << error << ", elastic energy "
              << c[1][last] << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  test<2>();
  test<3>();
}
