// BFEMP Section 6.4 at the paper's resolution and time line: the four
// scenes prm/experiments/6_4_slope/slope_mu_{0,0_1,0_1999,0_2}.prm (369
// particles, settled 2 s, released at 2 s, run to 3 s), checked as the
// reduced test (slope_check.h): a = g (sin theta - mu cos theta) to the
// paper's 0.01 % for mu < 0.2, |v| around eps_v for mu = 0.2. About
// 1-2 min of CPU per scene.

#include "../experiments/slope_check.h"

int
main()
{
  bfemp_tests::initlog();
  const std::string dir = BFEMP_SOURCE_DIR "/prm/experiments/6_4_slope/";
  slope_check::check(dir + "slope_mu_0.prm", "slope_mu_0", 0., 2.);
  slope_check::check(dir + "slope_mu_0_1.prm", "slope_mu_0_1", 0.1, 2.);
  slope_check::check(dir + "slope_mu_0_1999.prm",
                     "slope_mu_0_1999",
                     0.1999,
                     2.);
  slope_check::check(dir + "slope_mu_0_2.prm", "slope_mu_0_2", 0.2, 2.);
}
