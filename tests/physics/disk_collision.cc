// Two elastic disks collide through the background grid (after Sulsky,
// Chen and Schreyer 1994, Section 5.1): no gravity, no walls, a grid large
// enough that nothing reaches its edge. The disks differ in size so the
// total momentum is not zero. Checks, from diagnostics.csv (one row per
// step) and the particles:
//  - the total linear momentum equals the initial one at every step to
//    round-off (1e-12 relative to the initial |p|);
//  - the total energy never exceeds its initial value (by more than 1e-3
//    relative) and most of it survives the impact (no blow-up, no total
//    loss);
//  - the disks really collided: each body's x and y momentum changed sign.

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "diagnostics_csv.h"
#include "tests.h"

using namespace dealii;

namespace
{
  using bfemp_tests::read_columns;

  /** Momentum of each body, summed from the particles. */
  std::vector<Tensor<1, 2>>
  body_momenta(const bfemp::Simulation<2> &simulation)
  {
    using Layout = bfemp::ParticleLayout<2>;
    std::vector<Tensor<1, 2>> p(2);
    for (const auto &particle : simulation.particles().handler())
      {
        const auto props = particle.get_properties();
        p[static_cast<unsigned int>(props[Layout::body_id])] +=
          props[Layout::mass] * Layout::get_vector(props, Layout::velocity);
      }
    return p;
  }



  std::string
  format(const Tensor<1, 2> &p)
  {
    std::ostringstream out;
    out << std::setprecision(4) << '(' << p[0] << ", " << p[1] << ')';
    return out.str();
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  // Sulsky et al.: disks of radius 0.2 at (0.2, 0.2) and (0.8, 0.8) moving
  // at +-(0.1, 0.1), E = 1000, nu = 0.3, rho = 1000, dx = 0.05. Here the
  // second disk is smaller (radius 0.15) and the grid reaches 0.35 past the
  // unit square on every side.
  const std::string file = "disk_collision.prm";
  {
    std::ofstream prm(file);
    prm << "set dimension = 2\n"
           "set number of bodies = 2\n"
           "subsection run\n"
           "  set name = disks\n"
           "  set end time = 3.5\n"
           "  set quiet = true\n"
           "end\n"
           "subsection grid\n"
           "  set lower corner = -0.35, -0.35\n"
           "  set upper corner = 1.35, 1.35\n"
           "  set cell size = 0.025\n"
           "  set kernel = quadratic\n"
           "end\n"
           "subsection time\n"
           "  set integrator = explicit USL\n"
           "  set time step mode = CFL\n"
           "  set CFL number = 0.4\n"
           "end\n"
           "subsection transfer\n"
           "  set scheme = APIC\n"
           "end\n"
           "subsection gravity\n"
           "  set acceleration = 0, 0\n"
           "end\n"
           "subsection boundaries\n"
           "  set walls = none\n"
           "end\n"
           "subsection output\n"
           "  set directory = results\n"
           "  set interval = 0.5\n"
           "  set diagnostics interval = 1\n"
           "  set write particles = false\n"
           "end\n";
    const char *center[2]   = {"0.2, 0.2", "0.8, 0.8"};
    const char *radius[2]   = {"0.2", "0.15"};
    const char *velocity[2] = {"0.1, 0.1", "-0.1, -0.1"};
    for (unsigned int b = 0; b < 2; ++b)
      prm << "subsection body " << b
          << "\n"
             "  set particles per cell = 2\n"
             "  set initial velocity = "
          << velocity[b]
          << "\n"
             "  subsection primitive 0\n"
             "    set type = ball\n"
             "    set center = "
          << center[b] << "\n    set outer radius = " << radius[b]
          << "\n"
             "  end\n"
             "  subsection material\n"
             "    set model = linear elastic\n"
             "    set Young's modulus = 1000\n"
             "    set Poisson's ratio = 0.3\n"
             "    set density = 1000\n"
             "  end\n"
             "end\n";
  }

  bfemp::SceneParameters<2> parameters;
  parameters.read(file);
  std::ostringstream              console;
  bfemp::Simulation<2>            simulation(parameters, file, console);
  const std::vector<Tensor<1, 2>> p_initial = body_momenta(simulation);
  deallog << "particles " << simulation.particles().n_particles() << std::endl;
  deallog << "initial body momenta " << format(p_initial[0]) << ' '
          << format(p_initial[1]) << std::endl;
  simulation.run();
  const std::vector<Tensor<1, 2>> p_final = body_momenta(simulation);
  deallog << "final body momenta " << format(p_final[0]) << ' '
          << format(p_final[1]) << std::endl;

  const auto columns = read_columns(
    "results/disks/diagnostics.csv",
    {"time", "momentum_x", "momentum_y", "kinetic_energy", "elastic_energy"});
  const std::size_t n_rows = columns[0].size();
  deallog << "diagnostics rows " << n_rows << std::endl;
  bfemp_tests::check(n_rows > 100 && std::abs(columns[0].back() - 3.5) < 1e-12,
                     "one diagnostics row per step up to the end time");

  // Momentum: every row against the first. The csv has 12 significant
  // digits, which resolves 1e-12 of |p| as the components are ~|p|.
  const Tensor<1, 2> p0({columns[1][0], columns[2][0]});
  double             drift = 0.;
  for (std::size_t i = 0; i < n_rows; ++i)
    drift =
      std::max(drift,
               (Tensor<1, 2>({columns[1][i], columns[2][i]}) - p0).norm());
  deallog << "initial |p| " << p0.norm() << std::endl;
  bfemp_tests::check(std::abs(p0.norm() -
                              (p_initial[0] + p_initial[1]).norm()) <
                       1e-12 * p0.norm(),
                     "diagnostics momentum = sum over the bodies at t = 0");
  bfemp_tests::check(drift <= 1e-12 * p0.norm(),
                     "total momentum conserved to 1e-12 |p0| at every step");
  bfemp_tests::check((p_final[0] + p_final[1] - p0).norm() <= 1e-12 * p0.norm(),
                     "final particle momentum = initial momentum");

  // Energy: bounded above by its initial value, and mostly kept.
  const double E0    = columns[3][0] + columns[4][0];
  double       E_max = 0., E_min = E0;
  for (std::size_t i = 0; i < n_rows; ++i)
    {
      E_max = std::max(E_max, columns[3][i] + columns[4][i]);
      E_min = std::min(E_min, columns[3][i] + columns[4][i]);
    }
  const double       E_end = columns[3].back() + columns[4].back();
  std::ostringstream energy;
  energy << std::setprecision(3) << "energy: max / E0 " << E_max / E0
         << ", min / E0 " << E_min / E0 << ", end / E0 " << E_end / E0;
  deallog << energy.str() << std::endl;
  bfemp_tests::check(E_max <= (1. + 1e-3) * E0,
                     "the total energy never grows above E0 (1e-3)");
  bfemp_tests::check(E_min >= 0.5 * E0,
                     "at least half of the energy survives the impact");

  // The collision: each disk's momentum reverses in x and in y.
  for (unsigned int b = 0; b < 2; ++b)
    for (unsigned int c = 0; c < 2; ++c)
      bfemp_tests::check(p_initial[b][c] * p_final[b][c] < 0.,
                         "disk " + std::to_string(b) + ": momentum " +
                           (c == 0 ? "x" : "y") + " changed sign");
}
