// Seed 002 Fig. 26(a, b) on the 2D heterogeneous cube
// (prm/cmpm/heterogeneous_cube_2d{,_full_newton,_fine}.prm, Section 8.1.4):
// doc/experiments/cmpm_newton_history.py runs cMPM with the first Newton
// step and with full Newton in the local problem and BSMPM-fine with
// 'solver/log iterations', whose lines carry every energy term, and tables
// the strain energy (the 'MPM elasticity' term) over the global Newton
// iterations (about 5 s). The seed finds convergence "at a iteration step as
// small as 4" for both local solves, both close to the benchmark. Checked:
// - every pass of every step of the three runs converges in at most 6
//   iterations;
// - at t = 0.01 and 0.05 s the strain energy after the first iteration of a
//   pass lies within 5 % of the pass's converged value (the first iteration
//   does nearly all of it);
// - the converged strain energies of the two local solves agree within
//   0.2 %, and lie within 10 % of BSMPM-fine's.
// The strain energies at both times go to the output (5 digits).

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../format.h"
#include "../tests.h"

namespace
{
  struct Iteration
  {
    std::string  run, pass;
    unsigned int step, iteration;
    double       time, strain_energy;
  };

  std::vector<Iteration>
  read_history(const std::string &file)
  {
    std::ifstream          in(file);
    std::vector<Iteration> rows;
    std::string            line;
    std::getline(in, line);
    bfemp_tests::check(line == "run,step,time,pass,iteration,increment,"
                               "energy,strain_energy",
                       file + " has the script's columns");
    while (std::getline(in, line))
      {
        std::vector<std::string> e;
        std::stringstream        row(line);
        for (std::string entry; std::getline(row, entry, ',');)
          e.push_back(entry);
        rows.push_back({e.at(0),
                        e.at(3),
                        static_cast<unsigned int>(std::stoul(e.at(1))),
                        static_cast<unsigned int>(std::stoul(e.at(4))),
                        std::stod(e.at(2)),
                        std::stod(e.at(7))});
      }
    return rows;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  using bfemp_tests::check;
  using bfemp_tests::format;

  check(bfemp_tests::run_study("cmpm_newton_history.py", "history"),
        "cmpm_newton_history.py ran the three cubes");
  const std::vector<Iteration> rows =
    read_history("history/newton_history.csv");

  // iterations of each (run, step, pass), and the first and last strain
  // energy of each
  std::map<std::string, unsigned int>              iterations;
  std::map<std::string, std::pair<double, double>> first_last;
  std::map<std::string, std::map<double, double>>  converged;
  for (const Iteration &r : rows)
    {
      const std::string key =
        r.run + " step " + std::to_string(r.step) + " " + r.pass;
      iterations[key] = std::max(iterations[key], r.iteration);
      if (r.iteration == 1)
        first_last[key].first = r.strain_energy;
      first_last[key].second   = r.strain_energy;
      converged[r.run][r.time] = r.strain_energy; // the step's last pass
    }
  unsigned int most = 0;
  for (const auto &[key, n] : iterations)
    most = std::max(most, n);
  dealii::deallog << iterations.size() << " passes, at most " << most
                  << " Newton iterations in one" << std::endl;
  check(iterations.size() == 20,
        "5 steps: 5 passes each for the first "
        "Newton step and BSMPM-fine, 10 for full "
        "Newton");
  check(most <= 6, "every pass converges in at most 6 Newton iterations");

  for (const double t : {0.01, 0.05})
    {
      const unsigned int step = static_cast<unsigned int>(std::round(t / 0.01));
      double             worst = 0.;
      for (const std::string run : {"first", "full", "fine"})
        for (const std::string pass : {"first", "full"})
          {
            const auto it = first_last.find(run + " step " +
                                            std::to_string(step) + " " + pass);
            if (it != first_last.end())
              worst =
                std::max(worst,
                         std::abs(it->second.first / it->second.second - 1.));
          }
      const double first = converged["first"][t], full = converged["full"][t],
                   fine = converged["fine"][t];
      dealii::deallog << "t = " << format("%g", t)
                      << " s: strain energy first Newton step "
                      << format("%.5g", first) << " J, full Newton "
                      << format("%.5g", full) << " J, BSMPM-fine "
                      << format("%.5g", fine)
                      << " J; largest gap of a first iteration to its pass's "
                         "converged value "
                      << format("%.3f", worst) << std::endl;
      const std::string at = "t = " + format("%g", t) + " s: ";
      check(worst < 0.05,
            at + "the first iteration of every pass within 5 % of its "
                 "converged strain energy");
      check(std::abs(first / full - 1.) < 0.002,
            at + "first Newton step and full Newton within 0.2 %");
      check(std::abs(first / fine - 1.) < 0.1 &&
              std::abs(full / fine - 1.) < 0.1,
            at + "both within 10 % of BSMPM-fine");
    }
}
