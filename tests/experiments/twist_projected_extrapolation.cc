// 'solver/projected step extrapolation' and 'solver/skip failed exact
// factorizations' (issue 25) on the frictionless
// reduced 3D twist (prm/experiments/6_7_twist/twist_reduced_mu0.prm, 512
// particles, a 361-vertex shell, mu = 0), through the compression and the
// start of the twist (1.2 s), with the full prm files' Newton settings
// (material-point increment, factorization reuse, Eisenstat-Walker).
// Without friction the cube's top slides along the shell's edges and
// vertices, where the barrier's curvature is negative: the exact Hessian is
// indefinite and Newton falls back to the projected one. The projected
// Hessian is stiffer than the exact one (negative eigenvalues raised to 0),
// so its full step falls short; the lever doubles it while E falls.
//
// Checked, against the same run without the lever:
//  - both reach the end time with no particle inside the shell;
//  - the end states agree to N eps_d dt (N steps);
//  - the lever takes no more Newton iterations, and fewer projected
//    iterations and factorizations (measured at the time of writing: 529
//    against 554 iterations, 26 against 51 projected, 114 against 166
//    factorizations);
//  The paper's-line-search run's counts are printed to the test log, not
//  compared: on one machine CHOLMOD finds one exact Hessian of that run
//  indefinite that another machine's BLAS kernels factorize (166 against
//  167 factorizations, 51 against 52 projected iterations, the same Newton
//  iterations and end state); the check below holds on both.
//  - 'skip failed exact factorizations' on top: the same end state, no more
//    Newton iterations and fewer factorizations (529 iterations, 99 against
//    114 factorizations: the exact attempts it skips would have failed).

#include "twist_runs.h"

using namespace twist_runs;

int
main()
{
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  const std::string scene    = "twist_reduced_mu0";
  const double      end      = 1.2;
  const std::string settings = "subsection solver\n"
                               "  set Newton increment = material points\n"
                               "  set factorization reuse = 10\n"
                               "  set forcing term = Eisenstat-Walker\n";
  const Run         paper =
    run_variant(scene, "paper_line_search", settings + "end\n", end, false);
  const Run extrapolated =
    run_variant(scene,
                "extrapolated",
                settings + "  set projected step extrapolation = 3\nend\n",
                end);
  const Run skipping =
    run_variant(scene,
                "skipping",
                settings +
                  "  set projected step extrapolation = 3\n"
                  "  set skip failed exact factorizations = true\nend\n",
                end);

  for (const auto &[name, run] : {std::make_pair("extrapolated", &extrapolated),
                                  std::make_pair("skipping", &skipping)})
    deallog << name << ": "
            << static_cast<unsigned int>(run->projected_hessians)
            << " iterations with the projected Hessian" << std::endl;
  compare_end_states(paper,
                     extrapolated,
                     "the paper's line search and extrapolated projected "
                     "steps");
  bfemp_tests::check(extrapolated.newton_iterations <= paper.newton_iterations,
                     "extrapolation takes no more Newton iterations than the "
                     "paper's line search");
  // Margins rather than the paper's counts: at least 1.3 times the
  // factorizations and 1.5 times the projected iterations (measured 1.46
  // and 1.96).
  bfemp_tests::check(
    1.5 * extrapolated.projected_hessians <= paper.projected_hessians &&
      1.3 * extrapolated.factorizations <= paper.factorizations,
    "extrapolation takes fewer projected iterations and factorizations "
    "(the paper's line search at least 1.5 and 1.3 times as many)");
  compare_end_states(extrapolated,
                     skipping,
                     "extrapolated projected steps with and without skipped "
                     "exact factorizations");
  bfemp_tests::check(
    skipping.newton_iterations <= extrapolated.newton_iterations &&
      skipping.factorizations < extrapolated.factorizations,
    "skipping failed exact factorizations takes no more Newton iterations "
    "and fewer factorizations: " +
      bfemp_tests::format("%.0f", skipping.newton_iterations) + " and " +
      bfemp_tests::format("%.0f", skipping.factorizations) + " against " +
      bfemp_tests::format("%.0f", extrapolated.newton_iterations) + " and " +
      bfemp_tests::format("%.0f", extrapolated.factorizations));
}
