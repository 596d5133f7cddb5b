// bfemp: read the dimension of the scene first, then run it as 2D or 3D.

#include <bfemp/base/input_error.h>
#include <bfemp/base/stop_signals.h>
#include <bfemp/reference/fe_reference_run.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace
{
  using namespace bfemp;

  /**
   * Reads and builds the scene; runs it unless @p only_validate. Returns
   * the exit code: 0, or 128 + the signal that stopped the run (what a
   * shell reports for a process the signal ended, so that batch scripts
   * see an unfinished run either way).
   */
  template <int dim>
  int
  run(const std::string &file, const bool only_validate)
  {
    SceneParameters<dim> parameters;
    parameters.read(file);
    Simulation<dim> simulation(parameters, file, std::cout);
    if (only_validate)
      {
        std::cout << "bfemp: " << file << " is valid: " << dim << "D, "
                  << parameters.bodies.size() << " bodies, "
                  << simulation.particles().n_particles() << " particles"
                  << std::endl;
        return 0;
      }
    const StopSignals stop_signals;
    return simulation.run() ? 0 : 128 + StopSignals::received();
  }



  /** The scene's static FE reference (seed 002 Section 8.2). */
  template <int dim>
  int
  fe_reference(const std::string &file, const double cell_size)
  {
    SceneParameters<dim> parameters;
    parameters.read(file);
    run_fe_reference<dim>(parameters, file, cell_size, std::cout);
    return 0;
  }



  /** Documented defaults as prm (2D and 3D) and JSON into @p folder. */
  void
  print_parameters(const std::string &folder)
  {
    std::filesystem::create_directories(folder);
    const auto write = [&](auto dim_constant, const std::string &name) {
      constexpr int    dim = decltype(dim_constant)::value;
      ParameterHandler prm;
      // one of each numbered subsection, so that the reference shows them
      SceneParameters<dim>::declare_parameters(
        prm,
        {typename BodyParameters<dim>::Counts{1, 1, 1}},
        1,
        {2});
      std::ofstream prm_file(folder + "/" + name + ".prm");
      prm.print_parameters(prm_file, ParameterHandler::PRM);
      std::ofstream json_file(folder + "/" + name + ".json");
      prm.print_parameters(json_file, ParameterHandler::JSON);
    };
    write(std::integral_constant<int, 2>(), "parameters_2d");
    write(std::integral_constant<int, 3>(), "parameters_3d");
    std::cout << "bfemp: wrote the documented defaults to " << folder << "/"
              << std::endl;
  }



  int
  usage()
  {
    std::cerr << "usage: bfemp FILE.prm\n"
                 "       bfemp --validate FILE.prm           (check, write "
                 "nothing)\n"
                 "       bfemp --print-parameters [FOLDER]   (default: .)\n"
                 "       bfemp --fe-reference FILE.prm [CELL_SIZE]\n"
                 "             (static FE_Q(2) solution of the scene's body, "
                 "doc/cmpm.md)\n";
    return 2;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  if (argc < 2)
    return usage();
  const std::string argument = argv[1];
  std::string       file;
  try
    {
      if (argument == "--print-parameters")
        {
          print_parameters(argc > 2 ? argv[2] : ".");
          return 0;
        }
      if (argument == "--fe-reference")
        {
          if (argc < 3 || argc > 4)
            return usage();
          file             = argv[2];
          double cell_size = 0.;
          if (argc == 4)
            {
              char *end = nullptr;
              cell_size = std::strtod(argv[3], &end);
              if (end == argv[3] || *end != '\0' || !(cell_size > 0.))
                throw InputError("--fe-reference: the cell size '" +
                                 std::string(argv[3]) +
                                 "' is not a number > 0");
            }
          return read_dimension(file) == 2 ? fe_reference<2>(file, cell_size)
                                           : fe_reference<3>(file, cell_size);
        }
      const bool validate = argument == "--validate";
      file                = validate && argc == 3 ? argv[2] : argument;
      if ((validate && argc != 3) || (!validate && argc > 2) ||
          file.rfind("--", 0) == 0)
        return usage();
      return read_dimension(file) == 2 ? run<2>(file, validate)
                                       : run<3>(file, validate);
    }
  catch (const bfemp::InputError &error)
    {
      // Every refusal names the file; errors raised deep in a run (a
      // muParser expression that turns NaN at some t) know only their
      // subsection and entry, so the file is added here.
      const std::string message = error.what();
      std::cerr << "bfemp: input error: "
                << (file.empty() || message.rfind(file, 0) == 0 ? ""
                                                                : file + ": ")
                << message << std::endl;
      return 1;
    }
  catch (const bfemp::SimulationError &error)
    {
      std::cerr << "bfemp: simulation stopped: " << error.what() << std::endl;
      return 3;
    }
  catch (const std::exception &error)
    {
      std::cerr << "bfemp: error: " << error.what() << std::endl;
      return 4;
    }
  return 0;
}
