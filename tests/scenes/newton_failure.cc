// A Newton solve that does not converge within 'solver/maximum Newton
// iterations' must stop the run with a SimulationError that names the step,
// the residual and the energy, and leave the output of the converged steps
// complete: every diagnostics.csv row whole, every VTU file listed in the
// .pvd series present and closed, no temporary file.

#include <bfemp/base/input_error.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "diagnostics_csv.h"
#include "tests.h"

using namespace dealii;

namespace
{
  std::string
  read_file(const std::string &path)
  {
    std::ifstream     in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  std::filesystem::remove_all("results");
  {
    std::ofstream prm("newton_failure.prm");
    prm << "include " << BFEMP_SOURCE_DIR << "/prm/demo_implicit.prm\n"
        << "subsection run\n"
           "  set name     = newton_failure\n"
           "  set end time = 0.2\n"
           "  set quiet    = true\n"
           "end\n"
           "subsection output\n"
           "  set directory = results\n"
           "  set interval  = 0.01\n"
           "end\n"
           // With the exact Hessian, steps 1-9 converge to 1e-9 m/s in 3-4
           // iterations and step 10 needs 5.
           "subsection solver\n"
           "  set Newton tolerance          = 1e-9\n"
           "  set maximum Newton iterations = 4\n"
           "  set Hessian projection        = when indefinite\n"
           "end\n";
  }
  bfemp::SceneParameters<2> parameters;
  parameters.read("newton_failure.prm");
  std::ostringstream   console;
  bfemp::Simulation<2> simulation(parameters, "newton_failure.prm", console);

  std::string message;
  try
    {
      simulation.run();
    }
  catch (const bfemp::SimulationError &error)
    {
      message = error.what();
    }
  bfemp_tests::check(!message.empty(), "the run stopped with SimulationError");
  std::smatch match;
  bfemp_tests::check(std::regex_search(message,
                                       match,
                                       std::regex("^step ([0-9]+), t = ")),
                     "the message starts with the step");
  const unsigned int failed_step = std::stoi(match[1]);
  bfemp_tests::check(message.find("no convergence after 4 Newton iterations") !=
                       std::string::npos,
                     "the message names the iteration limit");
  for (const char *part : {"residual", "energy", "maximum Newton iterations"})
    bfemp_tests::check(message.find(part) != std::string::npos,
                       std::string("the message names the ") + part);
  bfemp_tests::check(failed_step >= 1,
                     "the failed step is named: step " +
                       std::to_string(failed_step));
  bfemp_tests::check(failed_step >= 2,
                     "steps before the failed one converged (their output is "
                     "what the remaining checks inspect): " +
                       std::to_string(failed_step - 1) + " steps");

  const std::string folder = "results/newton_failure";
  const auto steps = bfemp_tests::read_columns(folder + "/diagnostics.csv",
                                               {"step", "newton_iterations"});
  bfemp_tests::check(!steps[0].empty() && steps[0].back() < failed_step,
                     "diagnostics.csv ends before the failed step: last row "
                     "step " +
                       (steps[0].empty()
                          ? std::string("none")
                          : bfemp_tests::format("%.0f", steps[0].back())));
  unsigned int n_unsolved = 0;
  for (unsigned int r = 1; r < steps[1].size(); ++r)
    n_unsolved += !(steps[1][r] >= 1);
  bfemp_tests::check(n_unsolved == 0,
                     "every written row comes from solved steps: " +
                       std::to_string(n_unsolved) +
                       " rows after the first without Newton iterations, of " +
                       std::to_string(steps[1].size()));

  unsigned int n_listed   = 0;
  unsigned int n_complete = 0;
  for (const char *series : {"particles.pvd", "fem_body_0.pvd"})
    {
      const std::string pvd = read_file(folder + "/" + series);
      bfemp_tests::check(pvd.find("</VTKFile>") != std::string::npos,
                         std::string(series) + " is complete");
      const std::regex file_attribute("file=\"([^\"]+)\"");
      for (auto it =
             std::sregex_iterator(pvd.begin(), pvd.end(), file_attribute);
           it != std::sregex_iterator();
           ++it, ++n_listed)
        {
          const std::string vtu = read_file(folder + "/" + (*it)[1].str());
          n_complete += vtu.find("</VTKFile>") != std::string::npos;
        }
    }
  bfemp_tests::check(n_listed >= 2 && n_complete == n_listed,
                     "every VTU file the series list is complete: " +
                       std::to_string(n_complete) + " of " +
                       std::to_string(n_listed));
  unsigned int n_temporary = 0;
  for (const auto &entry : std::filesystem::directory_iterator(folder))
    n_temporary += entry.path().extension() == ".part";
  bfemp_tests::check(n_temporary == 0,
                     "no temporary file is left: " +
                       std::to_string(n_temporary) + " .part files");
  deallog << "OK" << std::endl;
}
