#ifndef bfemp_tests_contact_physics_slope_scene_h
#define bfemp_tests_contact_physics_slope_scene_h

// The slope of BFEMP Section 6.4 in the rotated frame, shared by the
// friction tests on the B-spline grid (contact_physics/slope_friction) and
// on cMPM (cmpm/contact_slope): a horizontal kinematic FEM slope, gravity
// tilted by theta = atan(0.2) with g = 5.1 m/s^2 (the paper's values),
// dhat = 1e-3, kappa = 1e6, eps_v = 1e-5 m/s, no walls.

#include "../implicit/implicit_scene.h"

namespace slope_scene
{
  using dealii::deallog;

  constexpr double g       = 5.1;
  constexpr double tangent = 0.2;

  inline double
  sin_theta()
  {
    return tangent / std::sqrt(1. + tangent * tangent);
  }

  inline double
  cos_theta()
  {
    return 1. / std::sqrt(1. + tangent * tangent);
  }

  /** Mass of the slope (0.56 wide, from y = 0.08 up to @p top, rho 1000). */
  inline double
  slope_mass(const double top)
  {
    return 0.56 * (top - 0.08) * 1000.;
  }

  /**
   * Gravity, walls, contact with friction coefficient @p mu and the slope
   * (FEM body 0, every node fixed) with its top face at y = @p top.
   */
  inline std::string
  physics(const double mu, const double top)
  {
    std::ostringstream prm;
    prm << std::setprecision(17)
        << "subsection gravity\n  set acceleration = " << g * sin_theta()
        << ", " << -g * cos_theta()
        << "\nend\n"
           "subsection boundaries\n  set walls = none\nend\n"
           "subsection contact\n  set activation distance = 1e-3\n"
           "  set barrier stiffness = 1e6\n"
           "  set static friction velocity = 1e-5\n"
           "  set friction coefficient = "
        << mu
        << "\nend\n"
           "subsection fem body 0\n  subsection mesh\n"
           "    set source = rectangle\n"
           "    set lower corner = 0.02, 0.08\n"
           "    set upper corner = 0.58, "
        << top << "\n    set target edge length = 0.02\n  end\n"
        << implicit_scene::material("neo-Hookean", 1e6, 0.3, 1000.)
        << "  subsection prescribed motion\n    set nodes = all\n"
           "    set motion = fixed\n  end\nend\n";
    return prm.str();
  }
  /**
   * Coulomb's law for the velocity v(t) along the slope of a block with
   * friction coefficient @p mu: sliding (mu < tan theta), the fitted slope
   * of v over t > @p from matches g (sin theta - mu cos theta) to @p
   * tolerance relative; sticking, |v| stays below 10 eps_v after @p from.
   */
  inline void
  check_coulomb(const std::vector<double> &t,
                const std::vector<double> &v,
                const double               mu,
                const double               from,
                const double               tolerance)
  {
    using implicit_scene::rounded;
    const double sliding = std::max(0., g * (sin_theta() - mu * cos_theta()));
    if (sliding > 0.)
      {
        const double acceleration = implicit_scene::fitted_slope(t, v, from);
        const double error        = std::abs(acceleration - sliding) / sliding;
        deallog << "mu = " << mu << ": a = " << rounded(acceleration, 5)
                << " m/s^2, g (sin - mu cos) = " << rounded(sliding, 5)
                << ", relative error < " << rounded(tolerance, 1) << ": "
                << (error < tolerance ? "yes" : "NO (" + rounded(error) + ")")
                << std::endl;
        return;
      }
    // after the start's bounce on the barrier has settled
    double largest = 0.;
    for (unsigned int i = 0; i < v.size(); ++i)
      if (t[i] > from)
        largest = std::max(largest, std::abs(v[i]));
    deallog << "mu = " << mu << ": sticks, max |v| < 10 eps_v: "
            << (largest < 1e-4 ? "yes" : "NO (" + rounded(largest) + ")")
            << std::endl;
  }
} // namespace slope_scene

#endif
