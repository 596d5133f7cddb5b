// A surface load (`body/surface load k`) on a free 2D bar, on the
// B-spline grid and on cMPM: the bar [0.2, 1.2] x [0.2, 0.4] m (E 1e4 Pa,
// nu 0, rho 1 kg/m^2, no gravity, 10 particles per 0.1 m) is pulled at its
// x+ face by a traction sigma = 10 Pa, applied from t = 0 with backward
// Euler steps of 0.01 s up to 0.2 s. Checked:
// - the total force is sigma times the face's length: the centre of mass
//   accelerates at a = sigma h / M = 10 m/s^2, so its velocity at t = 0.2 s
//   is 2 m/s (to 1e-6: momentum is exact in both discretizations);
// - the load is a traction on the face, not a body force: in the
//   accelerating bar the stress falls linearly from sigma at x+ to 0 at
//   x-, and once the waves of the sudden load are damped (backward Euler)
//   the elastic energy is sigma^2 h L / (6 E) = 3.33e-4 J (within 5 %);
// - the explicit integrators (USL, USF) apply the load as a grid force, and
//   the substepped one in its substeps, with the same total: 2 m/s (their
//   energy is not checked: the explicit runs oscillate undamped);
// - a layer that holds no particle is refused.

#include <bfemp/base/input_error.h>

#include <cmath>
#include <fstream>
#include <string>

#include "diagnostics_csv.h"
#include "format.h"
#include "run_scene.h"
#include "tests.h"

using namespace dealii;

namespace
{
  const std::string bar = R"(set dimension        = 2
set number of bodies = 1
subsection run
  set end time = 0.2
  set quiet    = true
end
subsection grid
  set lower corner = 0, 0
  set upper corner = 2.4, 0.6
end
subsection time
  set integrator     = implicit backward Euler
  set time step mode = fixed
  set time step      = 0.01
end
subsection gravity
  set acceleration = 0, 0
end
subsection boundaries
  set walls = none
end
subsection output
  set directory = results
  set interval  = 1
end
subsection body 0
  set number of surface loads = 1
  subsection primitive 0
    set type         = box
    set lower corner = 0.2, 0.2
    set upper corner = 1.2, 0.4
  end
  subsection material
    set model           = neo-Hookean
    set Young's modulus = 1e4
    set Poisson's ratio = 0
    set density         = 1
  end
  subsection surface load 0
    set face     = x+
    set traction = 10, 0
  end
end
)";

  const std::string kernel_grid = R"(subsection grid
  set cell size = 0.02
  set kernel    = quadratic
end
subsection body 0
  set particles per cell = 2
end
)";

  const std::string cmpm = R"(subsection grid
  set cell size = 0.1
end
subsection cmpm
  set enabled = true
end
subsection transfer
  set scheme = PIC
end
subsection body 0
  set particles per cell = 10
end
)";

  void
  run(const std::string &name,
      const std::string &discretization,
      const bool         damped = true)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << bar << discretization << "subsection run\n  set name = " << name
          << "\nend\n";
    }
    bfemp_tests::run_scene<2>(name + ".prm");
    const auto bodies = bfemp_tests::read_columns(
      "results/" + name + "/bodies.csv",
      {"mpm0_com_velocity_x", "mpm0_com_velocity_y", "mpm0_elastic_energy"});
    const double v_x             = bodies[0].back();
    const double v_y             = bodies[1].back();
    const double energy          = bodies[2].back();
    const double expected_energy = 10. * 10. * 0.2 * 1. / (6. * 1e4);
    deallog << name << ": centre-of-mass velocity "
            << bfemp_tests::format("%.6f", v_x) << " m/s";
    if (damped)
      deallog << ", elastic energy " << bfemp_tests::format("%.3e", energy)
              << " J (analytic " << bfemp_tests::format("%.3e", expected_energy)
              << ")";
    deallog << std::endl;
    std::cout << name << ": v_y " << v_y << ", elastic energy " << energy
              << std::endl;
    bfemp_tests::check(std::abs(v_x - 2.) < 1e-6 && std::abs(v_y) < 1e-9,
                       name + ": the load's total force is sigma h");
    if (damped)
      bfemp_tests::check(std::abs(energy / expected_energy - 1.) < 0.05,
                         name + ": the stress falls linearly from the loaded "
                                "face (elastic energy within 5 %)");
  }

  void
  refuse(const std::string &name, const std::string &entries)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << bar << kernel_grid << entries
          << "subsection run\n  set name = " << name << "\nend\n";
    }
    try
      {
        bfemp_tests::run_scene<2>(name + ".prm");
        bfemp_tests::check(false, name + ": refused");
      }
    catch (const bfemp::InputError &error)
      {
        deallog << name << ": " << error.what() << std::endl;
        bfemp_tests::check(true, name + ": refused");
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  run("bspline_grid", kernel_grid);
  run("cmpm", cmpm);
  // explicit: no damping of the waves, so the energy oscillates
  for (const std::string variant : {"USL", "USF"})
    run("explicit_" + variant,
        kernel_grid + "subsection time\n  set integrator = explicit " +
          variant + "\n  set time step = 1e-4\nend\n",
        false);
  run("substepped",
      kernel_grid + "subsection time\n  set integrator = substepped "
                    "explicit\nend\n",
      false);
  refuse("thin_layer",
         "subsection body 0\n  subsection surface load 0\n"
         "    set layer depth = 0.001\n  end\nend\n");
}
