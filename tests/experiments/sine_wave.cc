// BFEMP Section 6.2, "FEM as contact boundary for MPM" (reduced): an
// elastic box on a no-slip ground is pressed by a sine-wave boundary that
// moves down, sideways and up at 1 m/s; the boundary is (a) a kinematic FEM
// body in barrier contact (BFEMP) and (b) an analytic level set on the grid
// with the slip condition. Runs
// prm/experiments/6_2_sine_wave/sine_wave_{bfemp,level_set}_reduced.prm
// (box 1 x 1 at dx = 0.05, 1600 particles; the boundary's lowest point
// starts 0.03 m above the box, goes 0.1 m down, 0.05 m left, then up;
// h = 1e-3 s, 350 steps each).
//
// The paper: with BFEMP no particle penetrates the boundary and the box
// does not stick to it when it separates; with the level set particles
// penetrate and the box is pulled up with the separating boundary.
// Checked:
//  - both runs reach t = 0.35 s with one diagnostics row per step;
//  - BFEMP: contact in each of the three phases (down t < 0.1 s, sideways
//    0.1 .. 0.15 s, up after) and none in the last row (separated);
//    particles_in_fem = 0 and min_distance > 0 in every row (measured
//    min_distance 0.89 dhat);
//  - level set: particles_in_level_sets > 0 in some row (measured up to 40
//    of 1600: the slip condition acts on grid nodes only, and the wave,
//    2 cells long here, is smeared out on the grid);
//  - adhesion, measured as the height of the boundary's lowest point above
//    the box's initial top at the last row in which some particle touches
//    it (BFEMP: contact_particles > 0, i.e. within dhat; level set: a
//    particle inside it). BFEMP: 13 mm, the box's top following the
//    boundary while it relaxes elastically (it oscillates: its centre of
//    mass rises 8.5 mm above its start); band < 30 mm. Level set: 68 mm,
//    grid nodes inside the rising level set keep its normal velocity and
//    drag the box up (centre of mass 45 mm above its start); band > 45 mm
//    and more than twice the BFEMP value. The band between 30 and 45 mm
//    separates an elastic rebound from the level set's adhesion.
// Run time about 30 s (CPU) in Release.

#include "../implicit/implicit_scene.h"

using namespace dealii;
using namespace implicit_scene;

namespace
{
  const std::string directory =
    BFEMP_SOURCE_DIR "/prm/experiments/6_2_sine_wave/";
  constexpr double end_time = 0.35;
  constexpr double dt       = 1e-3;
  // The boundary's path (the reduced prm's keyframes): down until t_side,
  // left until t_up, then up, at 1 m/s; its lowest point starts at
  // y_start, the box's top at y_box.
  constexpr double t_side  = 0.1;
  constexpr double t_up    = 0.15;
  constexpr double y_start = 1.13;
  constexpr double y_box   = 1.1;

  /** Height of the boundary's lowest point at time @p t. */
  double
  lowest_point(const double t)
  {
    return y_start - std::min(t, t_side) + std::max(0., t - t_up);
  }

  /** A prm file that includes the reduced scene and writes into results/. */
  std::string
  scene(const std::string &variant)
  {
    std::ostringstream prm;
    prm << "include " << directory << "sine_wave_" << variant
        << "_reduced.prm\n"
           "subsection run\n  set name = "
        << variant
        << "\n  set quiet = true\nend\n"
           "subsection output\n  set directory = results\n"
           "  set interval = "
        << end_time
        << "\n  set diagnostics interval = 1\n"
           "  set write particles = false\n  set write grid = false\nend\n";
    return prm.str();
  }

