// Extreme compression with implicit backward Euler: the filtered line
// search (BFEMP Section 5: every trial step stays below the first root of
// det F) must never accept an iterate with det F <= 0. Every scene runs with
// 'solver/check invariants = true', which stops the run with a
// SimulationError naming the "invariant check" if an accepted Newton
// iterate has det F <= 0 anywhere. Either outcome below is allowed:
//  (a) the run completes, and min det F > 0 in every diagnostics row;
//  (b) it stops early with a SimulationError that is not the invariant
//      check and names its step (e.g. the prescribed positions of a step
//      cannot be reached without inversion, or Newton does not converge),
//      and every row written before has min det F > 0.
// No gravity, neo-Hookean E = 1e5 Pa, nu = 0.3, rho = 1000, end time 1 s.
//
// FEM: a square block [0.4, 0.6] x [0.1, 0.3] (a 10 x 10 x 2 triangle mesh
// written here as a gmsh file whose bottom and top edges carry boundary id
// 1); those nodes are prescribed by the expression u = (0, -s t (y - 0.1) /
// 0.2): the bottom stays, the top moves down by s t, s = 0.19 m/s, to 95 %
// compression at t = 1 s. Two runs:
//  - dt = 0.05 s: each step moves the top by half the initial element
//    height. Newton moves the prescribed nodes towards their targets only
//    as far as the det F bound allows (NewtonSolver::move_constraints),
//    carrying the free nodes along with their linear response, so no
//    iterate inverts.
//  - dt = 0.01 s.
// With the default 'solver/Hessian projection = when indefinite' both
// complete (outcome a) down to min det F ~0.04 and ~0.03, at most 42 and 49
// Newton iterations per step. With projected Newton only ('always') they
// stopped on the iteration limit (outcome b) at t = 0.7 (min det F ~0.25:
// the top row thinner than a step) and t = 0.68 (min det F ~0.23: the
// clamped tangent loses much of the curvature of the compressed elements
// and Newton converged too slowly).
//
// MPM: a block [0.4, 0.6] x [0.1, 0.3] (dx = 0.05, 64 particles, dt = 0.05
// s) on the sticky bottom wall of the grid (nodes y <= 0.1), crushed by a
// sticky level-set box (lower edge at y = 0.35, x in [0.2, 0.8]) moving
// down at 0.24 m/s, until no row of free nodes is left between the two
// (outcome a, min det F ~0.22).
//
// Printed: how each run ended and min det F over its rows; checked also
// that the compression is real (min det F < 0.6, < 0.3 and < 0.3).

