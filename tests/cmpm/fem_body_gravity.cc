// An FEM cantilever next to a cMPM block, both released from rest under
// gravity, apart (2D, backward Euler, 5 steps of 0.01 s). cMPM's coarse
// nodes keep only 1e-8 of their lumped mass (the consistent inertia over
// the particles carries theirs), and the FEM nodes must keep all of theirs:
// a first version scaled every node's, and the cantilever then had neither
// weight nor inertia and did not move. The cantilever does not see the
// MPM body, so its motion must be the same with cMPM and with the B-spline
// grid, and it must fall; the block falls at g t.

#include <cmath>
#include <fstream>
#include <string>

#include "diagnostics_csv.h"
#include "format.h"
#include "run_scene.h"
#include "tests.h"

using namespace dealii;
using bfemp_tests::format;

namespace
{
  /** time, block and cantilever centre-of-mass velocity and height at the
   *  end, with cMPM on or off */
  std::vector<double>
  run(const bool cmpm)
  {
    const std::string name = cmpm ? "with_cmpm" : "with_grid";
    {
      std::ofstream prm(name + ".prm");
      prm << "set dimension = 2\n"
             "set number of bodies = 1\nset number of FEM bodies = 1\n"
             "subsection run\n  set name = "
          << name
          << "\n  set end time = 0.05\n  set quiet = true\nend\n"
             "subsection grid\n  set lower corner = 0, 0\n"
             "  set upper corner = 2, 1\n  set cell size = 0.125\n"
             "  set kernel = quadratic\nend\n"
             "subsection cmpm\n  set enabled = "
          << (cmpm ? "true" : "false")
          << "\n  set fine nodes per direction = 5\nend\n"
             "subsection time\n  set integrator = implicit backward Euler\n"
             "  set time step mode = fixed\n  set time step = 0.01\nend\n"
             "subsection transfer\n  set scheme = PIC\nend\n"
             "subsection boundaries\n  set walls = none\nend\n"
             "subsection solver\n  set Newton tolerance = 1e-7\nend\n"
             "subsection output\n  set directory = results\n"
             "  set interval = 0.05\nend\n"
             "subsection body 0\n  set particles per cell = 6\n"
             "  subsection primitive 0\n    set type = box\n"
             "    set lower corner = 0.25, 0.5\n"
             "    set upper corner = 0.75, 0.75\n  end\n"
             "  subsection material\n    set Young's modulus = 1e6\n"
             "    set density = 1000\n  end\nend\n"
             "subsection fem body 0\n  subsection mesh\n"
             "    set source = rectangle\n"
             "    set lower corner = 1, 0.5\n"
             "    set upper corner = 1.9, 0.56\n"
             "    set target edge length = 0.02\n  end\n"
             "  subsection material\n    set Young's modulus = 1e7\n"
             "    set density = 1000\n  end\n"
             "  subsection prescribed motion\n    set nodes = box\n"
             "    set box lower corner = 1, 0.5\n"
             "    set box upper corner = 1.05, 0.56\n"
             "    set motion = fixed\n  end\nend\n";
    }
    bfemp_tests::run_scene<2>(name + ".prm");
    const auto c = bfemp_tests::read_columns(
      "results/" + name + "/bodies.csv",
      {"time", "mpm0_com_velocity_y", "fem0_com_velocity_y", "fem0_com_y"});
    const std::size_t last = c[0].size() - 1;
    return {c[0][last], c[1][last], c[2][last], c[3][last] - c[3][0]};
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  const std::vector<double> on = run(true), off = run(false);
  const double              expected = -9.81 * on[0];
  deallog << "t = " << format("%.3f", on[0]) << " s: cMPM block velocity "
          << format("%.6f", on[1]) << " m/s (g t = " << format("%.6f", expected)
          << ")" << std::endl;
  deallog << "cantilever centre of mass: velocity " << format("%.5f", on[2])
          << " m/s, drop " << format("%.6f", -on[3]) << " m with cMPM; "
          << format("%.5f", off[2]) << " m/s, " << format("%.6f", -off[3])
          << " m with the B-spline grid" << std::endl;
  std::cout << "block error " << on[1] - expected << ", cantilever "
            << on[2] - off[2] << " m/s, " << on[3] - off[3] << " m"
            << std::endl;
  bfemp_tests::check(std::abs(on[1] - expected) < 1e-5,
                     "the cMPM block falls at g t");
  bfemp_tests::check(off[2] < -0.05 &&
                       std::abs(on[2] - off[2]) < 1e-4 * std::abs(off[2]) &&
                       std::abs(on[3] - off[3]) < 1e-4 * std::abs(off[3]),
                     "the cantilever falls, and the same with cMPM as with "
                     "the B-spline grid (its nodes keep their mass)");
}
