// Energy behaviour of the two implicit schemes (BFEMP eq. 21) on a free,
// vibrating FEM ring: 2D, annulus 0.15 < r < 0.25 meshed by gmsh (target
// edge 0.025), neo-Hookean E = 1e6 Pa, nu = 0.3, rho = 1000, no gravity, no
// walls, no MPM body. Before run() every node gets the radial velocity
// v = v0 (x - c) / |x - c|, v0 = 0.5 m/s (through Simulation::fem_bodies()),
// which mostly excites the breathing mode (strain amplitude ~1.5 %). The
// ring vibrates for 0.4 s, about 10 breathing periods, with dt = 2e-3 s
// (~20 steps per period).
//
// Midpoint Newmark (alpha = 1/2, beta = 1/4, gamma = 1/2: the trapezoidal
// rule) conserves the energy of a linear system exactly and of this mildly
// nonlinear one to O(dt^2); backward Euler damps a mode of frequency w by
// 1 / (1 + (w dt)^2) in energy per step. Checked:
//  - Newmark: |E(t) / E_0 - 1| < 1 % at every step, while kinetic and
//    elastic energy exchange (E_el reaches > 30 % of E_0, the kinetic
//    energy has >= 15 local minima: the ring really vibrates);
//  - backward Euler: E_end / E_0 < 0.5, and below the Newmark ratio by more
//    than 0.4;
//  - both runs conserve the linear momentum (|p - p_0| < 1e-9 M v0; p_0 is
//    not exactly 0 on the unstructured mesh).

#include "implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double v0       = 0.5;
  constexpr double end_time = 0.4;
  constexpr double dt       = 2e-3;
  const Point<2>   center(0.5, 0.5);

  std::string
  scene(const std::string &name, const std::string &integrator)
  {
    return head(2, 0, 1, name, end_time) + fixed_step(integrator, dt) +
           solver(1e-8, true) +
           "subsection gravity\n  set acceleration = 0, 0\nend\n"
           "subsection boundaries\n  set walls = none\nend\n"
           "subsection fem body 0\n" +
           material("neo-Hookean", 1e6, 0.3, 1000.) +
           "  subsection mesh\n    set source = ring\n"
           "    set center = 0.5, 0.5\n    set inner radius = 0.15\n"
           "    set outer radius = 0.25\n"
           "    set target edge length = 0.025\n  end\nend\n";
  }

  struct Energies
  {
    std::vector<double> total, kinetic, elastic;
    double              max_momentum = 0.; // max |p - p_0| over the rows
    double              mass         = 0.;
  };

  Energies
  run_ring(const std::string &name, const std::string &integrator)
  {
    write(name + ".prm", scene(name, integrator));
    const Outcome<2> outcome =
      run<2>(name + ".prm", [](bfemp::Simulation<2> &simulation) {
        auto &body = *simulation.fem_bodies()[0];
        for (unsigned int a = 0; a < body.n_nodes(); ++a)
          {
            const Tensor<1, 2> r = body.positions()[a] - center;
            body.velocities()[a] = v0 * r / r.norm();
          }
      });
    if (!outcome.error.empty())
      deallog << "error: " << outcome.error << std::endl;
    bfemp_tests::check(outcome.error.empty(),
                       integrator + ": the run reached the end time");
    const auto c = columns(name,
                           {"total_energy",
                            "kinetic_energy",
                            "elastic_energy",
                            "momentum_x",
                            "momentum_y",
                            "mass",
                            "min_J"});
    bfemp_tests::check(finite(c) && c[0].size() == 201 && min_of(c[6]) > 0.,
                       integrator + ": 200 finite steps with det F > 0");
    Energies e;
    e.total   = c[0];
    e.kinetic = c[1];
    e.elastic = c[2];
    e.mass    = c[5][0];
    for (std::size_t k = 0; k < c[0].size(); ++k)
      e.max_momentum =
        std::max(e.max_momentum,
                 std::hypot(c[3][k] - c[3][0], c[4][k] - c[4][0]));
    return e;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  const Energies newmark = run_ring("ring_newmark", "implicit Newmark");
  const Energies euler   = run_ring("ring_euler", "implicit backward Euler");

  const double E0 = newmark.total[0];
  // 1e-10: the csv holds 12 significant digits.
  bfemp_tests::check(std::abs(euler.total[0] - E0) <= 1e-10 * E0 &&
                       std::abs(E0 - 0.5 * newmark.mass * v0 * v0) <=
                         1e-10 * E0,
                     "both start with E_0 = M v0^2 / 2");

  double deviation = 0.;
  for (const double E : newmark.total)
    deviation = std::max(deviation, std::abs(E / E0 - 1.));
  unsigned int kinetic_minima = 0;
  for (std::size_t k = 1; k + 1 < newmark.kinetic.size(); ++k)
    if (newmark.kinetic[k] < newmark.kinetic[k - 1] &&
        newmark.kinetic[k] <= newmark.kinetic[k + 1])
      ++kinetic_minima;
  const double elastic_peak = max_of(newmark.elastic) / E0;
  const double newmark_end  = newmark.total.back() / E0;
  const double euler_end    = euler.total.back() / E0;

  deallog << "Newmark: max |E / E_0 - 1| = " << rounded(deviation, 1)
          << ", E_end / E_0 = " << rounded(newmark_end, 4)
          << ", max E_el / E_0 > 0.9: " << (elastic_peak > 0.9 ? "yes" : "no")
          << std::endl;
  // Backward Euler damps the breathing mode (w dt ~ 0.3) by ~9 % per step.
  deallog << "backward Euler: E_end / E_0 "
          << (euler_end < 1e-6 ? std::string("< 1e-6")
                               : "= " + rounded(euler_end, 2))
          << std::endl;
  bfemp_tests::check(deviation < 1e-2,
                     "Newmark keeps the energy within 1 % at every step");
  bfemp_tests::check(elastic_peak > 0.3 && kinetic_minima >= 15,
                     "the ring vibrates (energy exchange, >= 15 kinetic "
                     "energy minima)");
  bfemp_tests::check(euler_end < 0.5 && newmark_end - euler_end > 0.4,
                     "backward Euler loses clearly more energy");
  bfemp_tests::check(newmark.max_momentum < 1e-9 * newmark.mass * v0 &&
                       euler.max_momentum < 1e-9 * euler.mass * v0,
                     "linear momentum is conserved (1e-9 M v0; it is not "
                     "exactly 0 on the unstructured mesh)");
}
