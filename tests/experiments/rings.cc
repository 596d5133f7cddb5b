// BFEMP Section 6.1, colliding rings, reduced: runs
// prm/experiments/6_1_rings/rings_reduced.prm (the paper's scene and contact
// parameters at dx = 0.4, 2 x 2 particles per cell, FEM edge 0.5, Newmark
// h = 5e-4 s) with APIC and with FLIP and checks what the paper reports,
// within the bands that doc/experiments/rings.md justifies:
//  - total momentum conserved to the solver tolerance: every row within
//    n_steps M eps_d of the initial one (the paper: "perfectly preserved");
//  - the collision window, first / last row with contact pairs: paper
//    0.025 s / 0.293 s; band +-0.003 s / +-0.01 s;
//  - the energy (kinetic + elastic + barrier) lost by the first row after
//    the collision: paper 8.57 % (APIC), 9.67 % (FLIP); band 4 % .. 22 %.
//    At this resolution the loss is chaotic: the surface particles bounce
//    on the barrier, and perturbations of round-off size (the Newton
//    tolerance, exact or projected Hessian, BLAS threads in CHOLMOD) as well
//    as grid offsets move it between 7.8 and 15.3 % (APIC) and 12.5 and
//    19.0 % (FLIP) over 26 runs, see doc/experiments/rings.md. The band
//    holds all of them with a margin; it is a plausibility band, not a
//    convergence result. For the same reason the measured values go to
//    stdout, not into the compared output, and the paper's ordering (FLIP
//    loses more than APIC, true in 12 of 13 paired runs) is not checked;
//  - after the separation the FEM ring keeps its energy (bodies.csv, kinetic
//    + elastic of fem0, within 0.5 % of its value after the collision) while
//    the MPM ring loses some (particle-grid transfers).

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double eps_d = 1e-6;
  constexpr double speed = 40.;

  void
  check_scheme(const std::string &scheme)
  {
    const std::string name   = "rings_" + scheme;
    const std::string prefix = scheme + ": ";
    write(name + ".prm",
          "include " BFEMP_SOURCE_DIR
          "/prm/experiments/6_1_rings/rings_reduced.prm\n"
          "subsection run\n  set name = " +
            name +
            "\n  set quiet = true\nend\n"
            "subsection transfer\n  set scheme = " +
            scheme +
            "\nend\n"
            "subsection output\n  set directory = results\n"
            "  set write particles = false\n  set write grid = false\nend\n");
    const auto outcome = run<2>(name + ".prm");
    deallog << scheme << std::endl;
    if (!outcome.error.empty())
      deallog << "error: " << outcome.error << std::endl;
    bfemp_tests::check(outcome.error.empty(),
                       prefix + "the run reached the end time");

    const auto c = columns(name,
                           {"time",
                            "dt",
                            "total_energy",
                            "barrier_energy",
                            "momentum_x",
                            "momentum_y",
                            "mass",
                            "contact_pairs",
                            "min_distance"});
    const auto b = bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                             {"mpm0_kinetic_energy",
                                              "mpm0_elastic_energy",
                                              "fem0_kinetic_energy",
                                              "fem0_elastic_energy"});
    const std::size_t n = c[0].size();
    bfemp_tests::check(n > 2 && b[0].size() == n,
                       prefix + "diagnostics and bodies rows");
    bfemp_tests::check(finite({c[2], c[3], c[4], c[5]}),
                       prefix + "finite diagnostics");

    // Momentum: the gradients of elasticity and barrier sum to zero, so a
    // step changes p by at most M eps_d per component.
    const double M     = c[6][0];
    const double bound = (n - 1) * M * eps_d;
    double       drift = 0.;
    for (std::size_t k = 0; k < n; ++k)
      drift = std::max(
        {drift, std::abs(c[4][k] - c[4][0]), std::abs(c[5][k] - c[5][0])});
    deallog << "  max |p - p0| / (M v0) "
            << (drift < 1e-10 * M * speed ? std::string("< 1e-10")
                                          : rounded(drift / (M * speed), 1))
            << std::endl;
    bfemp_tests::check(drift <= bound,
                       prefix + "total momentum conserved to n_steps M eps_d");

    // Collision window.
    std::size_t first = 0, last = 0;
    double      min_distance = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < n; ++k)
      {
        min_distance = std::min(min_distance, c[8][k]);
        if (c[7][k] > 0.)
          {
            if (first == 0)
              first = k;
            last = k;
          }
      }
    std::cout << scheme << ": contact from t = " << rounded(c[0][first], 3)
              << " s to t = " << rounded(c[0][last], 3) << " s" << std::endl;
    bfemp_tests::check(min_distance > 0., prefix + "no penetration");
    bfemp_tests::check(first > 0 && std::abs(c[0][first] - 0.025) <= 0.003,
                       prefix + "contact starts at 0.025 +- 0.003 s");
    bfemp_tests::check(last + 1 < n && std::abs(c[0][last] - 0.293) <= 0.01,
                       prefix + "contact ends at 0.293 +- 0.01 s");
    if (first == 0 || last + 1 >= n)
      return;

    // Energy lost in the collision.
    std::vector<double> E(n);
    for (std::size_t k = 0; k < n; ++k)
      E[k] = c[2][k] + c[3][k];
    const std::size_t after = last + 1;
    const double      loss  = 1. - E[after] / E[0];
    std::cout << scheme << ": energy lost in the collision "
              << rounded(100. * loss, 3) << " %" << std::endl;
    bfemp_tests::check(loss >= 0.04 && loss <= 0.22,
                       prefix + "energy lost in the collision within "
                                "4 % .. 22 % (paper 8.57 % / 9.67 %)");

    // After the separation.
    const auto   fem = [&](const std::size_t k) { return b[2][k] + b[3][k]; };
    const auto   mpm = [&](const std::size_t k) { return b[0][k] + b[1][k]; };
    const double fem_change = fem(n - 1) / fem(after) - 1.;
    const double mpm_change = mpm(n - 1) / mpm(after) - 1.;
    std::cout << scheme << ": after the separation ("
              << rounded(c[0][n - 1] - c[0][after], 2)
              << " s): FEM ring energy " << std::showpos
              << rounded(100. * fem_change, 1) << " %, MPM ring "
              << rounded(100. * mpm_change, 2) << std::noshowpos << " %"
              << std::endl;
    bfemp_tests::check(std::abs(fem_change) <= 5e-3,
                       prefix + "the FEM ring keeps its energy (0.5 %)");
    bfemp_tests::check(mpm_change < 0., prefix + "the MPM ring loses energy");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  for (const std::string scheme : {"APIC", "FLIP"})
    check_scheme(scheme);
}
