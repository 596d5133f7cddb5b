// BFEMP Section 6.1 at the paper's resolution, APIC:
// prm/experiments/6_1_rings/rings_apic.prm with the time step quartered to
// h = 5e-5 s, checked as the reduced test (rings_check.h). At the paper's
// h = 2e-4 s the full APIC run gains 5-10 % of energy in the collision
// instead of losing 8.57 %: the surface particles bounce on the barrier,
// and halving and quartering h removes the rising steps
// (doc/experiments/rings.md); at 5e-5 s it loses 9.4 %. This test checks
// that resolved run, with the energy band 6 % .. 13 % of rings_full_flip.
// 42 min wall in ctest (2026-11-25, 2 cores shared by four validation
// tests).

#include "../experiments/rings_check.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");
  rings_check::check({BFEMP_SOURCE_DIR
                      "/prm/experiments/6_1_rings/rings_apic.prm",
                      "APIC",
                      "subsection time\n  set time step = 5e-5\nend\n",
                      0.06,
                      0.13});
}
