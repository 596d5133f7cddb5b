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

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double g        = 5.1;
  constexpr double tangent  = 0.2;
  constexpr double end_time = 0.4;
  constexpr double fem_mass = 0.56 * 0.02 * 1000.;

  double
  sin_theta()
  {
    return tangent / std::sqrt(1. + tangent * tangent);
  }

  double
  cos_theta()
  {
    return 1. / std::sqrt(1. + tangent * tangent);
  }

  std::string
  scene(const std::string &name, const double mu)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << head(2, 1, 1, name, end_time)
        << fixed_step("implicit backward Euler", 1e-3) << solver(1e-8, false)
        << "subsection grid\n  set lower corner = 0, 0\n"
           "  set upper corner = 0.6, 0.2\n  set cell size = 0.005\n"
           "  set kernel = quadratic\nend\n"
           "subsection gravity\n  set acceleration = "
        << g * sin_theta() << ", " << -g * cos_theta()
        << "\nend\n"
           "subsection boundaries\n  set walls = none\nend\n"
           "subsection contact\n  set activation distance = 1e-3\n"
           "  set barrier stiffness = 1e6\n"
           "  set static friction velocity = 1e-5\n"
           "  set friction coefficient = "
        << mu << "\nend\n"
        << mpm_box(0,
                   "0.1, 0.1005",
                   "0.2, 0.1205",
                   "0, 0",
                   material("neo-Hookean", 4e8, 0.2, 100.))
        << "subsection fem body 0\n  subsection mesh\n"
           "    set source = rectangle\n"
           "    set lower corner = 0.02, 0.08\n"
           "    set upper corner = 0.58, 0.1\n"
           "    set target edge length = 0.02\n  end\n"
        << material("neo-Hookean", 1e6, 0.3, 1000.)
        << "  subsection prescribed motion\n    set nodes = all\n"
           "    set motion = fixed\n  end\nend\n";
    return prm.str();
  }

  /** Least-squares slope of y(t) over t >= t0. */
  double
  fitted_slope(const std::vector<double> &t,
               const std::vector<double> &y,
               const double               t0)
  {
    double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
    for (unsigned int i = 0; i < t.size(); ++i)
      if (t[i] >= t0)
        {
          n += 1;
          st += t[i];
          sy += y[i];
          stt += t[i] * t[i];
          sty += t[i] * y[i];
        }
    return (n * sty - st * sy) / (n * stt - st * st);
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
    const double        block_mass = c[2][0] - fem_mass;
    std::vector<double> velocity;
    for (const double p : c[1])
      velocity.push_back(p / block_mass);
    const double sliding = std::max(0., g * (sin_theta() - mu * cos_theta()));
    const double acceleration = fitted_slope(c[0], velocity, 0.15);

    if (sliding > 0.)
      {
        const double error = std::abs(acceleration - sliding) / sliding;
        deallog << "mu = " << mu << ": a = " << rounded(acceleration, 5)
                << " m/s^2, g (sin - mu cos) = " << rounded(sliding, 5)
                << ", relative error < 1e-3: "
                << (error < 1e-3 ? "yes" : "NO (" + rounded(error) + ")")
                << std::endl;
      }
    else
      {
        // After the start's bounce on the barrier has settled.
        double largest = 0.;
        for (unsigned int i = 0; i < velocity.size(); ++i)
          if (c[0][i] >= 0.15)
            largest = std::max(largest, std::abs(velocity[i]));
        deallog << "mu = " << mu << ": sticks, max |v| < 10 eps_v: "
                << (largest < 1e-4 ? "yes" : "NO (" + rounded(largest) + ")")
                << std::endl;
      }
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
