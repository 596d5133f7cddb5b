// A fixed time step above the explicit stability limit stops the bfemp
// executable cleanly: non-zero exit code, the message "exceeds the explicit
// stability limit" on stderr, and only complete, finite output behind it
// (every VTU and the PVD end with </VTKFile>, no temporary *.part file, no
// nan or inf in diagnostics.csv).
//
// Case "at_start": dt is twice the limit from the first step on.
// Case "mid_run": dt starts at CFL 0.4 under 'maximum CFL number = 0.5',
// gravity accelerates the disk until c_p + max |v_p| makes the same dt
// exceed the limit a few steps (and snapshots) later.
//
// BFEMP_EXECUTABLE (the path of the bfemp program) comes from
// tests/physics/CMakeLists.txt.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "tests.h"

#ifndef BFEMP_EXECUTABLE
#  error "BFEMP_EXECUTABLE must name the bfemp program"
#endif

using namespace dealii;

namespace
{
  std::string
  read_file(const std::string &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }



  bool
  ends_with_vtkfile(const std::string &path)
  {
    std::string text = read_file(path);
    while (!text.empty() &&
           std::isspace(static_cast<unsigned char>(text.back())))
      text.pop_back();
    const std::string end = "</VTKFile>";
    return text.size() >= end.size() &&
           text.compare(text.size() - end.size(), end.size(), end) == 0;
  }



  std::string
  lower_case(std::string text)
  {
    for (char &c : text)
      c = std::tolower(static_cast<unsigned char>(c));
    return text;
  }



  /**
   * Runs bfemp on a disk of E = 1000, nu = 0.3, rho = 1000 (c_p = 1.16 m/s)
   * with dx = 0.05, fixed dt and the given gravity and maximum CFL number,
   * and checks the stop and what it left behind.
   */
  void
  run_case(const std::string &name,
           const double       time_step,
           const double       gravity,
           const double       maximum_cfl,
           const unsigned int minimum_snapshots)
  {
    deallog << "case " << name << std::endl;
    const std::string prm_file = name + ".prm";
    {
      std::ofstream prm(prm_file);
      prm << "set dimension = 2\n"
             "subsection run\n"
             "  set name = "
          << name
          << "\n"
             "  set end time = 1\n"
             "  set quiet = true\n"
             "end\n"
             "subsection grid\n"
             "  set lower corner = 0, 0\n"
             "  set upper corner = 1, 1\n"
             "  set cell size = 0.05\n"
             "end\n"
             "subsection time\n"
             "  set time step mode = fixed\n"
             "  set time step = "
          << time_step << "\n  set maximum CFL number = " << maximum_cfl
          << "\nend\n"
             "subsection gravity\n"
             "  set acceleration = 0, "
          << -gravity
          << "\n"
             "end\n"
             "subsection boundaries\n"
             "  set walls = none\n"
             "end\n"
             "subsection output\n"
             "  set directory = results\n"
             "  set interval = 0\n"
             "  set write grid = true\n"
             "end\n"
             "subsection body 0\n"
             "  subsection primitive 0\n"
             "    set type = ball\n"
             "    set center = 0.5, 0.5\n"
             "    set outer radius = 0.2\n"
             "  end\n"
             "  subsection material\n"
             "    set model = neo-Hookean\n"
             "    set Young's modulus = 1000\n"
             "    set Poisson's ratio = 0.3\n"
             "    set density = 1000\n"
             "  end\n"
             "end\n";
    }

    const std::string command = std::string(BFEMP_EXECUTABLE) + " " + prm_file +
                                " > " + name + ".stdout 2> " + name + ".stderr";
    const int status = std::system(command.c_str());
    const int exit_code =
      (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    deallog << "exit code " << exit_code << std::endl;
    bfemp_tests::check(exit_code > 0, "bfemp exits with a non-zero code");

    std::string message = read_file(name + ".stderr");
    while (!message.empty() && message.back() == '\n')
      message.pop_back();
    deallog << "stderr: " << message << std::endl;
    bfemp_tests::check(message.find("exceeds the explicit stability limit") !=
                         std::string::npos,
                       "stderr says the step exceeds the stability limit");

    const std::string folder      = "results/" + name;
    const std::string diagnostics = read_file(folder + "/diagnostics.csv");
    const std::string lower       = lower_case(diagnostics);
    unsigned int      rows        = 0;
    for (const char c : diagnostics)
      rows += (c == '\n');
    deallog << "diagnostics rows " << rows - 1 << std::endl;
    bfemp_tests::check(rows >= 2, "diagnostics.csv has the t = 0 row");
    bfemp_tests::check(lower.find("nan") == std::string::npos &&
                         lower.find("inf") == std::string::npos,
                       "diagnostics.csv holds no nan or inf");

    for (const std::string series : {"particles", "grid"})
      {
        unsigned int n_vtu = 0, n_complete = 0, n_listed = 0;
        bool         no_part_file = true;
        for (const auto &entry : std::filesystem::directory_iterator(folder))
          {
            const std::string file = entry.path().filename().string();
            if (file.size() > 5 && file.substr(file.size() - 5) == ".part")
              no_part_file = false;
            if (file.rfind(series + "_", 0) == 0 &&
                entry.path().extension() == ".vtu")
              {
                ++n_vtu;
                n_complete += ends_with_vtkfile(entry.path().string());
              }
          }
        const std::string pvd = read_file(folder + "/" + series + ".pvd");
        for (std::size_t at = pvd.find("<DataSet"); at != std::string::npos;
             at             = pvd.find("<DataSet", at + 1))
          ++n_listed;
        deallog << series << ": " << n_vtu << " VTU files, " << n_complete
                << " complete, " << n_listed << " listed in the PVD"
                << std::endl;
        // The grid series has no snapshot at t = 0 (no grid state yet).
        const unsigned int expected =
          series == "grid" ? minimum_snapshots - 1 : minimum_snapshots;
        bfemp_tests::check(n_vtu >= expected,
                           series + ": the snapshots before the stop exist");
        bfemp_tests::check(n_complete == n_vtu && n_listed == n_vtu,
                           series + ": every VTU is complete and in the PVD");
        if (n_vtu > 0)
          bfemp_tests::check(ends_with_vtkfile(folder + "/" + series + ".pvd"),
                             series + ".pvd is complete");
        bfemp_tests::check(no_part_file,
                           series + ": no temporary *.part file is left");
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  // c_p = sqrt((lambda + 2 mu) / rho) for E = 1000, nu = 0.3, rho = 1000.
  const double c_p   = std::sqrt(1000. * 0.7 / (1.3 * 0.4) / 1000.);
  const double limit = 0.05 / c_p; // dx / c_p: CFL 1 at rest
  deallog << "dt at CFL 1 for the disk at rest: " << limit << std::endl;

  run_case("at_start", 2. * limit, 0., 1., 1);
  // CFL 0.4 at rest; the 0.5 limit is crossed once max |v_p| > c_p / 4 =
  // 0.29 m/s, after 0.058 s of free fall at 5 m/s^2: step 5 (of 0.0172 s)
  // stops, after the snapshots of t = 0 and steps 1 to 4.
  run_case("mid_run", 0.4 * limit, 5., 0.5, 5);
}
