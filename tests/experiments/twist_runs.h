#ifndef bfemp_tests_experiments_twist_runs_h
#define bfemp_tests_experiments_twist_runs_h

// Runs of the reduced 3D twist (prm/experiments/6_7_twist/) through the
// first 0.4 s of its compression, while the contact grows, for the tests
// that compare a variant of the Newton loop with the loop without it: the
// run with a few prm entries changed, its Newton iterations and
// factorizations, and the distance of two runs' end states against the
// N eps_d dt that N steps of Newton tolerance allow (each step's answer is
// within about one last Newton increment, at most eps_d dt, of the exact
// minimizer).

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>

#include "../format.h"
#include "../implicit/implicit_scene.h"

namespace twist_runs
{
  using namespace implicit_scene;

  constexpr double end_time = 0.4;
  constexpr double dt       = 1e-2;
  constexpr double eps_d    = 1e-3;

  /** @p scene in prm/experiments/6_7_twist/, without ".prm". */
  inline std::string
  scene_prm(const std::string &scene)
  {
    return BFEMP_SOURCE_DIR "/prm/experiments/6_7_twist/" + scene + ".prm";
  }

  struct Run
  {
    Outcome<3> outcome;
    double     newton_iterations  = 0.;
    double     factorizations     = 0.;
    double     projected_hessians = 0.;
    /** Steps taken. */
    double steps = 0.;
  };

  /**
   * Runs @p scene as results/<name> with @p changes (prm subsections) on
   * top, one thread, to @p end (end_time unless given); checks that it gets
   * there with no particle inside the shell. The run's counts go into the
   * compared output unless @p counts_in_output is false: then they go to
   * stdout (the ctest log) only, for a run whose path follows a decision
   * that round-off can flip (CHOLMOD's definiteness test on an exact
   * Hessian that is singular to working precision gives 166 factorizations
   * on one machine and 167 on another with the same build).
   */
  inline Run
  run_variant(const std::string &scene,
              const std::string &name,
              const std::string &changes,
              const double       end              = end_time,
              const bool         counts_in_output = true)
  {
    write(name + ".prm",
          "include " + scene_prm(scene) +
            "\n"
            "subsection run\n  set name = " +
            name + "\n  set end time = " + rounded(end, 6) +
            "\n  set quiet = true\n  set threads = 1\nend\n"
            "subsection output\n  set directory = results\n"
            "  set interval = 1\n  set write particles = false\n"
            "  set write grid = false\nend\n" +
            changes);
    Run result{run<3>(name + ".prm")};
    bfemp_tests::check(result.outcome.error.empty(),
                       name + ": the run reached the end time" +
                         (result.outcome.error.empty()
                            ? ""
                            : ": " + result.outcome.error));
    const auto c = columns(name,
                           {"newton_iterations",
                            "particles_in_fem",
                            "min_distance",
                            "factorizations",
                            "projected_hessians"});
    bfemp_tests::check(finite({c[0], c[1]}) && max_of(c[1]) == 0. &&
                         min_of(c[2]) > 0.,
                       name +
                         ": no particle inside the shell, smallest "
                         "distance " +
                         bfemp_tests::format("%.2e", min_of(c[2])) + " m > 0");
    for (unsigned int i = 0; i < c[0].size(); ++i)
      {
        result.newton_iterations += c[0][i];
        result.factorizations += c[3][i];
        result.projected_hessians += c[4][i];
      }
    result.steps = c[0].size() - 1;
    std::ostringstream counts;
    counts << name << ": "
           << static_cast<unsigned int>(result.newton_iterations)
           << " Newton iterations, "
           << static_cast<unsigned int>(result.factorizations)
           << " factorizations in " << static_cast<unsigned int>(result.steps)
           << " steps";
    if (counts_in_output)
      deallog << counts.str() << std::endl;
    else
      {
        std::cout << counts.str() << ", "
                  << static_cast<unsigned int>(result.projected_hessians)
                  << " of them with the projected Hessian" << std::endl;
        deallog << name
                << ": counts in the test log only (round-off decides one "
                   "definiteness test on the way)"
                << std::endl;
      }
    return result;
  }

  /** The largest particle and shell node distances between two runs' ends,
   *  each checked against N eps_d dt. */
  inline void
  compare_end_states(const Run &a, const Run &b, const std::string &what)
  {
    const double particles = particle_distance(a.outcome, b.outcome);
    const double nodes     = fem_node_distance(a.outcome, b.outcome);
    const double bound     = std::max(a.steps, b.steps) * eps_d * dt;
    bfemp_tests::check_below(particles,
                             bound,
                             "end states: largest particle distance between " +
                               what + " in m");
    bfemp_tests::check_below(nodes,
                             bound,
                             "end states: largest shell node distance "
                             "between " +
                               what + " in m");
  }
} // namespace twist_runs

#endif
