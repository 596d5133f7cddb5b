// BFEMP Section 6.2 at the paper's resolution, the BFEMP variant:
// prm/experiments/6_2_sine_wave/sine_wave_bfemp.prm (box 1 x 1 m at
// dx = 0.02, 22500 particles, the sine-wave boundary a kinematic FEM body of
// 10142 vertices; 0.6 s down from 0.2 m above the box, 0.5 s left, up to
// t = 1.8 s; h = 1e-3 s, 1800 steps), checked as the reduced test
// (sine_wave_check.h): contact in every phase and none at the end, no
// particle inside the mesh and min_distance > 0 in every row. Adhesion
// bands: the box is compressed by 0.4 m and its top follows the rising
// boundary by its elastic rebound (measured: last contact 31 mm above the
// box's initial top, centre of mass at most 0.74 mm above its start), so
// last contact below 100 mm and a lift below 5 mm; the level-set variant
// (sine_wave_full_level_set) still holds particles when the boundary is
// 300 mm up and lifts the centre of mass by 24 mm. 29 min wall in ctest
// (2026-11-25, 2 cores shared by four validation tests).

#include "../experiments/sine_wave_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  // The prm file's keyframes and the box's top at y = 1.04.
  const sine_wave_check::Path path{0.6, 1.1, 1.24, 1.04, 1.8, 1e-3};
  const auto                  bfemp = sine_wave_check::check_bfemp(
    BFEMP_SOURCE_DIR "/prm/experiments/6_2_sine_wave/sine_wave_bfemp.prm",
    path,
    1e-3);
  bfemp_tests::check(bfemp.separation < 0.1,
                     "bfemp: no adhesion (separates < 100 mm above the top)");
  bfemp_tests::check(bfemp.lift < 0.005,
                     "bfemp: the centre of mass rises < 5 mm above its start");
}
