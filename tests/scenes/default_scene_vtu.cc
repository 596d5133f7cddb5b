// The output files of a run are readable by VTK itself: the default scene
// (prm/default.prm, shortened to a few snapshots, grid output on) runs
// through Simulation<2>, then read_vtu.py opens particles.pvd and grid.pvd
// with VTK's XML readers (Debian's /usr/bin/python3 with python3-vtk9) and
// checks point counts, the arrays of every snapshot (names, component
// counts, finite values), the total mass and the final momentum against the
// simulation's own particles.

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  const std::string source_dir = BFEMP_SOURCE_DIR;
  std::filesystem::remove_all("results");
  {
    std::ofstream prm("default_scene_vtu.prm");
    prm << "include " << source_dir << "/prm/default.prm\n"
        << "subsection run\n"
           "  set end time = 0.05\n"
           "  set quiet    = true\n"
           "end\n"
           "subsection output\n"
           "  set directory  = results\n"
           "  set interval   = 0.02\n"
           "  set write grid = true\n"
           "end\n";
  }

  bfemp::SceneParameters<2> parameters;
  parameters.read("default_scene_vtu.prm");
  std::ostringstream   console;
  bfemp::Simulation<2> simulation(parameters, "default_scene_vtu.prm", console);
  simulation.run();

  using Layout           = bfemp::ParticleLayout<2>;
  const auto  &particles = simulation.particles();
  double       mass      = 0.;
  Tensor<1, 2> momentum;
  for (const auto &particle : particles.handler())
    {
      const auto p = particle.get_properties();
      mass += p[Layout::mass];
      momentum += p[Layout::mass] * Layout::get_vector(p, Layout::velocity);
    }
  deallog << "particles " << particles.n_particles() << std::endl;
  deallog << "total mass " << mass << std::endl;
  bfemp_tests::check(particles.n_particles() > 1000,
                     "the default scene has its particles");

  std::ostringstream command;
  command << std::setprecision(17) << "/usr/bin/python3 " << source_dir
          << "/tests/scenes/read_vtu.py results/default "
          << particles.n_particles() << ' ' << mass << ' ' << momentum[0] << ' '
          << momentum[1] << " > read_vtu.log 2>&1";
  const int status = std::system(command.str().c_str());

  std::ifstream log("read_vtu.log");
  for (std::string line; std::getline(log, line);)
    deallog << "read_vtu: " << line << std::endl;
  bfemp_tests::check(status == 0, "read_vtu.py accepts the run's VTU files");
}
