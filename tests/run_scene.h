#ifndef bfemp_tests_run_scene_h
#define bfemp_tests_run_scene_h

// Runs a scene from its prm file as the bfemp executable does, with the
// console output kept out of the test's output.

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <sstream>
#include <string>

namespace bfemp_tests
{
  /** Reads @p prm_file and runs its scene to the end; returns the console
   *  output. */
  template <int dim>
  std::string
  run_scene(const std::string &prm_file)
  {
    bfemp::SceneParameters<dim> parameters;
    parameters.read(prm_file);
    std::ostringstream     console;
    bfemp::Simulation<dim> simulation(parameters, prm_file, console);
    simulation.run();
    return console.str();
  }
} // namespace bfemp_tests

#endif
