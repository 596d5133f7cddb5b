// 'body N/initial velocity' as muParser expressions of the rest position: a
// disk of radius 0.2 about (0.5, 0.5) spinning rigidly at omega = 2 rad/s,
// v = (-2 (y - 0.5), 2 (x - 0.5)). At t = 0 its kinetic energy must be
// I omega^2 / 2 with I = M R^2 / 2 (within the sampling error of I, 1 %) and
// its centre-of-mass velocity zero (the sampling is symmetric about the
// centre); the constant form of the entry is unchanged
// (a second body moving at (1, 0) as numbers).

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "diagnostics_csv.h"
#include "run_scene.h"
#include "tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  for (const bool with_constant_body : {false, true})
    {
      const std::string name =
        with_constant_body ? "spin_and_translation" : "spin";
      {
        std::ofstream prm(name + ".prm");
        prm << "set dimension = 2\nset number of bodies = "
            << (with_constant_body ? 2 : 1)
            << "\n"
               "subsection run\n  set name = "
            << name
            << "\n  set end time = 1e-5\n  set quiet = true\nend\n"
               "subsection grid\n  set upper corner = 2, 1\n"
               "  set cell size = 0.02\nend\n"
               "subsection time\n  set time step mode = fixed\n"
               "  set time step = 1e-5\nend\n"
               "subsection gravity\n  set acceleration = 0, 0\nend\n"
               "subsection output\n  set directory = results\nend\n"
               "subsection body 0\n"
               "  set initial velocity = -2*(y - 0.5), 2*(x - 0.5)\n"
               "  subsection primitive 0\n    set type = disk\n"
               "    set center = 0.5, 0.5\n    set outer radius = 0.2\n"
               "  end\n"
               "  subsection material\n    set density = 1000\n  end\n"
               "end\n";
        if (with_constant_body)
          prm << "subsection body 1\n"
                 "  set initial velocity = 1, 0\n"
                 "  subsection primitive 0\n    set type = box\n"
                 "    set lower corner = 1.3, 0.4\n"
                 "    set upper corner = 1.5, 0.6\n"
                 "  end\n"
                 "  subsection material\n    set density = 1000\n  end\n"
                 "end\n";
      }
      bfemp_tests::run_scene<2>(name + ".prm");
      const auto c =
        bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                  {"mpm0_mass",
                                   "mpm0_kinetic_energy",
                                   "mpm0_com_velocity_x",
                                   "mpm0_com_velocity_y"});
      const double M = c[0][0], omega = 2., R = 0.2;
      const double I = 0.5 * M * R * R;
      const double energy_error =
        std::abs(c[1][0] - 0.5 * I * omega * omega) / (0.5 * I * omega * omega);
      deallog << name
              << ": E_kin / (I omega^2 / 2) - 1 = " << std::setprecision(2)
              << energy_error << std::setprecision(8) << std::endl;
      bfemp_tests::check(energy_error < 0.01,
                         name + ": kinetic energy of the spinning disk "
                                "within 1 %");
      bfemp_tests::check(std::abs(c[2][0]) < 1e-12 && std::abs(c[3][0]) < 1e-12,
                         name + ": no linear momentum");
      if (with_constant_body)
        {
          const auto v =
            bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                      {"mpm1_com_velocity_x",
                                       "mpm1_com_velocity_y"});
          bfemp_tests::check(v[0][0] == 1. && v[1][0] == 0.,
                             name + ": the constant velocity of body 1");
        }
    }
}
