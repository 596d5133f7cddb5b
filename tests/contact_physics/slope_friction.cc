// Friction of an MPM block on a rigid FEM slope against Coulomb's law
// (BFEMP Section 6.4, eq. 40): a rigid block released on a slope of angle
// theta slides with a = g (sin theta - mu cos theta) if mu < tan theta and
// sticks otherwise.
//
// The slope is horizontal here and gravity is tilted by theta = atan(0.2)
// (g = 5.1 m/s^2, the paper's values), which is the same problem in a
// rotated frame: the block's faces stay aligned with the grid, as the
// paper's block is with its slope. The slope is a kinematic FEM body (every
// node prescribed fixed, 0.56 x 0.02); the MPM block 0.1 x 0.02 (dx =
// 0.005, 2 x 2 particles per cell, rho = 100, E = 4e8 Pa, nu = 0.2, stiff so
// that it moves rigidly) starts at rest with its lowest particles 1.75
// dhat above it (particles sit at sub-cell centres). dhat = 1e-3,
// kappa = 1e6, eps_v = 1e-5 m/s, backward Euler, dt = 1e-3 s, eps_d = 1e-8
// m/s, friction iterated to convergence (Algorithm 1), 0.4 s.
//
// mu = 0, 0.1, 0.1999 (99.95 % of critical), 0.2 (critical) and 0.3.
// Checked: the block's velocity along the slope (its momentum over its
// mass; the slope does not move) is linear in time after the first 0.15 s
// (the barrier settles in the first steps), its fitted slope matches a
// within 0.1 % for the sliding cases (measured ~4e-6 relative, also for mu
// = 0.1999 where a is 2000 times smaller than for mu = 0), and for mu >=
// tan theta the block sticks: |v| stays below 10 eps_v (measured ~2.3
// eps_v for the critical mu, whose static friction the mollifier of eq. 36
// can only provide while sliding at ~eps_v, as the paper reports). The
// normal contact force equals m g cos theta to 1e-6 and every friction
// step converged.

#include "slope_scene.h"

using namespace dealii;
using namespace implicit_scene;
using namespace slope_scene;

namespace
{
  constexpr double end_time = 0.4;
  constexpr double top      = 0.1;

  std::string
  scene(const std::string &name, const double mu)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << head(2, 1, 1, name, end_time)
        << fixed_step("implicit backward Euler", 1e-3) << solver(1e-8, false)
        << "subsection grid\n  set lower corner = 0, 0\n"
           "  set upper corner = 0.6, 0.2\n  set cell size = 0.005\n"
           "  set kernel = quadratic\nend\n"
        << physics(mu, top)
        << mpm_box(0,
                   "0.1, 0.1005",
                   "0.2, 0.1205",
                   "0, 0",
                   material("neo-Hookean", 4e8, 0.2, 100.));
    return prm.str();
  }

  void
  check(const double mu)
  {
    const std::string name = "slope_" + rounded(mu, 4);
    write(name + ".prm", scene(name, mu));
    const Outcome<2> outcome = run<2>(name + ".prm");
    bfemp_tests::check(outcome.error.empty(), name + " ran: " + outcome.error);

    const auto          c          = columns(name,
                           {"time",
                                              "momentum_x",
                                              "mass",
                                              "contact_force_m0_f0_y",
                                              "friction_updates",
                                              "newton_iterations"});
    const double        block_mass = c[2][0] - slope_mass(top);
    std::vector<double> velocity;
    for (const double p : c[1])
      velocity.push_back(p / block_mass);
    check_coulomb(c[0], velocity, mu, 0.15, 1e-3);
    // The normal force at the end carries the block's weight component.
    const double normal = -c[3].back();
    const double weight = block_mass * g * cos_theta();
    deallog << "  normal force = m g cos(theta) to 1e-6: "
            << (std::abs(normal - weight) < 1e-6 * weight
                  ? "yes"
                  : "NO (" + rounded(normal / weight - 1.) + ")")
            << std::endl;
    if (mu > 0.)
      deallog << "  friction updated every step: "
              << (*std::min_element(c[4].begin() + 1, c[4].end()) >= 1. ? "yes"
                                                                        : "no")
              << std::endl;
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  for (const double mu : {0., 0.1, 0.1999, 0.2, 0.3})
    check(mu);
}