#include "implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double end_time = 1.;

  /** A structured triangle mesh of [x0, x0 + L] x [y0, y0 + L], n x n
   *  squares each cut into two triangles, in gmsh format 2.2; the bottom
   *  and top edges are lines of physical tag 1 (boundary id 1). */
  void
  write_block_mesh(const std::string &file,
                   const double       x0,
                   const double       y0,
                   const double       L,
                   const unsigned int n)
  {
    std::ofstream out(file);
    out << std::setprecision(17) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
        << "$Nodes\n"
        << (n + 1) * (n + 1) << '\n';
    const auto id = [n](const unsigned int i, const unsigned int j) {
      return j * (n + 1) + i + 1;
    };
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        out << id(i, j) << ' ' << x0 + L * i / n << ' ' << y0 + L * j / n
            << " 0\n";
    out << "$EndNodes\n$Elements\n" << 2 * n + 2 * n * n << '\n';
    unsigned int element = 1;
    for (unsigned int i = 0; i < n; ++i)
      {
        out << element++ << " 1 2 1 1 " << id(i, 0) << ' ' << id(i + 1, 0)
            << '\n';
        out << element++ << " 1 2 1 2 " << id(i + 1, n) << ' ' << id(i, n)
            << '\n';
      }
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          // Counter-clockwise triangles.
          out << element++ << " 2 2 5 5 " << id(i, j) << ' ' << id(i + 1, j)
              << ' ' << id(i + 1, j + 1) << '\n';
          out << element++ << " 2 2 5 5 " << id(i, j) << ' ' << id(i + 1, j + 1)
              << ' ' << id(i, j + 1) << '\n';
        }
    out << "$EndElements\n";
  }

  std::string
  fem_scene(const std::string &name, const double dt)
  {
    return head(2, 0, 1, name, end_time) +
           fixed_step("implicit backward Euler", dt) + solver(1e-6, true) +
           "subsection gravity\n  set acceleration = 0, 0\nend\n"
           "subsection boundaries\n  set walls = none\nend\n"
           "subsection fem body 0\n" +
           material("neo-Hookean", 1e5, 0.3, 1000.) +
           "  subsection mesh\n    set source = file\n"
           "    set file = block.msh\n  end\n"
           "  subsection prescribed motion\n    set nodes = boundary id\n"
           "    set boundary id = 1\n    set motion = expression\n"
           "    set constants = s=0.19\n"
           "    set displacement = 0, -s*t*(y - 0.1)/0.2\n  end\nend\n";
  }

  std::string
  mpm_scene()
  {
    return head(2, 1, 0, "mpm_block", end_time) +
           fixed_step("implicit backward Euler", 0.05) + solver(1e-6, true) +
           "subsection grid\n  set lower corner = 0, 0\n"
           "  set upper corner = 1, 0.6\n  set cell size = 0.05\n"
           "  set kernel = quadratic\nend\n"
           "subsection gravity\n  set acceleration = 0, 0\nend\n"
           "subsection boundaries\n  set walls = y-\n"
           "  set wall condition = sticky\n  set number of level sets = 1\n"
           "  subsection level set 0\n    set type = box\n"
           "    set condition = sticky\n    set lower corner = 0.2, 0.35\n"
           "    set upper corner = 0.8, 1\n    set velocity = 0, -0.24\n"
           "  end\nend\n" +
           mpm_box(0,
                   "0.4, 0.1",
                   "0.6, 0.3",
                   "0, 0",
                   material("neo-Hookean", 1e5, 0.3, 1000.));
  }

  /** Runs a scene, prints how it ended and min det F; returns min det F. */
  double
  crush(const std::string &name, const std::string &prm)
  {
    write(name + ".prm", prm);
    const Outcome<2> outcome = run<2>(name + ".prm");
    const auto       c       = columns(name, {"time", "min_J"});
    bfemp_tests::check(finite(c), name + ": every diagnostics row is finite");
    const double min_J = min_of(c[1]);
    if (outcome.error.empty())
      deallog << name << ": completed " << c[0].size() - 1 << " steps";
    else
      deallog << name << ": stopped with a SimulationError after t = "
              << rounded(c[0].back(), 3) << " (" << c[0].size() - 1
              << " steps)";
    deallog << ", min det F over the run " << rounded(min_J, 2) << std::endl;
    // The message up to its numbers in parentheses.
    if (!outcome.error.empty())
      deallog << "  message: "
              << outcome.error.substr(0, outcome.error.find(" (")) << std::endl;
    bfemp_tests::check(outcome.error.find("invariant check") ==
                         std::string::npos,
                       name + ": no accepted Newton iterate had det F <= 0");
    bfemp_tests::check(outcome.error.empty() ||
                         outcome.error.find("step ") == 0,
                       name + ": a failure is a SimulationError naming its "
                              "step");
    bfemp_tests::check(min_J > 0., name + ": min det F > 0 in every row");
    if (outcome.error.empty())
      bfemp_tests::check(std::abs(c[0].back() - end_time) < 1e-12,
                         name + ": reached the end time");
    return min_J;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  write_block_mesh("block.msh", 0.4, 0.1, 0.2, 10);
  const double fem_coarse =
    crush("fem_block_large_steps", fem_scene("fem_block_large_steps", 0.05));
  bfemp_tests::check(fem_coarse < 0.6,
                     "the FEM block was compressed (det F < 0.6)");
  const double fem_fine =
    crush("fem_block_small_steps", fem_scene("fem_block_small_steps", 0.01));
  bfemp_tests::check(fem_fine < 0.3, "the FEM block was crushed (det F < 0.3)");
  const double mpm_J = crush("mpm_block", mpm_scene());
  bfemp_tests::check(mpm_J < 0.3, "the MPM block was crushed (det F < 0.3)");
}
