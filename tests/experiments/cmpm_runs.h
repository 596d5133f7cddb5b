#ifndef bfemp_tests_experiments_cmpm_runs_h
#define bfemp_tests_experiments_cmpm_runs_h

// Runs of the cMPM experiments of seed 002 Section 8 (prm/cmpm/) for the
// tests in tests/experiments and tests/validation: a scene's prm file run
// as results/<name> with its cost from the clock and diagnostics.csv, and
// the errors r_u, r_sigma (eq. 38) of one run against another through
// doc/experiments/particle_error.py.

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <numeric>
#include <string>
#include <sys/resource.h>
#include <utility>
#include <vector>

#include "../diagnostics_csv.h"
#include "../format.h"
#include "../run_scene.h"
#include "../tests.h"

namespace cmpm_runs
{
  using bfemp_tests::format;

  /** Cost of one run, from the clock and its diagnostics.csv. */
  struct Cost
  {
    unsigned int steps         = 0;
    double       cpu_seconds   = 0.;
    double       wall_per_step = 0.;
    // per step: inside Newton (assembly = the integrals; factorization and
    // solve = the linear system; line search), and the rest (for cMPM: the
    // shape functions of the step, P2G and G2P)
    double assembly = 0., linear_system = 0., line_search = 0., rest = 0.;
    double newton_iterations = 0.;
    double dofs              = 0.;
  };

  inline double
  cpu_seconds()
  {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
           1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }

  /** Writes <name>.prm: @p prm run as @p name, quiet, with its output in
   *  results/, and the prm text @p entries appended. Returns its name. */
  inline std::string
  write_prm(const std::string &prm,
            const std::string &name,
            const std::string &entries = "")
  {
    const std::string file = name + ".prm";
    std::ofstream     out(file);
    out << "include " << prm << "\nsubsection run\n  set name = " << name
        << "\n  set quiet = true\nend\n"
        << "subsection output\n  set directory = results\nend\n"
        << entries;
    return file;
  }

  /** Runs @p prm, with the prm text @p entries appended, as
   *  results/<name>; returns its cost. */
  template <int dim>
  Cost
  run(const std::string &prm,
      const std::string &name,
      const std::string &entries = "")
  {
    const std::string file      = write_prm(prm, name, entries);
    const double      cpu_start = cpu_seconds();
    bfemp_tests::run_scene<dim>(file);
    Cost cost;
    cost.cpu_seconds = cpu_seconds() - cpu_start;

    const auto c =
      bfemp_tests::read_columns("results/" + name + "/diagnostics.csv",
                                {"step",
                                 "wall_time",
                                 "assembly_time",
                                 "factorization_time",
                                 "solve_time",
                                 "line_search_time",
                                 "newton_iterations",
                                 "dofs"});
    // row 0 is the state at t = 0, before any step
    cost.steps      = c[0].size() - 1;
    const auto mean = [&](const std::vector<double> &v) {
      return std::accumulate(v.begin() + 1, v.end(), 0.) / cost.steps;
    };
    bfemp_tests::check(c[0][0] == 0., name + ": diagnostics start at step 0");
    cost.wall_per_step = c[1].back() / cost.steps;
    cost.assembly      = mean(c[2]);
    cost.linear_system = mean(c[3]) + mean(c[4]);
    cost.line_search   = mean(c[5]);
    cost.rest = cost.wall_per_step - cost.assembly - cost.linear_system -
                cost.line_search;
    cost.newton_iterations = mean(c[6]);
    cost.dofs              = mean(c[7]);
    return cost;
  }

  /** max r_u, max r_sigma of results/<run> against results/<reference>. */
  inline std::pair<double, double>
  max_errors(const std::string &reference,
             const std::string &run,
             const bool         log_series = false)
  {
    const std::string command =
      std::string("/usr/bin/python3 ") + BFEMP_SOURCE_DIR +
      "/doc/experiments/particle_error.py results/" + reference + " results/" +
      run + " --quiet > " + run + "_error.log 2>&1";
    const int status = std::system(command.c_str());
    bfemp_tests::check(status == 0,
                       "particle_error.py compares " + run + " with " +
                         reference);
    const auto c =
      bfemp_tests::read_columns("results/" + run + "/particle_error.csv",
                                {"time", "r_u", "r_sigma"});
    // the series, so that numdiff sees drift at every output time
    if (log_series)
      for (std::size_t i = 0; i < c[0].size(); ++i)
        dealii::deallog << run << " t = " << format("%.3f", c[0][i]) << ": r_u "
                        << format("%.4f", c[1][i]) << ", r_sigma "
                        << format("%.4f", c[2][i]) << std::endl;
    return {*std::max_element(c[1].begin(), c[1].end()),
            *std::max_element(c[2].begin(), c[2].end())};
  }

  inline void
  print_cost(const std::string &label, const Cost &cost)
  {
    std::cout << label << ": " << cost.steps << " steps, CPU "
              << cost.cpu_seconds << " s, wall per step " << cost.wall_per_step
              << " s (assembly " << cost.assembly << ", linear system "
              << cost.linear_system << ", line search " << cost.line_search
              << ", rest " << cost.rest << "), Newton iterations per step "
              << cost.newton_iterations << ", unknowns " << cost.dofs
              << std::endl;
  }

} // namespace cmpm_runs

#endif
