// A heterogeneous cMPM cube (E 1e6, rho 1000, with a soft, dense ball
// region E 2e4, rho 2000) dropped onto a kinematic FEM slab in 3D: barrier
// contact of a matrix-valued cMPM body in a 3D scene (boundary B-spline,
// L = H, H = 0.05, n = 5, 2 x 2 x 2 coarse elements, 1728 particles; dhat =
// 2e-3, kappa = 1e5, frictionless, backward Euler dt = 5e-3 s, 0.1 s). The
// cube falls 4.7 mm, lands at t = 0.03 s and comes to rest.
// Checked: no particle ever lies inside the slab and the smallest distance
// stays positive; at the end the normal force on the slab equals the cube's
// weight m g to 1e-4 and its momentum is below 1e-4 m g dt.

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double slab_mass = 0.2 * 0.0275 * 0.2 * 1000.;

  std::string
  scene()
  {
    std::ostringstream prm;
    prm << head(3, 1, 1, "cmpm_drop_3d", 0.1) << solver(1e-6, true)
        << "subsection grid\n"
           "  set lower corner = 0, 0, 0\n"
           "  set upper corner = 0.3, 0.3, 0.3\n"
           "  set cell size = 0.05\n"
           "end\n"
           "subsection cmpm\n"
           "  set enabled = true\n"
           "  set coarse element type = boundary B-spline\n"
           "  set coarse node span = H\n"
           "  set fine nodes per direction = 5\n"
           "end\n"
           "subsection time\n"
           "  set integrator = implicit backward Euler\n"
           "  set time step mode = fixed\n"
           "  set time step = 5e-3\n"
           "end\n"
           "subsection transfer\n"
           "  set scheme = PIC\n"
           "end\n"
           "subsection boundaries\n"
           "  set walls = none\n"
           "end\n"
           "subsection contact\n"
           "  set activation distance = 2e-3\n"
           "  set barrier stiffness = 1e5\n"
           "end\n"
           "subsection body 0\n"
           "  set particles per cell = 6\n"
           "  set number of material regions = 1\n"
           "  subsection primitive 0\n"
           "    set type = box\n"
           "    set lower corner = 0.1, 0.1, 0.1\n"
           "    set upper corner = 0.2, 0.2, 0.2\n"
           "  end\n"
           "  subsection material\n"
           "    set Young's modulus = 1e6\n"
           "    set density = 1000\n"
           "  end\n"
           "  subsection material region 0\n"
           "    set type = ball\n"
           "    set center = 0.15, 0.15, 0.15\n"
           "    set outer radius = 0.03\n"
           "    subsection material\n"
           "      set Young's modulus = 2e4\n"
           "      set density = 2000\n"
           "    end\n"
           "  end\n"
           "end\n"
           "subsection fem body 0\n"
           "  subsection mesh\n"
           "    set source = rectangle\n"
           "    set lower corner = 0.05, 0.07, 0.05\n"
           "    set upper corner = 0.25, 0.0975, 0.25\n"
           "    set target edge length = 0.05\n"
           "  end\n"
           "  subsection prescribed motion\n"
           "    set nodes = all\n"
           "    set motion = fixed\n"
           "  end\n"
           "end\n";
    return prm.str();
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  write("cmpm_drop_3d.prm", scene());
  const Outcome<3> outcome = run<3>("cmpm_drop_3d.prm");
  bfemp_tests::check(outcome.error.empty(), "the drop ran: " + outcome.error);
  const auto   c       = columns("cmpm_drop_3d",
                         {"mass",
                                  "momentum_y",
                                  "contact_force_m0_f0_y",
                                  "particles_in_fem",
                                  "min_distance",
                                  "contact_particles"});
  const double m       = c[0][0] - slab_mass;
  const double g       = 9.81;
  double       closest = std::numeric_limits<double>::infinity();
  for (const double d : c[4])
    closest = std::min(closest, d);
  char line[200];
  std::snprintf(line,
                sizeof(line),
                "cube mass %.4f kg; particles inside the slab: %.0f; smallest "
                "distance %.2f dhat",
                m,
                max_of(c[3]),
                closest / 2e-3);
  bfemp_tests::check(max_of(c[3]) == 0. && closest > 0., line);
  bfemp_tests::check(max_of(c[5]) > 100.,
                     "the cube's bottom layer is in contact: at most " +
                       bfemp_tests::format("%.0f", max_of(c[5])) +
                       " particles in contact (more than 100 required)");
  const double force_error = std::abs(-c[2].back() / (m * g) - 1.);
  std::cout << "normal force / m g - 1 = " << -c[2].back() / (m * g) - 1.
            << ", momentum_y = " << c[1].back() << std::endl;
  bfemp_tests::check(force_error < 1e-4,
                     "at rest: normal force = m g to 1e-4: |F / (m g) - 1| " +
                       bfemp_tests::measured(force_error, 1e-4));
  bfemp_tests::check(
    std::abs(c[1].back()) < 1e-4 * m * g * 5e-3,
    "at rest: |momentum| < 1e-4 m g dt: |p_y| / (m g dt) " +
      bfemp_tests::measured(std::abs(c[1].back()) / (m * g * 5e-3), 1e-4));
}
