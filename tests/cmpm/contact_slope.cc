// A heterogeneous cMPM block in barrier frictional contact with an FEM
// slope (BFEMP Sections 4-5 on seed 002's discretization), against
// Coulomb's law: a block released on a slope of angle theta slides with
// a = g (sin theta - mu cos theta) if mu < tan theta and sticks otherwise,
// whatever its stiffness distribution.
//
// The scene is tests/contact_physics/slope_friction's (horizontal kinematic
// FEM slope, gravity tilted by theta = atan(0.2), g = 5.1 m/s^2, dhat =
// 1e-3, kappa = 1e6, eps_v = 1e-5 m/s, backward Euler, dt = 1e-3 s, eps_d
// = 1e-8 m/s) with
// the block 0.1 x 0.02 made of two bodies on one cMPM discretization: its
// left half E = 4e8 Pa, rho = 100, its right half E = 4e6 Pa, rho = 300
// (boundary B-spline, L = H/2, H = 0.02, n = 7, 10 x 10 particles per
// coarse element, the lowest row 1.5 dhat above the slope). Contact acts
// through the matrix-valued chain rule dx_q/du_I = Phi_I(x_q).
//
// mu = 0, 0.1 and 0.3. Checked: the block's velocity along the slope
// (momentum over mass) is linear in time after 0.1 s with the fitted slope
// within 0.2 % of a when sliding; when sticking |v| stays below 10 eps_v;
// the normal contact force on the slope averaged over t > 0.1 s equals
// m g cos theta to 1e-6 (measured < 1e-7; the instantaneous force
// oscillates by a few 1e-6 with the soft half's vertical vibration, its
// largest deviation goes to stdout); no particle ever lies inside the
// slope.

#include "../contact_physics/slope_scene.h"

using namespace dealii;
using namespace implicit_scene;
using namespace slope_scene;

namespace
{
  constexpr double end_time = 0.25;
  constexpr double top      = 0.0995;

  std::string
  scene(const std::string &name, const double mu)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << head(2, 2, 1, name, end_time)
        << fixed_step("implicit backward Euler", 1e-3) << solver(1e-8, true)
        << "subsection grid\n  set lower corner = 0, 0\n"
           "  set upper corner = 0.6, 0.2\n  set cell size = 0.02\nend\n"
           "subsection cmpm\n  set enabled = true\n"
           "  set coarse element type = boundary B-spline\n"
           "  set coarse node span = H/2\n"
           "  set fine nodes per direction = 7\nend\n"
           "subsection transfer\n  set scheme = PIC\nend\n"
        << physics(mu, top)
        << mpm_box(0,
                   "0.1, 0.1",
                   "0.15, 0.12",
                   "0, 0",
                   material("neo-Hookean", 4e8, 0.2, 100.),
                   10)
        << mpm_box(1,
                   "0.15, 0.1",
                   "0.2, 0.12",
                   "0, 0",
                   material("neo-Hookean", 4e6, 0.2, 300.),
                   10);
    return prm.str();
  }

  void
  check(const double mu)
  {
    const std::string name = "cmpm_slope_" + rounded(mu, 4);
    write(name + ".prm", scene(name, mu));
    const Outcome<2> outcome = run<2>(name + ".prm");
    bfemp_tests::check(outcome.error.empty(), name + " ran: " + outcome.error);

    const auto          c          = columns(name,
                           {"time",
                                              "momentum_x",
                                              "mass",
                                              "contact_force_m0_f0_y",
                                              "contact_force_m1_f0_y",
                                              "particles_in_fem"});
    const double        block_mass = c[2][0] - slope_mass(top);
    std::vector<double> velocity;
    for (const double p : c[1])
      velocity.push_back(p / block_mass);
    check_coulomb(c[0], velocity, mu, 0.1, 2e-3);
    const double weight  = block_mass * g * cos_theta();
    double       sum     = 0.;
    double       largest = 0.;
    unsigned int n       = 0;
    for (unsigned int i = 0; i < c[0].size(); ++i)
      if (c[0][i] > 0.1)
        {
          const double normal = -(c[3][i] + c[4][i]);
          sum += normal;
          largest = std::max(largest, std::abs(normal / weight - 1.));
          ++n;
        }
    const double mean = sum / n;
    deallog << "  mean normal force over t > 0.1 = m g cos(theta) to 1e-6: "
            << (std::abs(mean - weight) < 1e-6 * weight
                  ? "yes"
                  : "NO (" + rounded(mean / weight - 1.) + ")")
            << ", particles inside the slope: " << max_of(c[5]) << std::endl;
    std::cout << name
              << ": mean normal force / m g cos - 1 = " << mean / weight - 1.
              << ", largest instantaneous deviation = " << largest << std::endl;
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  for (const double mu : {0., 0.1, 0.3})
    check(mu);
}
