// Implicit backward Euler far beyond the explicit stability limit: a 2D
// neo-Hookean block (E = 1e7 Pa, nu = 0.3, rho = 1000, c_p = 116 m/s)
// moving at 0.2 m/s along x falls 0.1 m under gravity onto the bottom wall
// of the grid and settles,
// with dt = 100 dx / c_p = 0.043 s, i.e. 100 times the explicit CFL step
// (explicit MPM at CFL 1), 24 steps over 1 s. Four scenes: an MPM block
// (64 particles) and an FEM block (rectangle, 128 triangles) each on a
// sticky and on a slip wall (2 layers; walls hold FEM nodes inside them like
// grid nodes). 'solver/check invariants = true' stops a run if any accepted
// Newton iterate has det F <= 0. Checked for each scene:
//  - the run reaches the end time, every diagnostics row is finite and has
//    min det F > 0;
//  - backward Euler dissipates: the total energy (kinetic + elastic +
//    gravitational, zero at y = 0) never exceeds its initial value
//    (1e-9 relative) and the energy ratio E_end / E_0 is printed;
//  - the block came down onto the wall and rests there: its centre of mass
//    fell by 0.05 .. 0.15 m, has moved less than 1e-4 m over the last
//    0.25 s; on the sticky wall its largest speed at the end is below 1e-3
//    m/s (vs. 1.4 m/s at impact); on the slip wall its x momentum is
//    conserved (1e-9 relative) and it slides rigidly (max |v| = v_x and
//    p_y = 0 to 1e-3 m/s at the end).

#include "implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double dx       = 0.05;
  constexpr double youngs   = 1e7;
  constexpr double poisson  = 0.3;
  constexpr double density  = 1000.;
  constexpr double gravity  = 9.81;
  constexpr double end_time = 1.;

  double
  p_wave_speed()
  {
    const double lambda =
      youngs * poisson / ((1. + poisson) * (1. - 2. * poisson));
    const double mu = youngs / (2. * (1. + poisson));
    return std::sqrt((lambda + 2. * mu) / density);
  }

  std::string
  scene(const std::string &name,
        const bool         fem,
        const std::string &wall,
        const double       dt)
  {
    std::string prm =
      head(2, fem ? 0 : 1, fem ? 1 : 0, name, end_time) +
      fixed_step("implicit backward Euler", dt) + solver(1e-6, true) +
      "subsection grid\n  set lower corner = 0, 0\n"
      "  set upper corner = 1, 0.6\n  set cell size = 0.05\n"
      "  set kernel = quadratic\nend\n"
      "subsection gravity\n  set acceleration = 0, -9.81\nend\n"
      "subsection boundaries\n  set walls = all\n  set wall condition = " +
      wall + "\nend\n";
    const std::string mat = material("neo-Hookean", youngs, poisson, density);
    if (fem)
      prm += "subsection fem body 0\n  set initial velocity = 0.2, 0\n" + mat +
             "  subsection mesh\n    set source = rectangle\n"
             "    set lower corner = 0.4, 0.2\n"
             "    set upper corner = 0.6, 0.4\n"
             "    set target edge length = 0.025\n  end\nend\n";
    else
      prm += mpm_box(0, "0.4, 0.2", "0.6, 0.4", "0.2, 0", mat);
    return prm;
  }

  void
  check_scene(const bool fem, const std::string &wall, const double dt)
  {
    const std::string name = std::string(fem ? "fem_" : "mpm_") + wall;
    write(name + ".prm", scene(name, fem, wall, dt));
    const Outcome<2> outcome = run<2>(name + ".prm");
    deallog << (fem ? "FEM" : "MPM") << " block on a " << wall << " wall"
            << std::endl;
    if (!outcome.error.empty())
      deallog << "error: " << outcome.error << std::endl;
    bfemp_tests::check(outcome.error.empty(), "the run reached the end time");

    const auto c = columns(name,
                           {"time",
                            "total_energy",
                            "gravitational_energy",
                            "mass",
                            "min_J",
                            "max_speed",
                            "newton_iterations",
                            "momentum_x",
                            "momentum_y"});
    bfemp_tests::check(finite(c), "every diagnostics row is finite");
    const std::size_t n = c[0].size();
    bfemp_tests::check(n == 25, "24 steps of dt = 100 dx / c_p");
    bfemp_tests::check(min_of(c[4]) > 0.,
                       "min det F > 0 at every step (and every Newton "
                       "iterate: check invariants)");

    const double E0 = c[1][0];
    const double E_max =
      max_of(std::vector<double>(c[1].begin() + 1, c[1].end()));
    const double E_end  = c[1].back();
    const auto   height = [&](const std::size_t k) {
      return c[2][k] / (c[3][k] * gravity);
    };
    const double drop = height(0) - height(n - 1);
    // Rows at t = 0.75 s and 1 s: 0.75 / dt is not an integer; take the
    // row at or just before 0.75 s.
    std::size_t late = 0;
    while (c[0][late + 1] <= 0.75)
      ++late;
    const double creep = std::abs(height(n - 1) - height(late));

    deallog << "  min det F " << rounded(min_of(c[4]), 2)
            << ", E_max / E_0 (after t = 0) " << rounded(E_max / E0, 4)
            << ", E_end / E_0 " << rounded(E_end / E0, 3)
            << ", centre of mass drop " << rounded(drop, 2) << " m"
            << std::endl;
    bfemp_tests::check(E_max <= E0 * (1. + 1e-9),
                       "the total energy never exceeds its initial value");
    bfemp_tests::check(drop > 0.05 && drop < 0.15,
                       "the block came down onto the wall");
    bfemp_tests::check(creep < 1e-4,
                       "the centre of mass height changed < 1e-4 m over "
                       "the last 0.25 s");
    if (wall == "sticky")
      bfemp_tests::check(c[5].back() < 1e-3,
                         "max speed at the end < 1e-3 m/s: at rest");
    else
      {
        // Frictionless: nothing acts along x, the block keeps sliding at
        // 0.2 m/s (1e-9 relative: the Newton tolerance), rigidly (max |v|
        // = |v_x| to 1e-3 m/s).
        double drift = 0.;
        for (std::size_t k = 0; k < n; ++k)
          drift = std::max(drift, std::abs(c[7][k] - c[7][0]));
        const double v_x = c[7].back() / c[3].back();
        deallog << "  sliding velocity at the end " << rounded(v_x, 6) << " m/s"
                << std::endl;
        bfemp_tests::check(drift <= 1e-9 * std::abs(c[7][0]),
                           "x momentum conserved on the slip wall");
        bfemp_tests::check(std::abs(c[5].back() - v_x) < 1e-3 &&
                             std::abs(c[8].back()) < 1e-3 * c[3].back(),
                           "the block slides rigidly along the wall, at "
                           "rest vertically");
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  const double explicit_step = dx / p_wave_speed();
  const double dt            = 100. * explicit_step;
  deallog << "c_p = " << rounded(p_wave_speed()) << " m/s, explicit CFL step "
          << "dx / c_p = " << rounded(explicit_step)
          << " s, dt = " << rounded(dt) << " s" << std::endl;

  for (const bool fem : {false, true})
    for (const std::string wall : {"sticky", "slip"})
      check_scene(fem, wall, dt);
}
