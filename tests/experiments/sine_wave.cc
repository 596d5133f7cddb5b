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

#include "sine_wave_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  // The reduced prm files' keyframes.
  const std::string directory =
    BFEMP_SOURCE_DIR "/prm/experiments/6_2_sine_wave/";
  const sine_wave_check::Path path{0.1, 0.15, 1.13, 1.1, 0.35, 1e-3};

  const auto bfemp =
    sine_wave_check::check_bfemp(directory + "sine_wave_bfemp_reduced.prm",
                                 path,
                                 1e-3);
  bfemp_tests::check(bfemp.separation < 0.03,
                     "bfemp: no adhesion (separates < 30 mm above the top)");

  const auto level_set =
    sine_wave_check::check_level_set(directory +
                                       "sine_wave_level_set_reduced.prm",
                                     path);
  bfemp_tests::check(level_set.separation > 0.045,
                     "level set: adhesion (box held > 45 mm above its top)");
  bfemp_tests::check(level_set.separation > 2. * bfemp.separation,
                     "level set holds the box more than twice as high as "
                     "BFEMP");
}
