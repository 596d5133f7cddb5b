// An MPM block thrown at 50 m/s onto a thin FEM plate with a large time
// step (BFEMP Sections 4-5: barrier contact, CCD-filtered line search).
//
// 2D, no gravity, backward Euler, Newton tolerance eps_d = 1e-6 m/s,
// 'solver/check invariants = true' (every accepted Newton iterate has
// det F > 0 and no particle inside an FEM element or at distance 0 from
// its boundary), dhat = 1e-3 m, kappa = 1e6 Pa, no friction.
//  - block: MPM box 0.1 x 0.05 (200 particles, dx = 0.01, quadratic
//    B-splines, APIC), neo-Hookean E = 1e7 Pa, nu = 0.3, rho = 1000,
//    starting 0.05 m above the plate at v = (0, -50) m/s;
//  - plate: FEM rectangle 0.6 x 0.02 (edge 0.01: 2 elements through the
//    thickness, 240 triangles), neo-Hookean E = 1e8 Pa, nu = 0.3,
//    rho = 1000, top face at y = 0;
//  - dt = 2e-3 s: the block moves 0.1 m per step, 5 plate thicknesses or
//    100 dhat, so an unfiltered Newton step would carry it through the
//    plate (73 times the explicit step of the plate, dx / c_p).
// Three scenes, 15 steps to t = 0.03 s each:
//  - free: nothing else, the plate is free. Translation invariance of the
//    elastic and barrier terms makes the change of the total momentum over
//    a time step (1 - alpha) sum_i m_i p_i / dt for the last Newton
//    direction p taken with line search step alpha (0 after a full step),
//    so |p(t) - p(0)| <= n_steps M eps_d (per component, M = 17 kg/m the total
//    mass): checked at every row; measured round-off (< 1e-12 |p(0)|: the
//    last Newton step of every time step was a full one, alpha = 1).
//    Backward Euler gives the plate the momentum change dt F(x^{n+1}) per
//    step, F the contact force on it (diagnostics contact_force_m0_f0,
//    barrier only here): checked sum_k dt F_k = P_plate(end) to the same
//    n_steps M eps_d (not a strict bound here: the difference is the
//    plate's share of the final Newton gradients; measured 1e-8 relative,
//    2e-6 N s). The block ends moving down slower than the plate's centre
//    of mass (-9.6 vs -17 m/s): it bounced off the plate, which got 202 of
//    the 250 N s.
//  - held: the end nodes of the plate (rest |x| >= 0.25) sit inside two
//    sticky level-set boxes, which hold FEM nodes like grid nodes: checked
//    that they did not move, and that the block bounced (its mean vertical
//    velocity at the end is > 0, measured +9.4 m/s; E_end / E_0 = 0.04).
//  - rigid: every node of the plate prescribed (fixed): a kinematic
//    obstacle without unknowns, with dt = 1e-2 s (0.5 m per step, 25
//    plate thicknesses; 5 steps to 0.05 s): backward Euler stops the block
//    (|v_y| < 1 m/s at the end, measured 0.025 m/s).
// In every scene: the run finishes; every diagnostics row after the
// initial one has min_distance > 0 (row 0 carries no contact measurement;
// the printed minimum over the rows is 0.98 .. 0.99 dhat: the barrier holds
// the block just inside dhat); contact happened (contact_pairs > 0 in
// some row) and a CCD bound limited a Newton step (ccd_bound_hits > 0 in
// some row); the block is out of contact at the end; every particle lies
// above the plate's deformed top surface
// (boundary id 3 of the rectangle; its facet under the particle's x); the
// total energy (kinetic + elastic + barrier) never exceeds its initial
// value (1e-9 relative: backward Euler dissipates; E_end / E_0 = 0.34 for
// the free plate). Run time about 1.5 s in Release on 2 cores.