  /** Runs @p variant and returns its diagnostics columns @p which (time
   *  first) and the box's centre-of-mass height from bodies.csv (last). */
  std::vector<std::vector<double>>
  simulate(const std::string &variant, std::vector<std::string> which)
  {
    write(variant + ".prm", scene(variant));
    const std::string error = implicit_scene::run<2>(variant + ".prm").error;
    if (!error.empty())
      deallog << variant << ": " << error << std::endl;
    bfemp_tests::check(error.empty(), variant + ": the run reached the end");
    which.insert(which.begin(), "time");
    auto c = columns(variant, which);
    c.push_back(bfemp_tests::read_columns("results/" + variant + "/bodies.csv",
                                          {"mpm0_com_y"})[0]);
    bfemp_tests::check(c[0].size() ==
                         static_cast<std::size_t>(std::round(end_time / dt)) +
                           1,
                       variant + ": one diagnostics row per step");
    bfemp_tests::check(c.back().size() == c[0].size(),
                       variant + ": one bodies.csv row per step");
    return c;
  }

  /** How far above the box's initial top the boundary's lowest point is
   *  at the last row where @p touching (a count per row) is positive. */
  double
  separation_height(const std::vector<double> &t,
                    const std::vector<double> &touching)
  {
    double last = 0.;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (touching[k] > 0)
        last = t[k];
    return lowest_point(last) - y_box;
  }

  /** Largest rise of the centre of mass @p y above y(0) in the up phase. */
  double
  lift(const std::vector<double> &t, const std::vector<double> &y)
  {
    double rise = -std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] > t_up)
        rise = std::max(rise, y[k] - y[0]);
    return rise;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  // BFEMP: the boundary is a kinematic FEM body.
  double bfemp_separation = 0.;
  {
    const auto c =
      simulate("bfemp",
               {"contact_particles", "particles_in_fem", "min_distance"});
    const auto  &t          = c[0];
    bool         contact[3] = {false, false, false};
    unsigned int inside     = 0;
    double       d_min      = std::numeric_limits<double>::max();
    for (std::size_t k = 1; k < t.size(); ++k)
      {
        const unsigned int phase = t[k] < t_side ? 0 : t[k] < t_up ? 1 : 2;
        contact[phase]           = contact[phase] || c[1][k] > 0;
        inside = std::max(inside, static_cast<unsigned int>(c[2][k]));
        d_min  = std::min(d_min, c[3][k]);
      }
    bfemp_tests::check(contact[0] && contact[1] && contact[2],
                       "bfemp: contact while going down, sideways and up");
    bfemp_tests::check(c[1].back() == 0, "bfemp: separated at the end");
    deallog << "bfemp: max particles_in_fem " << inside
            << ", min_distance / dhat " << rounded(d_min / 1e-3, 2)
            << std::endl;
    bfemp_tests::check(inside == 0,
                       "bfemp: no particle inside the FEM boundary, any row");
    bfemp_tests::check(d_min > 0., "bfemp: min_distance > 0 in every row");
    bfemp_separation = separation_height(t, c[1]);
    deallog << "bfemp: last contact with the boundary "
            << rounded(1e3 * bfemp_separation, 2)
            << " mm above the box's initial top; lift of the centre of mass "
            << rounded(1e3 * lift(t, c[4]), 2) << " mm" << std::endl;
    bfemp_tests::check(bfemp_separation < 0.03,
                       "bfemp: no adhesion (separates < 30 mm above the top)");
  }

  // Level set: the same motion as a slip boundary on the grid.
  {
    const auto   c = simulate("level_set", {"particles_in_level_sets"});
    const auto  &t = c[0];
    const double n = implicit_scene::max_of(c[1]);
    deallog << "level set: max particles_in_level_sets "
            << static_cast<unsigned int>(n) << std::endl;
    bfemp_tests::check(n > 0, "level set: particles penetrate the boundary");
    const double separation = separation_height(t, c[1]);
    deallog << "level set: last particle inside the boundary "
            << rounded(1e3 * separation, 2)
            << " mm above the box's initial top; lift of the centre of mass "
            << rounded(1e3 * lift(t, c[2]), 2) << " mm" << std::endl;
    bfemp_tests::check(separation > 0.045,
                       "level set: adhesion (box held > 45 mm above its top)");
    bfemp_tests::check(separation > 2. * bfemp_separation,
                       "level set holds the box more than twice as high as "
                       "BFEMP");
  }
}
