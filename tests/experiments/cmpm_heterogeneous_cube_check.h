#ifndef bfemp_tests_experiments_cmpm_heterogeneous_cube_check_h
#define bfemp_tests_experiments_cmpm_heterogeneous_cube_check_h

// Seed 002 Section 8.1.4 (the heterogeneous cube, first Newton step against
// full Newton in the local problem), the runs and checks shared by the
// reduced test (tests/experiments/cmpm_heterogeneous_cube, 2D) and the full
// one (tests/validation/cmpm_heterogeneous_cube_full, 3D):
// prm/cmpm/heterogeneous_cube_<dim>d{,_full_newton,_fine}.prm on the same
// particles. Checked: max r_u (eq. 38 against BSMPM-fine) of both local
// solves below @p r_u_bound, within 5 % of each other; the full solve takes
// at least 1.8 times the Newton iterations (it solves each step twice,
// doc/cmpm.md; the CPU times go to the console, not into a check).

#include <cmath>
#include <string>

#include "../format.h"
#include "cmpm_runs.h"

namespace cmpm_heterogeneous_cube_check
{
  template <int dim>
  void
  check(const double r_u_bound)
  {
    using bfemp_tests::format;
    const std::string prefix = std::string(BFEMP_SOURCE_DIR) +
                               "/prm/cmpm/heterogeneous_cube_" +
                               std::to_string(dim) + "d";

    const auto first = cmpm_runs::run<dim>(prefix + ".prm", "cube_first");
    const auto full =
      cmpm_runs::run<dim>(prefix + "_full_newton.prm", "cube_full_newton");
    const auto fine = cmpm_runs::run<dim>(prefix + "_fine.prm", "cube_fine");
    cmpm_runs::print_cost("cMPM first Newton step", first);
    cmpm_runs::print_cost("cMPM full Newton", full);
    cmpm_runs::print_cost("BSMPM-fine", fine);

    const auto [first_u, first_sigma] =
      cmpm_runs::max_errors("cube_fine", "cube_first");
    const auto [full_u, full_sigma] =
      cmpm_runs::max_errors("cube_fine", "cube_full_newton");
    dealii::deallog << dim << "D: max r_u first Newton step "
                    << format("%.4f", first_u) << ", full Newton "
                    << format("%.4f", full_u)
                    << " (seed 3D: 0.040, 0.031); max r_sigma "
                    << format("%.4f", first_sigma) << ", "
                    << format("%.4f", full_sigma) << std::endl;
    dealii::deallog << "Newton iterations per step: first Newton step "
                    << format("%.2f", first.newton_iterations)
                    << ", full Newton "
                    << format("%.2f", full.newton_iterations) << std::endl;
    bfemp_tests::check(first_u < r_u_bound && full_u < r_u_bound,
                       "max r_u of both local solves below " +
                         format("%g", r_u_bound));
    bfemp_tests::check(std::abs(first_u - full_u) < 0.05 * full_u,
                       "the two local solves within 5 % of each other");
    bfemp_tests::check(full.newton_iterations >= 1.8 * first.newton_iterations,
                       "the full Newton local solve takes at least 1.8 times "
                       "the Newton iterations");
  }
} // namespace cmpm_heterogeneous_cube_check

#endif
