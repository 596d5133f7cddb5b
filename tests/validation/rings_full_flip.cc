// BFEMP Section 6.1 at the paper's resolution, FLIP:
// prm/experiments/6_1_rings/rings_flip.prm (dx = 0.1, 3 x 3 particles per
// cell, FEM edge 0.127, Newmark h = 2e-4 s) checked as the reduced test
// (rings_check.h). Energy band 6 % .. 13 %: the paper's 8.57 % and 9.67 %
// widened by about a third. At this resolution the contact is resolved
// (the loss changes from 8.4 % to 8.0 % when h goes from 2e-4 to 5e-5 s,
// doc/experiments/rings.md), so the band is tighter than the reduced
// test's 4 % .. 22 %; it is still a band around one sample, not a
// convergence result. 16 min wall in
// ctest (2026-11-25, 2 cores shared by four validation tests).

#include "../experiments/rings_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");
  rings_check::check({BFEMP_SOURCE_DIR
                      "/prm/experiments/6_1_rings/rings_flip.prm",
                      "FLIP",
                      "",
                      0.06,
                      0.13});
}