#include <bfemp/particles/particle_layout.h>

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  constexpr double speed        = 50.;
  constexpr double eps_d        = 1e-6;
  constexpr double dhat         = 1e-3;
  constexpr double kappa        = 1e6;
  constexpr double thickness    = 0.02;
  constexpr double half_length  = 0.3;
  constexpr double held_from    = 0.25;
  constexpr double block_youngs = 1e7;
  constexpr double plate_youngs = 1e8;
  constexpr double density      = 1000.;
  /** Boundary id of the top face of a 'rectangle' mesh (2 d + 1, d = y). */
  constexpr types::boundary_id top_face = 3;

  enum class Plate
  {
    free,
    held,
    rigid
  };

  std::string
  scene(const std::string &name,
        const Plate        plate,
        const double       dt,
        const double       end_time)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << head(2, 1, 1, name, end_time)
        << fixed_step("implicit backward Euler", dt) << solver(eps_d, true)
        << "subsection grid\n  set lower corner = -0.4, -0.8\n"
           "  set upper corner = 0.4, 0.3\n  set cell size = 0.01\n"
           "  set kernel = quadratic\nend\n"
           "subsection transfer\n  set scheme = APIC\nend\n"
           "subsection gravity\n  set acceleration = 0, 0\nend\n"
           "subsection contact\n  set activation distance = "
        << dhat << "\n  set barrier stiffness = " << kappa
        << "\n  set friction coefficient = 0\nend\n"
        << "subsection boundaries\n  set walls = none\n";
    if (plate == Plate::held)
      {
        // Boxes around the plate's ends, away from the block; their inner
        // faces at |x| = held_from - 0.005, between two node columns.
        prm << "  set number of level sets = 2\n";
        for (unsigned int i = 0; i < 2; ++i)
          prm << "  subsection level set " << i
              << "\n    set type = box\n    set condition = sticky\n"
                 "    set lower corner = "
              << (i == 0 ? -0.4 : held_from - 0.005) << ", -0.05\n"
              << "    set upper corner = "
              << (i == 0 ? -held_from + 0.005 : 0.4) << ", 0.03\n  end\n";
      }
    prm << "end\n"
        << mpm_box(0,
                   "-0.05, 0.05",
                   "0.05, 0.1",
                   "0, " + std::to_string(-speed),
                   material("neo-Hookean", block_youngs, 0.3, density))
        << "subsection fem body 0\n"
        << material("neo-Hookean", plate_youngs, 0.3, density)
        << "  subsection mesh\n    set source = rectangle\n"
           "    set lower corner = "
        << -half_length << ", " << -thickness
        << "\n    set upper corner = " << half_length
        << ", 0\n    set target edge length = 0.01\n  end\n";
    if (plate == Plate::rigid)
      prm << "  subsection prescribed motion\n    set nodes = all\n"
             "    set motion = fixed\n  end\n";
    prm << "end\n";
    return prm.str();
  }

  /** The state a run left behind. */
  struct End
  {
    std::string           error;
    double                block_mass = 0.;
    Tensor<1, 2>          block_momentum;
    std::vector<Point<2>> particles;
    /** The plate: nodes now and at rest, masses, velocities, top facets. */
    std::vector<Point<2>>                    nodes, rest;
    std::vector<double>                      masses;
    std::vector<Tensor<1, 2>>                velocities;
    std::vector<std::array<unsigned int, 2>> top_facets;
  };

  End
  simulate(const std::string &file)
  {
    using Layout = bfemp::ParticleLayout<2>;
    End end;
    end.error =
      implicit_scene::run<2>(file, {}, [&](bfemp::Simulation<2> &simulation) {
        for (const auto &particle : simulation.particles().handler())
          {
            const auto properties = particle.get_properties();
            end.particles.push_back(particle.get_location());
            end.block_mass += properties[Layout::mass];
            end.block_momentum +=
              properties[Layout::mass] *
              Layout::get_vector(properties, Layout::velocity);
          }
        const auto &plate  = *simulation.fem_bodies()[0];
        end.nodes          = plate.positions();
        end.rest           = plate.mesh().rest_positions();
        end.masses         = plate.masses();
        end.velocities     = plate.velocities();
        const auto &facets = plate.mesh().boundary_facets();
        const auto &ids    = plate.mesh().boundary_facet_ids();
        for (unsigned int f = 0; f < facets.size(); ++f)
          if (ids[f] == top_face)
            end.top_facets.push_back({{facets[f][0], facets[f][1]}});
      }).error;
    return end;
  }

  /**
   * Whether every particle lies strictly above the plate's top surface: a
   * top facet spans its x and the particle is on the facet's outer side
   * (boundary facets run with the body on their left).
   */
  bool
  above_top_surface(const End &end)
  {
    for (const Point<2> &x : end.particles)
      {
        bool covered = false, above = true;
        for (const auto &facet : end.top_facets)
          {
            const Point<2> &a = end.nodes[facet[0]], &b = end.nodes[facet[1]];
            if (x[0] < std::min(a[0], b[0]) || x[0] > std::max(a[0], b[0]))
              continue;
            covered                 = true;
            const Tensor<1, 2> edge = b - a, r = x - a;
            above = above && (edge[0] * r[1] - edge[1] * r[0] < 0.);
          }
        if (!covered || !above)
          return false;
      }
    return true;
  }

  void
  check_scene(const Plate plate, const double dt, const double end_time)
  {
    const std::string name   = plate == Plate::free   ? "free"
                               : plate == Plate::held ? "held"
                                                      : "rigid";
    const std::string prefix = name + " plate: ";
    write(name + ".prm", scene(name, plate, dt, end_time));
    const End end = simulate(name + ".prm");
    deallog << name << " plate, dt = " << rounded(dt) << " s ("
            << rounded(speed * dt / thickness) << " plate thicknesses per step)"
            << std::endl;
    if (!end.error.empty())
      deallog << "error: " << end.error << std::endl;
    bfemp_tests::check(end.error.empty(),
                       prefix + "the run reached the end time");

    const auto        c = columns(name,
                           {"time",
                                   "total_energy",
                                   "momentum_x",
                                   "momentum_y",
                                   "mass",
                                   "min_J",
                                   "contact_pairs",
                                   "min_distance",
                                   "barrier_energy",
                                   "ccd_bound_hits",
                                   "contact_force_m0_f0_x",
                                   "contact_force_m0_f0_y"});
    const std::size_t n = c[0].size();
    bfemp_tests::check(n ==
                         static_cast<std::size_t>(std::round(end_time / dt)) +
                           1,
                       prefix + "one diagnostics row per step");
    bfemp_tests::check(min_of(c[5]) > 0.,
                       prefix + "min det F > 0 in every row");

    // Row 0 is written before any step and carries no contact measurement.
    double       min_distance  = std::numeric_limits<double>::infinity();
    unsigned int first_contact = 0;
    double       ccd_hits = 0., max_energy = 0.;
    for (std::size_t k = 1; k < n; ++k)
      {
        min_distance = std::min(min_distance, c[7][k]);
        if (first_contact == 0 && c[6][k] > 0.)
          first_contact = k;
        ccd_hits += c[9][k];
        max_energy = std::max(max_energy, c[1][k] + c[8][k]);
      }
    const double E0    = c[1][0] + c[8][0];
    const double ratio = (c[1].back() + c[8].back()) / E0;
    deallog << "  first contact in step " << first_contact
            << ", smallest particle-plate distance "
            << rounded(min_distance / dhat, 2) << " dhat, E_end / E_0 "
            << (ratio < 1e-3 ? std::string("< 0.001") : rounded(ratio, 2))
            << std::endl;
    bfemp_tests::check(min_distance > 0.,
                       prefix + "min_distance > 0 in every row after the "
                                "initial one");
    bfemp_tests::check(first_contact > 0, prefix + "the block hit the plate");
    bfemp_tests::check(ccd_hits > 0.,
                       prefix + "a CCD bound limited a Newton step");
    bfemp_tests::check(c[6].back() == 0.,
                       prefix + "the block is out of contact at the end");
    bfemp_tests::check(above_top_surface(end),
                       prefix + "every particle lies above the plate's top "
                                "surface");
    bfemp_tests::check(max_energy <= E0 * (1. + 1e-9),
                       prefix + "kinetic + elastic + barrier energy never "
                                "exceeds its initial value");

    const double block_velocity = end.block_momentum[1] / end.block_mass;
    if (plate == Plate::free)
      {
        const double M     = c[4][0];
        const double bound = (n - 1) * M * eps_d;
        double       drift = 0.;
        for (std::size_t k = 0; k < n; ++k)
          drift = std::max(
            {drift, std::abs(c[2][k] - c[2][0]), std::abs(c[3][k] - c[3][0])});
        const double p0 = std::abs(c[3][0]);
        deallog << "  max |p - p0| / |p0| "
                << (drift < 1e-12 * p0 ? std::string("< 1e-12")
                                       : rounded(drift / p0, 1))
                << ", bound n_steps M eps_d / |p0| " << rounded(bound / p0, 2)
                << std::endl;
        bfemp_tests::check(drift <= bound,
                           prefix + "total momentum conserved to n_steps M "
                                    "eps_d");

        Tensor<1, 2> plate_momentum, impulse;
        double       plate_mass = 0.;
        for (unsigned int a = 0; a < end.nodes.size(); ++a)
          {
            plate_momentum += end.masses[a] * end.velocities[a];
            plate_mass += end.masses[a];
          }
        for (std::size_t k = 1; k < n; ++k)
          impulse +=
            (c[0][k] - c[0][k - 1]) * Tensor<1, 2>({c[10][k], c[11][k]});
        const double mismatch = (plate_momentum - impulse).norm();
        deallog << "  contact impulse on the plate " << rounded(impulse[1], 3)
                << " N s, |P_plate - impulse| / |P_plate| "
                << (mismatch < 1e-9 * plate_momentum.norm()
                      ? std::string("< 1e-9")
                      : rounded(mismatch / plate_momentum.norm(), 1))
                << std::endl;
        bfemp_tests::check(mismatch <= bound,
                           prefix + "the plate's momentum is the time "
                                    "integral of the contact force");
        const double plate_velocity = plate_momentum[1] / plate_mass;
        deallog << "  mean v_y at the end: block " << rounded(block_velocity, 2)
                << " m/s, plate " << rounded(plate_velocity, 2) << " m/s"
                << std::endl;
        bfemp_tests::check(block_velocity > plate_velocity &&
                             plate_velocity < 0.,
                           prefix + "the plate was pushed down and the block "
                                    "bounced off it");
      }
    else if (plate == Plate::held)
      {
        double       moved = 0.;
        unsigned int held  = 0;
        for (unsigned int a = 0; a < end.nodes.size(); ++a)
          if (std::abs(end.rest[a][0]) >= held_from - 1e-9)
            {
              ++held;
              moved = std::max(moved, (end.nodes[a] - end.rest[a]).norm());
            }
        deallog << "  " << held << " held nodes, block mean v_y at the end "
                << rounded(block_velocity, 2) << " m/s" << std::endl;
        bfemp_tests::check(held > 0 && moved <= 1e-12,
                           prefix + "the nodes in the sticky boxes stayed "
                                    "in place");
        bfemp_tests::check(block_velocity > 0.,
                           prefix + "the block bounced (v_y > 0)");
      }
    else
      bfemp_tests::check(std::abs(block_velocity) < 0.02 * speed,
                         prefix + "the block stopped (|v_y| < 1 m/s)");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  check_scene(Plate::free, 2e-3, 0.03);
  check_scene(Plate::held, 2e-3, 0.03);
  check_scene(Plate::rigid, 1e-2, 0.05);
}
