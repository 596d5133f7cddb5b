// 'body N/initial displacement' u(X) as muParser expressions of the rest
// position: a box [0.2, 1] x [0.2, 0.4] (2 x 2 particles per cell of 0.05,
// neo-Hookean E 1e5, nu 0.3) starts bent and stretched,
//   u = (0.05 (x - 0.2)^2, 0.02 sin(pi x) y).
// At t = 0 (row 0 of bodies.csv) the particles' elastic energy must be
// sum_p V_p psi(I + grad u(X_p)) with the analytic gradient at the regular
// sampling positions (the code differentiates the expressions numerically:
// fourth-order differences, agreement to 1e-9 relative), and the centre of
// mass must be the mean of X_p + u(X_p). A second run with the constant
// entry 0.1, 0 translates the body rigidly: no elastic energy.

#include <bfemp/material/material.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "diagnostics_csv.h"
#include "format.h"
#include "run_scene.h"
#include "tests.h"

using namespace dealii;
using bfemp_tests::format;

namespace
{
  std::vector<std::vector<double>>
  run(const std::string &name, const std::string &displacement)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << "set dimension = 2\n"
             "subsection run\n  set name = "
          << name
          << "\n  set end time = 1e-5\n  set quiet = true\nend\n"
             "subsection grid\n  set upper corner = 1.4, 0.8\n"
             "  set cell size = 0.05\nend\n"
             "subsection time\n  set time step mode = fixed\n"
             "  set time step = 1e-5\nend\n"
             "subsection gravity\n  set acceleration = 0, 0\nend\n"
             "subsection output\n  set directory = results\nend\n"
             "subsection body 0\n"
             "  set initial displacement = "
          << displacement
          << "\n"
             "  subsection primitive 0\n    set type = box\n"
             "    set lower corner = 0.2, 0.2\n"
             "    set upper corner = 1.0, 0.4\n  end\n"
             "  subsection material\n    set Young's modulus = 1e5\n"
             "    set Poisson's ratio = 0.3\n    set density = 1000\n"
             "  end\nend\n";
    }
    bfemp_tests::run_scene<2>(name + ".prm");
    return bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                     {"mpm0_elastic_energy",
                                      "mpm0_com_x",
                                      "mpm0_com_y"});
  }

} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  // the analytic energy and centre of mass over the regular sampling
  const auto material =
    bfemp::create_material<2>("neo-Hookean",
                              bfemp::ElasticModuli::from_young_poisson(1e5,
                                                                       0.3));
  const double h      = 0.025;
  double       energy = 0., com_x = 0., com_y = 0.;
  unsigned int n = 0;
  for (unsigned int i = 0; i < 32; ++i)
    for (unsigned int j = 0; j < 8; ++j, ++n)
      {
        const double x = 0.2 + (i + 0.5) * h, y = 0.2 + (j + 0.5) * h;
        Tensor<2, 2> F;
        F[0][0] = 1. + 0.1 * (x - 0.2);
        F[1][0] = 0.02 * numbers::PI * std::cos(numbers::PI * x) * y;
        F[1][1] = 1. + 0.02 * std::sin(numbers::PI * x);
        energy += h * h * material->energy_density(F);
        com_x += x + 0.05 * (x - 0.2) * (x - 0.2);
        com_y += y + 0.02 * std::sin(numbers::PI * x) * y;
      }
  com_x /= n;
  com_y /= n;

  const auto   c            = run("bent", "0.05*(x - 0.2)^2, 0.02*sin(pi*x)*y");
  const double energy_error = std::abs(c[0][0] - energy) / energy;
  const double com_error =
    std::max(std::abs(c[1][0] - com_x), std::abs(c[2][0] - com_y));
  deallog << "bent: elastic energy at t = 0 " << format("%.6e", c[0][0])
          << " J, analytic " << format("%.6e", energy) << " J" << std::endl;
  std::cout << "relative energy error " << energy_error
            << ", centre-of-mass error " << com_error << " m" << std::endl;
  bfemp_tests::check(energy_error < 1e-9,
                     "bent: the elastic energy at t = 0 is sum V psi(I + grad "
                     "u) to 1e-9");
  bfemp_tests::check(com_error < 1e-12,
                     "bent: the particles start at X + u(X) (centre of mass "
                     "to 1e-12 m)");

  const auto t = run("translated", "0.1, 0");
  deallog << "translated: elastic energy at t = 0 " << format("%.1e", t[0][0])
          << " J, centre of mass x " << format("%.6f", t[1][0]) << std::endl;
  bfemp_tests::check(t[0][0] == 0. && std::abs(t[1][0] - 0.7) < 1e-12,
                     "translated: a constant displacement moves the body "
                     "rigidly (no elastic energy, centre of mass 0.6 + 0.1)");
}
