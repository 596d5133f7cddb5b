// BFEMP Section 6.4, critical value of the friction coefficient: the
// reduced scene prm/experiments/6_4_slope/slope_reduced.prm (the full
// scene's box, slope, support plate and numerics; settled 0.1 s instead of
// 2 s, released for 0.2 s instead of 1 s) for mu = 0, 0.1, 0.1999, 0.2,
// checked by slope_check.h (tests/validation/slope_full runs the full
// scenes through the same checks).
//
// Measured: before the release |v| is 5e-15 m/s for mu = 0, 7e-15 for
// mu = 0.1 and ~1e-11 for mu >= 0.1999 (the static-friction zone of the
// mollifier lets the settling decay more slowly); the fitted accelerations
// are within ~1e-9 of eq. (40) (for mu = 0.1999 a is 2000 times smaller
// than for mu = 0); for mu = 0.2 |v| after the release stays at
// 0.99994 eps_v.

#include "slope_check.h"

int
main()
{
  bfemp_tests::initlog();
  const std::string prm =
    BFEMP_SOURCE_DIR "/prm/experiments/6_4_slope/slope_reduced.prm";
  slope_check::check(prm, "slope_mu_0", 0., 0.1);
  slope_check::check(prm, "slope_mu_0_1", 0.1, 0.1);
  slope_check::check(prm, "slope_mu_0_1999", 0.1999, 0.1);
  slope_check::check(prm, "slope_mu_0_2", 0.2, 0.1);
}
