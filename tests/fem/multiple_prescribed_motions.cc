// Several prescribed motions on one FEM body ('number of prescribed
// motions' = 2): a bar 1 x 0.1 m (E 1e6 Pa, nu = 0, rho 1) clamped at its
// left end ('prescribed motion': nodes in the box x <= 0, fixed) and pulled
// at its right end ('prescribed motion 1': nodes in the box x >= 1,
// displacement (0.1 t, 0)), quasi-static (backward Euler, dt = 0.05 s, 1 s).
// Checked at t = 1: the left nodes are at their rest positions, the right
// nodes at X + (0.1, 0), both to 1e-12 m, and the free nodes stretch
// uniformly as a linear bar does, u_x = 0.1 X to 1 % of the end
// displacement (nu = 0: no lateral contraction).

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

int
main()
{
  bfemp_tests::initlog();
  std::ostringstream prm;
  prm << head(2, 0, 1, "two_motions", 1.)
      << fixed_step("implicit backward Euler", 0.05) << solver(1e-9, true)
      << "subsection grid\n  set lower corner = -0.5, -0.5\n"
         "  set upper corner = 1.5, 0.5\n  set cell size = 0.1\nend\n"
         "subsection gravity\n  set acceleration = 0, 0\nend\n"
         "subsection boundaries\n  set walls = none\nend\n"
         "subsection fem body 0\n"
         "  set number of prescribed motions = 2\n"
         "  subsection mesh\n    set source = rectangle\n"
         "    set lower corner = 0, 0\n    set upper corner = 1, 0.1\n"
         "    set target edge length = 0.05\n  end\n"
      << material("neo-Hookean", 1e6, 0., 1.)
      << "  subsection prescribed motion\n    set nodes = box\n"
         "    set box lower corner = -1, -1\n"
         "    set box upper corner = 0, 1\n    set motion = fixed\n  end\n"
         "  subsection prescribed motion 1\n    set nodes = box\n"
         "    set box lower corner = 1, -1\n"
         "    set box upper corner = 2, 1\n    set motion = expression\n"
         "    set displacement = 0.1*t, 0\n  end\n"
         "end\n";
  write("two_motions.prm", prm.str());
  std::vector<Point<2>> rest;
  const Outcome<2>      outcome =
    run<2>("two_motions.prm", {}, [&](bfemp::Simulation<2> &simulation) {
      const auto &mesh = simulation.fem_bodies()[0]->mesh();
      for (unsigned int a = 0; a < mesh.n_nodes(); ++a)
        rest.push_back(mesh.rest_position(a));
    });
  bfemp_tests::check(outcome.error.empty(), "the bar ran: " + outcome.error);

  double       clamp_error = 0., pull_error = 0., free_error = 0.;
  unsigned int clamped = 0, pulled = 0, free = 0;
  for (unsigned int a = 0; a < rest.size(); ++a)
    {
      const Tensor<1, 2> u = outcome.fem_positions[0][a] - rest[a];
      if (rest[a][0] <= 1e-12)
        {
          clamp_error = std::max(clamp_error, u.norm());
          ++clamped;
        }
      else if (rest[a][0] >= 1. - 1e-12)
        {
          pull_error =
            std::max(pull_error, (u - Tensor<1, 2>({0.1, 0.})).norm());
          ++pulled;
        }
      else
        {
          free_error = std::max(free_error, std::abs(u[0] - 0.1 * rest[a][0]));
          ++free;
        }
    }
  char line[200];
  std::snprintf(line,
                sizeof(line),
                "%u clamped nodes at rest, %u pulled nodes at X + (0.1, 0): "
                "largest distance",
                clamped,
                pulled);
  bfemp_tests::check(
    clamped > 0 && pulled > 0 && clamp_error < 1e-12 && pull_error < 1e-12,
    std::string(line) + " " + bfemp_tests::measured(clamp_error, 1e-12) +
      " (clamped), " + bfemp_tests::measured(pull_error, 1e-12) +
      " (pulled) m");
  std::snprintf(line,
                sizeof(line),
                "%u free nodes: u_x = 0.1 X to 1 %% of the end displacement: "
                "largest |u_x - 0.1 X| in m",
                free);
  bfemp_tests::check(free > 0 && free_error < 1e-3,
                     std::string(line) + " " +
                       bfemp_tests::measured(free_error, 1e-3));
}
