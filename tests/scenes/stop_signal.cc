// Stopping a run by a signal (StopSignals, Simulation::run()): while a
// StopSignals object lives, SIGTERM, SIGINT and SIGUSR1 no longer end the
// process; run() finishes the step in progress, writes a checkpoint
// although the prm asks for none, says how to continue and returns false.
// Continued with 'resume = auto', the run repeats the uninterrupted one bit
// for bit (diagnostics.csv, bodies.csv, VTU and PVD files). With
// 'diagnostics interval' > 1 the stop adds a row at its step: the continued
// file is the uninterrupted one plus that row, and the rows' Newton
// iterations still sum to the uninterrupted run's. A signal raised before
// run() stops the run after its first step, which keeps the test
// deterministic. The destructor restores the handler found before.

#include <bfemp/base/stop_signals.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "diagnostics_csv.h"
#include "run_comparison.h"
#include "tests.h"

using namespace dealii;
using namespace run_comparison;

namespace
{
  /** What the last run printed. */
  std::string last_console;

  /**
   * Writes @p name.prm (demo_contact.prm plus @p entries) and runs it;
   * raises @p signal first unless it is 0. Returns what run() returned.
   */
  bool
  run(const std::string &name, const std::string &entries, const int signal)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << "include " << BFEMP_SOURCE_DIR << "/prm/demo_contact.prm\n"
          << "subsection run\n"
             "  set name     = "
          << name
          << "\n"
             "  set quiet    = true\n"
             "  set threads  = 1\n"
             "  set end time = 0.125\n"
             "end\n"
             "subsection output\n"
             "  set directory = results\n"
             "  set interval  = 0.03125\n"
             "end\n"
             "subsection time\n"
             "  set time step = 0.00390625\n"
             "end\n"
          << entries;
    }
    bfemp::SceneParameters<2> parameters;
    parameters.read(name + ".prm");
    std::ostringstream       console;
    bfemp::Simulation<2>     simulation(parameters, name + ".prm", console);
    const bfemp::StopSignals stop_signals;
    if (signal != 0)
      std::raise(signal);
    const bool finished = simulation.run();
    last_console        = console.str();
    return finished;
  }

  /** The console line that starts with @p start. */
  std::string
  console_line(const std::string &start)
  {
    const std::size_t begin = last_console.find(start);
    if (begin == std::string::npos)
      return "";
    return last_console.substr(begin, last_console.find('\n', begin) - begin);
  }

  /**
   * Stops the scene after its first step by @p signal, continues it, and
   * returns the folder of the continued run.
   */
  std::string
  stop_and_continue(const std::string &name,
                    const std::string &entries,
                    const int          signal)
  {
    const std::string folder = "results/" + name;
    bfemp_tests::check(!run(name, entries, signal),
                       "run() returns false after " +
                         bfemp::StopSignals::name(signal));
    const std::string stop = console_line("bfemp: stopped");
    deallog << stop << std::endl;
    bfemp_tests::check(stop.find("stopped by " +
                                 bfemp::StopSignals::name(signal) +
                                 " after step 1") != std::string::npos &&
                         stop.find("resume = auto") != std::string::npos,
                       "the console names the signal, the step and how to "
                       "continue");
    bfemp_tests::check(std::filesystem::exists(folder + "/checkpoint.h5"),
                       "the stopped run left a checkpoint although the prm "
                       "asks for none");
    const auto steps =
      bfemp_tests::read_columns(folder + "/diagnostics.csv", {"step"})[0];
    deallog << "rows of the stopped run: " << steps.size() << std::endl;
    bfemp_tests::check(steps.size() == 2 && steps.back() == 1.,
                       "the stopped run wrote the rows of steps 0 and 1");

    bfemp::StopSignals::clear();
    bfemp_tests::check(run(name,
                           entries + "subsection checkpoint\n"
                                     "  set resume = auto\n"
                                     "end\n",
                           0),
                       "the continued run finishes");
    return folder;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  deallog << "--- SIGTERM, a row every step" << std::endl;
  bfemp_tests::check(run("uninterrupted", "", 0),
                     "the uninterrupted run finishes");
  compare_outputs("results/uninterrupted",
                  stop_and_continue("stopped", "", SIGTERM));

  deallog << "--- SIGINT, a row every 4 steps" << std::endl;
  const std::string every_4 = "subsection output\n"
                              "  set diagnostics interval = 4\n"
                              "end\n";
  bfemp_tests::check(run("uninterrupted_4", every_4, 0),
                     "the uninterrupted run finishes");
  const std::string continued = stop_and_continue("stopped_4", every_4, SIGINT);
  compare_vtu_files("results/uninterrupted_4", continued);
  {
    auto       rows = csv_without_timings(continued + "/diagnostics.csv");
    const auto uninterrupted =
      csv_without_timings("results/uninterrupted_4/diagnostics.csv");
    deallog << "rows: " << rows.size() - 1 << " against "
            << uninterrupted.size() - 1 << std::endl;
    bfemp_tests::check(rows.size() == uninterrupted.size() + 1 &&
                         rows[2][0] == "1",
                       "the continued file has one more row, at step 1");
    // Only the row after the stop differs: its Newton counts exclude step 1.
    const std::vector<std::string> counters = {"newton_iterations",
                                               "line_search_backtracks",
                                               "step_bound_hits",
                                               "projected_hessians",
                                               "factorizations"};
    const auto                    &header   = rows[0];
    for (const std::string &counter : counters)
      {
        const auto c =
          std::find(header.begin(), header.end(), counter) - header.begin();
        bfemp_tests::check(c < static_cast<long>(header.size()),
                           counter + " is a column");
        double sum_continued = 0., sum_uninterrupted = 0.;
        for (unsigned int r = 1; r < rows.size(); ++r)
          sum_continued += std::stod(rows[r][c]);
        for (unsigned int r = 1; r < uninterrupted.size(); ++r)
          sum_uninterrupted += std::stod(uninterrupted[r][c]);
        if (counter == "newton_iterations")
          deallog << "Newton iterations: " << sum_continued << " against "
                  << sum_uninterrupted << std::endl;
        bfemp_tests::check(sum_continued == sum_uninterrupted,
                           counter + " sums to the uninterrupted run's");
        rows[3][c] = uninterrupted[2][c];
      }
    rows.erase(rows.begin() + 2);
    bfemp_tests::check(rows == uninterrupted,
                       "without that row and the counters of the next, the "
                       "file is the uninterrupted one bit for bit");
  }

  deallog << "--- the handler found before comes back" << std::endl;
  std::signal(SIGUSR1, SIG_IGN);
  {
    const bfemp::StopSignals stop_signals;
  }
  std::raise(SIGUSR1);
  deallog << "SIGUSR1 after the object: ignored, received() = "
          << bfemp::StopSignals::received() << std::endl;
  bfemp_tests::check(bfemp::StopSignals::received() == 0,
                     "outside the object's life a signal is not recorded");
  return 0;
}
