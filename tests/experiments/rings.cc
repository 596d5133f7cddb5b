// BFEMP Section 6.1, colliding rings, reduced: runs
// prm/experiments/6_1_rings/rings_reduced.prm (the paper's scene and contact
// parameters at dx = 0.4, 2 x 2 particles per cell, FEM edge 0.5, Newmark
// h = 5e-4 s) with APIC and with FLIP and checks what the paper reports
// (rings_check.h), within the bands that doc/experiments/rings.md justifies.
// The energy band is 4 % .. 22 % for both schemes: at this resolution the
// loss is chaotic, since the surface particles bounce on the barrier, and
// perturbations of round-off size (the Newton tolerance, exact or projected
// Hessian, BLAS threads in CHOLMOD) as well as grid offsets move it between
// 7.8 and 15.3 % (APIC) and 12.5 and 19.0 % (FLIP) over 26 runs. The band
// holds all of them with a margin; it is a plausibility band, not a
// convergence result. For the same reason the paper's ordering (FLIP loses
// more than APIC, true in 12 of 13 paired runs) is not checked.

#include "rings_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  const std::string prm =
    BFEMP_SOURCE_DIR "/prm/experiments/6_1_rings/rings_reduced.prm";
  for (const std::string scheme : {"APIC", "FLIP"})
    rings_check::check({prm, scheme, "", 0.04, 0.22});
}
