// A particle exactly dhat away from an FEM boundary at t = 0 is a valid
// start (b(dhat) = 0, eq. 27), unlike a particle inside the mesh (refused
// at input, tests/input/contact_overlap.prm).
//
// An MPM block (one particle per cell, dx = 1/16, so its lowest particles
// sit at y = 0.53125) above a kinematic FEM plate whose top is at 0.53125 -
// dhat, dhat = 1/1024 (all binary-exact, so the distance at t = 0 is dhat
// to the last bit). Gravity pulls the block down with backward Euler, dt =
// 1e-2, for 1 s (it settles by then), check invariants on. The set-up is
// confirmed first (the lowest particle is dhat above the plate to the last
// bit). Checked on what bfemp measured: the scene is accepted and the run
// finishes, no pair is active at t = 0, contact starts later with every
// recorded distance in (0, dhat) (the range goes to the output), and at
// the end the plate carries the block's weight (contact force = m g within
// 1 %, the ratio to the output).

#include "../format.h"
#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

int
main()
{
  bfemp_tests::initlog();
  const double       dhat = 1. / 1024.;
  const double       top  = 0.53125 - dhat;
  std::ostringstream prm;
  prm << std::setprecision(17) << head(2, 1, 1, "start_at_dhat", 1.)
      << fixed_step("implicit backward Euler", 1e-2) << solver(1e-7, true)
      << "subsection grid\n  set lower corner = 0, 0\n"
         "  set upper corner = 1, 1\n  set cell size = 0.0625\n"
         "  set kernel = quadratic\nend\n"
         "subsection boundaries\n  set walls = none\nend\n"
         "subsection contact\n  set activation distance = "
      << dhat << "\n  set barrier stiffness = 1e5\nend\n"
      << mpm_box(0,
                 "0.25, 0.5",
                 "0.75, 0.75",
                 "0, 0",
                 material("neo-Hookean", 1e5, 0.3, 1000.),
                 1)
      << "subsection fem body 0\n  subsection mesh\n"
         "    set source = rectangle\n"
         "    set lower corner = 0.125, 0.40625\n"
         "    set upper corner = 0.875, "
      << top << "\n    set target edge length = 0.125\n  end\n"
      << material("neo-Hookean", 1e6, 0.3, 1000.)
      << "  subsection prescribed motion\n    set nodes = all\n"
         "    set motion = fixed\n  end\nend\n";
  write("start_at_dhat.prm", prm.str());

  double           start_distance = 0.;
  const Outcome<2> outcome =
    run<2>("start_at_dhat.prm", [&](bfemp::Simulation<2> &simulation) {
      double lowest = 1.;
      for (const auto &particle : simulation.particles().handler())
        lowest = std::min(lowest, particle.get_location()[1]);
      start_distance = lowest - top;
    });
  deallog << "accepted and finished: "
          << (outcome.error.empty() ? "yes" : "NO: " + outcome.error)
          << std::endl;
  // the set-up, not bfemp: the scene must pose the case it claims to
  deallog << "set-up: the lowest particle starts dhat above the plate to "
             "the last bit: "
          << (start_distance == dhat ? "yes" : "NO") << std::endl;

  // what bfemp measured: the contact pairs and distances of every step
  const auto c =
    columns("start_at_dhat",
            {"contact_pairs", "min_distance", "contact_force_m0_f0_y", "mass"});
  unsigned int first_contact_step = 0, max_pairs = 0;
  double       smallest = dhat, largest = 0.;
  for (unsigned int i = 0; i < c[0].size(); ++i)
    if (c[0][i] > 0.)
      {
        if (first_contact_step == 0)
          first_contact_step = i;
        max_pairs = std::max(max_pairs, static_cast<unsigned int>(c[0][i]));
        smallest  = std::min(smallest, c[1][i]);
        largest   = std::max(largest, c[1][i]);
      }
  deallog << "no contact pair at t = 0 (b(dhat) = 0): "
          << (c[0][0] == 0. ? "yes" : "NO") << "; first contact at step "
          << first_contact_step << ", at most " << max_pairs
          << " pairs; distance / dhat over the run in ["
          << bfemp_tests::format("%.4f", smallest / dhat) << ", "
          << bfemp_tests::format("%.4f", largest / dhat) << "]" << std::endl;
  bfemp_tests::check(c[0][0] == 0. && first_contact_step > 0 && smallest > 0. &&
                       largest < dhat,
                     "contact starts after t = 0 and every distance stays in "
                     "(0, dhat)");
  const double block_mass = 0.5 * 0.25 * 1000.;
  const double weight     = block_mass * 9.81;
  const double carried    = -c[2].back() / weight;
  deallog << "plate force / block weight at the end: "
          << bfemp_tests::format("%.4f", carried) << std::endl;
  bfemp_tests::check(std::abs(carried - 1.) < 0.01,
                     "the plate carries the block's weight to 1 %");
}
