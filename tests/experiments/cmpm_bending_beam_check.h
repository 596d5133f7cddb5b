#ifndef bfemp_tests_experiments_cmpm_bending_beam_check_h
#define bfemp_tests_experiments_cmpm_bending_beam_check_h

// Seed 002 Section 8.1.2 (the heterogeneous bending beam, cMPM against
// BSMPM-fine and BSMPM-coarse), the runs and checks shared by the reduced
// test (tests/experiments/cmpm_bending_beam: the 2D beam) and the full one
// (tests/validation/cmpm_bending_beam_full: the 3D beam). The three prm
// files of a beam (prm/cmpm/bending_beam_<dim>d{,_fine,_coarse}.prm) run on
// the same particles; doc/experiments/particle_error.py gives r_u and
// r_sigma (eq. 38) of cMPM and of BSMPM-coarse against BSMPM-fine at every
// output time. Checked, as the seed's Fig. 21 and Table 3 show:
// - max r_u of cMPM is below @p r_u_bound and below half of BSMPM-coarse's
//   (seed, 3D: 0.016 against 0.095);
// - cMPM takes less time per step than BSMPM-fine (seed: 11x less): CPU
//   time of this process, or, for runs that may continue from checkpoints,
//   the wall time per step of diagnostics.csv (counted across the sittings).
// The errors go to the test output (4 digits); times, which depend on the
// machine, to the console.

#include <iostream>
#include <string>

#include "../format.h"
#include "cmpm_runs.h"

namespace cmpm_bending_beam_check
{
  using cmpm_runs::Cost;
  using cmpm_runs::max_errors;
  using cmpm_runs::print_cost;
  using cmpm_runs::run;

  /** Runs the three beams of @p dim and checks them as described above.
   *  With @p resumable, each run saves a checkpoint every 15 minutes of wall
   *  time and continues from it when the test is started again. */
  template <int dim>
  void
  check(const double r_u_bound, const bool resumable = false)
  {
    const std::string entries =
      resumable ? "subsection checkpoint\n  set wall time interval = 900\n"
                  "  set resume = auto\nend\n"
                : "";
    const std::string prefix = std::string(BFEMP_SOURCE_DIR) +
                               "/prm/cmpm/bending_beam_" + std::to_string(dim) +
                               "d";
    const std::string beam = "beam_" + std::to_string(dim) + "d";
    const Cost        cmpm = run<dim>(prefix + ".prm", beam + "_cmpm", entries);
    const Cost fine = run<dim>(prefix + "_fine.prm", beam + "_fine", entries);
    const Cost coarse =
      run<dim>(prefix + "_coarse.prm", beam + "_coarse", entries);
    print_cost("cMPM", cmpm);
    print_cost("BSMPM-fine", fine);
    print_cost("BSMPM-coarse", coarse);
    std::cout << "CPU time per step, BSMPM-fine / cMPM: "
              << (fine.cpu_seconds / fine.steps) /
                   (cmpm.cpu_seconds / cmpm.steps)
              << std::endl;

    const auto [cmpm_u, cmpm_sigma] =
      max_errors(beam + "_fine", beam + "_cmpm", true);
    const auto [coarse_u, coarse_sigma] =
      max_errors(beam + "_fine", beam + "_coarse", true);
    using bfemp_tests::format;
    dealii::deallog << dim << "D beam, " << cmpm.steps
                    << " steps: max r_u cMPM " << format("%.4f", cmpm_u)
                    << ", BSMPM-coarse " << format("%.4f", coarse_u)
                    << " (seed 3D: 0.016, 0.095); max r_sigma cMPM "
                    << format("%.4f", cmpm_sigma) << ", BSMPM-coarse "
                    << format("%.4f", coarse_sigma) << std::endl;
    bfemp_tests::check(cmpm_u < r_u_bound,
                       "max r_u of cMPM below " + format("%g", r_u_bound));
    bfemp_tests::check(cmpm_u < 0.5 * coarse_u,
                       "max r_u of cMPM below half of BSMPM-coarse's");
    if (resumable)
      bfemp_tests::check(cmpm.wall_per_step < fine.wall_per_step,
                         "cMPM takes less wall time per step than BSMPM-fine");
    else
      bfemp_tests::check(cmpm.cpu_seconds / cmpm.steps <
                           fine.cpu_seconds / fine.steps,
                         "cMPM takes less CPU time per step than BSMPM-fine");
  }
} // namespace cmpm_bending_beam_check

#endif
