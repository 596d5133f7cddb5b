#ifndef bfemp_tests_experiments_refinement_check_h
#define bfemp_tests_experiments_refinement_check_h

// BFEMP Section 6.5 (convergence under refinement), shared by the reduced
// test (tests/experiments/refinement) and the full-resolution one
// (tests/validation/refinement_full): run each resolution's scene, read
// the whole system's settled centre-of-mass height h (MPM box and FEM box,
// mass-weighted, from bodies.csv), and fit the order of |h_N - h_ref| in
// dx = 1/N.

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "../implicit/implicit_scene.h"

namespace refinement_check
{
  using namespace dealii;

  /**
   * Runs @p base_prm as results/<name>; returns the final whole-system
   * centre-of-mass height and its largest change over the last second.
   */
  inline std::pair<double, double>
  settled_height(const std::string &base_prm, const std::string &name)
  {
    implicit_scene::write(
      name + ".prm",
      "include " + base_prm + "\nsubsection run\n  set name = " + name +
        "\n  set quiet = true\nend\n"
        "subsection output\n  set directory = results\n"
        "  set write particles = false\n  set write grid = false\nend\n");
    const implicit_scene::Outcome<2> outcome =
      implicit_scene::run<2>(name + ".prm");
    bfemp_tests::check(outcome.error.empty(), name + " ran: " + outcome.error);

    const auto c = bfemp_tests::read_columns(
      "results/" + name + "/bodies.csv",
      {"time", "mpm0_mass", "mpm0_com_y", "fem0_mass", "fem0_com_y"});
    std::vector<double> h;
    for (unsigned int i = 0; i < c[0].size(); ++i)
      h.push_back((c[1][i] * c[2][i] + c[3][i] * c[4][i]) /
                  (c[1][i] + c[3][i]));
    double change = 0.;
    for (unsigned int i = 0; i < h.size(); ++i)
      if (c[0][i] >= c[0].back() - 1.)
        change = std::max(change, std::abs(h[i] - h.back()));
    return {h.back(), change};
  }

  /**
   * Runs the scene @p prm_of(N) for every N of @p ns and for @p reference,
   * checks that the errors |h_N - h_ref| decrease with N and returns their
   * least-squares order in dx = 1/N (the paper's Figure 14).
   *
   * It also checks that each run is static at its end, where "static" is
   * measured against what the height is used for: h changed over the last
   * second by less than 1e-3 of the run's error (for the reference: of the
   * smallest error). Some runs still creep downward at the end, the MPM box
   * compressing slowly with a decay time of about 9 s (N = 10, PPC 16:
   * 1.6e-6 m in the last second, 2e-7 m/s at t = 30 s); with that decay
   * the bound keeps the height that the creep would still change below 1 %
   * of the error.
   */
  template <typename PrmOf>
  double
  fitted_order(const std::vector<unsigned int> &ns,
               const unsigned int               reference,
               const PrmOf                     &prm_of)
  {
    std::map<unsigned int, std::pair<double, double>> settled;
    std::vector<unsigned int>                         all = ns;
    all.push_back(reference);
    for (const unsigned int n : all)
      settled[n] =
        settled_height(prm_of(n), "refinement_N" + std::to_string(n));
    const double h_ref = settled[reference].first;

    double       sx = 0, sy = 0, sxx = 0, sxy = 0;
    double       previous   = std::numeric_limits<double>::infinity();
    bool         decreasing = true;
    const double m          = ns.size();
    for (const unsigned int n : ns)
      {
        const auto [h, change] = settled[n];
        const double error     = std::abs(h - h_ref);
        deallog << "N = " << n << ": h = " << implicit_scene::rounded(h, 5)
                << " m, |h - h_" << reference
                << "| = " << implicit_scene::rounded(error, 2) << " m"
                << std::endl;
        bfemp_tests::check(change < 1e-3 * error,
                           "  static: h changed by < 1e-3 of the error in the "
                           "last second");
        decreasing     = decreasing && error < previous;
        previous       = error;
        const double x = std::log(1. / n), y = std::log(error);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
      }
    deallog << "N = " << reference
            << " (reference): h = " << implicit_scene::rounded(h_ref, 5) << " m"
            << std::endl;
    bfemp_tests::check(settled[reference].second < 1e-3 * previous,
                       "  static: h changed by < 1e-3 of the smallest error "
                       "in the last second");
    bfemp_tests::check(decreasing, "the error decreases with N");
    const double order = (m * sxy - sx * sy) / (m * sxx - sx * sx);
    deallog << "fitted order = " << implicit_scene::rounded(order, 3)
            << std::endl;
    return order;
  }
} // namespace refinement_check

#endif
