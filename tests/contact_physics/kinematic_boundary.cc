// An FEM body whose nodes are all prescribed is a separable, frictional,
// kinematic boundary for MPM (BFEMP Section 4.4): no unknowns, only
// positions that follow the prescribed motion.
//
// A rigid FEM plate 0.6 x 0.03 starts 0.02 above an MPM block 0.4 x 0.2
// (E = 1e5 Pa, nu = 0.3, rho = 1000, dx = 0.025) that rests under gravity on
// the sticky bottom wall of the grid. The plate follows rigid keyframes:
// down at 0.5 m/s until t = 0.06 s (pressing the block), sideways at 0.5
// m/s until 0.16 s, then up at 1 m/s. Backward Euler, dt = 2e-3 s (the plate
// moves 1 to 2 dhat per step, dhat = 1e-3), kappa = 1e5, check invariants
// on, 0.3 s; once frictionless and once with mu = 0.5 (eps_v = 1e-3 m/s).
// Checked for both:
//  - no particle ever inside the plate or at distance 0 (invariant check),
//    min_distance in (0, dhat) whenever there is contact;
//  - the plate's prescribed moves had to be cut by collision detection or
//    carry the particles along (their linear response) in some step
//    (partial_ or carried_constraint_moves > 0): the particles in its way
//    are pushed ahead, not crossed;
//  - it pressed the block (contact force up to > 1.5 m g);
//  - no adhesion: after the plate has lifted off (t > 0.2 s) no pair is
//    within dhat, and no particle rises above the block's initial top;
//  - Coulomb: the tangential contact force never exceeds mu times the
//    normal force (1e-5 relative slack: friction uses the normal forces of
//    its last update, which differ from the final ones by the friction
//    convergence tolerance; measured 1.4e-6); frictionless: it is 0
//    (round-off, 1e-9 of the normal force); with mu = 0.5 while the plate
//    slides it
//    reaches mu times the normal force within 1 % (kinetic friction), and
//    the block is dragged along (its x momentum > 1 kg m/s).

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double plate_mass = 0.6 * 0.03 * 1000.;

  std::string
  scene(const std::string &name, const double mu)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << head(2, 1, 1, name, 0.3)
        << fixed_step("implicit backward Euler", 2e-3) << solver(1e-5, true)
        << "subsection grid\n  set lower corner = 0, 0\n"
           "  set upper corner = 1, 0.5\n  set cell size = 0.025\n"
           "  set kernel = quadratic\nend\n"
           "subsection boundaries\n  set walls = y-\n"
           "  set wall condition = sticky\nend\n"
           "subsection contact\n  set activation distance = 1e-3\n"
           "  set barrier stiffness = 1e5\n"
           "  set static friction velocity = 1e-3\n"
           "  set friction coefficient = "
        << mu << "\nend\n"
        << mpm_box(0,
                   "0.3, 0.05",
                   "0.7, 0.25",
                   "0, 0",
                   material("neo-Hookean", 1e5, 0.3, 1000.))
        << "subsection fem body 0\n  subsection mesh\n"
           "    set source = rectangle\n"
           "    set lower corner = 0.2, 0.27\n"
           "    set upper corner = 0.8, 0.3\n"
           "    set target edge length = 0.03\n  end\n"
           "  subsection prescribed motion\n    set nodes = all\n"
           "    set motion = rigid\n"
           "    set keyframes = 0: 0, -0.5, 0; 0.06: 0.5, 0, 0; "
           "0.16: 0, 1, 0\n  end\nend\n";
    return prm.str();
  }

  void
  check(const double mu)
  {
    const std::string name = "kinematic_plate_mu_" + rounded(mu);
    write(name + ".prm", scene(name, mu));
    const Outcome<2> outcome = run<2>(name + ".prm");
    deallog << name << " finished: "
            << (outcome.error.empty() ? "yes" : "NO: " + outcome.error)
            << std::endl;
    const auto   c          = columns(name,
                           {"time",
                                       "contact_pairs",
                                       "min_distance",
                                       "partial_constraint_moves",
                                       "contact_force_m0_f0_x",
                                       "contact_force_m0_f0_y",
                                       "momentum_x",
                                       "mass",
                                       "carried_constraint_moves"});
    const double block_mass = c[7][0] - plate_mass;
    const double weight     = block_mass * 9.81;
    bool         distances = true, late_contact = false;
    double       moves = 0., pressing = 0., dragged = 0.;
    double       ratio = 0., kinetic_ratio = 1e300;
    for (unsigned int i = 0; i < c[0].size(); ++i)
      {
        if (c[1][i] > 0.)
          distances = distances && c[2][i] > 0. && c[2][i] < 1e-3;
        if (c[0][i] > 0.2 + 1e-9)
          late_contact = late_contact || c[1][i] > 0.;
        moves += c[3][i] + c[8][i];
        // The block pushes the plate up (+y).
        const double normal = c[5][i], tangential = std::abs(c[4][i]);
        pressing = std::max(pressing, normal);
        if (normal > 0.)
          {
            ratio = std::max(ratio, tangential / normal);
            // Sliding phase: the plate moves sideways (0.07 .. 0.15 s).
            if (c[0][i] > 0.07 && c[0][i] < 0.15 && mu > 0.)
              kinetic_ratio =
                std::min(kinetic_ratio, tangential / (mu * normal));
          }
        // The plate's own x momentum (0.5 m/s in the sliding phase).
        const double plate_vx =
          (c[0][i] > 0.06 + 1e-9 && c[0][i] <= 0.16 + 1e-9) ? 0.5 : 0.;
        dragged = std::max(dragged, c[6][i] - plate_mass * plate_vx);
      }
    deallog << "  distances in (0, dhat) in contact: "
            << (distances ? "yes" : "no")
            << ", prescribed moves cut by CCD or carrying particles: "
            << (moves > 0. ? "yes" : "no") << ", pressed (> 1.5 m g): "
            << (pressing > 1.5 * weight
                  ? "yes"
                  : "NO (" + rounded(pressing / weight) + " m g)")
            << std::endl;
    double highest = 0.;
    for (const auto &[id, x] : outcome.particles)
      highest = std::max(highest, x[1]);
    deallog << "  no adhesion: no pair after lift-off: "
            << (late_contact ? "NO" : "yes")
            << ", no particle above the initial top: "
            << (highest < 0.25 ? "yes" : "NO (" + rounded(highest, 6) + ")")
            << std::endl;
    if (mu == 0.)
      deallog << "  frictionless: tangential force / normal < 1e-9: "
              << (ratio < 1e-9 ? "yes" : "NO (" + rounded(ratio) + ")")
              << std::endl;
    else
      deallog << "  Coulomb |F_t| <= mu F_n: "
              << (ratio <= mu * (1. + 1e-5) ? "yes"
                                            : "NO (" + rounded(ratio) + ")")
              << ", kinetic |F_t| = mu F_n within 1 % while sliding: "
              << (kinetic_ratio > 0.99 ? "yes"
                                       : "NO (" + rounded(kinetic_ratio) + ")")
              << ", block dragged: " << (dragged > 1. ? "yes" : "no")
              << std::endl;
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();
  check(0.);
  check(0.5);
}
