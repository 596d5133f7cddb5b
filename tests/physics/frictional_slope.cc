// Coulomb friction of a grid boundary (separable slip, BoundaryCondition):
// an elastic block on a frictional half-plane, with gravity tilted by
// theta = 20 degrees (the same physics as a block on a slope). While it
// slides, its centre of mass must accelerate at g (sin theta - mu cos theta).
// With mu above tan theta it must (nearly) stop: grid-node friction removes
// at most mu |v_n| per node and step, so the block creeps slowly, and the
// test bounds that creep.

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <deal.II/base/numbers.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "diagnostics_csv.h"
#include "format.h"
#include "tests.h"

using namespace dealii;

namespace
{
  const double g     = 9.81;
  const double theta = 20. * numbers::PI / 180.;

  /** Least-squares slope of v_x(t) over t > 0.1 s, from diagnostics.csv. */
  double
  acceleration(const std::string &csv)
  {
    const auto columns =
      bfemp_tests::read_columns(csv, {"time", "momentum_x", "mass"});
    double n = 0, st = 0, sv = 0, stt = 0, stv = 0;
    for (unsigned int k = 0; k < columns[0].size(); ++k)
      if (const double t = columns[0][k]; t > 0.1)
        {
          const double v = columns[1][k] / columns[2][k];
          n += 1;
          st += t;
          sv += v;
          stt += t * t;
          stv += t * v;
        }
    return (n * stv - st * sv) / (n * stt - st * st);
  }

  double
  run(const double mu)
  {
    const std::string name = "slope_" + std::to_string(mu);
    {
      std::ofstream prm(name + ".prm");
      prm << "set dimension = 2\n"
          << "subsection run\n  set name = " << name
          << "\n  set end time = 0.3\n  set quiet = true\nend\n"
          << "subsection grid\n  set upper corner = 2, 0.5\n"
             "  set cell size = 0.01\nend\n"
          << "subsection time\n  set CFL number = 0.3\nend\n"
          << std::setprecision(17) << "subsection gravity\n"
          << "  set acceleration = " << g * std::sin(theta) << ", "
          << -g * std::cos(theta) << "\nend\n"
          << "subsection boundaries\n  set walls = none\n"
             "  set number of level sets = 1\n"
             "  subsection level set 0\n    set type = half-plane\n"
             "    set point = 0, 0.1\n    set normal = 0, 1\n"
             "    set condition = separable slip\n"
          << "    set friction = " << mu << "\n  end\nend\n"
          << "subsection output\n  set directory = results\n"
             "  set write particles = false\nend\n"
          << "subsection body 0\n  subsection primitive 0\n"
             "    set lower corner = 0.2, 0.1\n"
             "    set upper corner = 0.5, 0.2\n  end\n"
             "  subsection material\n    set Young's modulus = 1e6\n"
             "    set density = 1000\n  end\nend\n";
    }
    bfemp::SceneParameters<2> parameters;
    parameters.read(name + ".prm");
    std::ostringstream   console;
    bfemp::Simulation<2> simulation(parameters, name + ".prm", console);
    simulation.run();
    return acceleration("results/" + name + "/diagnostics.csv");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  for (const double mu : {0., 0.1, 0.2})
    {
      const double a     = run(mu);
      const double exact = g * (std::sin(theta) - mu * std::cos(theta));
      const double error = std::abs(a - exact) / exact;
      std::cout << "mu " << mu << ": a = " << a << ", exact " << exact
                << ", relative error " << error << std::endl;
      deallog << "mu " << mu << ": measured acceleration "
              << bfemp_tests::format("%.4f", a) << " m/s^2, exact "
              << bfemp_tests::format("%.4f", exact)
              << ", relative error "
              // round-off (mu = 0) as a bound, so that numdiff compares
              // only measured digits
              << (error < 1e-10 ? std::string("below 1e-10")
                                : bfemp_tests::format("%.1e", error))
              << std::endl;
      bfemp_tests::check(error < 1e-3,
                         "sliding block accelerates at g (sin - mu cos) "
                         "within 0.1 %");
    }

  const double a_stick = run(0.5);
  deallog << "mu 0.5 (> tan theta): measured acceleration "
          << bfemp_tests::format("%.4f", a_stick) << " m/s^2, "
          << bfemp_tests::format("%.4f", a_stick / (g * std::sin(theta)))
          << " of the frictionless one" << std::endl;
  bfemp_tests::check(std::abs(a_stick) < 0.1 * g * std::sin(theta),
                     "mu = 0.5 > tan(theta): the block creeps at less than "
                     "10 % of the frictionless acceleration");
}
