// Seed 002 Section 8.1.2, how the bending beam's max r_u depends on the
// places of its 40 soft inclusions, which the seed does not give: the 2D
// beam of prm/cmpm/bending_beam_2d.prm (layout seed 2002) and eleven other
// layouts drawn the same way, plus the beam without inclusions, each run as
// cMPM, BSMPM-fine and BSMPM-coarse by doc/experiments/cmpm_beam_layouts.py
// (about 6 min). Checked, in every layout:
// - max r_u of cMPM below half of BSMPM-coarse's (the seed's Fig. 21);
// - where cMPM's largest error comes in the first 0.1 s, most of its
//   squared displacement error (> 0.5) lies in the soft inclusions (about
//   15 % of the volume) and within 3 m of the clamped ends: there the soft
//   inclusions fall inside a stiff matrix that hardly moves yet, a motion a
//   coarse element's boundary-interior map (eq. 30, f_i = 0) cannot give;
// and across layouts: the homogeneous beam's max r_u lies below every
// layout's, and prm/cmpm's layout lies within the spread. Each layout's row
// goes to the test output (4 digits); doc/cmpm.md discusses the spread.

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "../diagnostics_csv.h"
#include "../format.h"
#include "../tests.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  using bfemp_tests::check;
  using bfemp_tests::format;

  check(bfemp_tests::run_study("cmpm_beam_layouts.py", "layouts"),
        "cmpm_beam_layouts.py ran 13 beams");

  // layout 0 is prm/cmpm's (seed 2002), the last one the homogeneous beam
  const auto        c       = bfemp_tests::read_columns("layouts/layouts.csv",
                                           {"max_r_u_cmpm",
                                                         "time_of_max",
                                                         "max_r_u_coarse",
                                                         "soft_share",
                                                         "clamp_share"});
  const std::size_t layouts = c[0].size() - 1;
  check(layouts == 12, "twelve layouts and the homogeneous beam");
  double smallest = 1e300, largest = 0.;
  bool   below_half = true, mostly_soft = true;
  for (std::size_t i = 0; i <= layouts; ++i)
    {
      // the script's default layouts: seed 2002, then seeds 1, ..., 11
      dealii::deallog << (i == layouts ? std::string("homogeneous")
                                       : "layout seed " +
                                           std::to_string(i == 0 ? 2002 : i))
                      << ": max r_u cMPM " << format("%.4f", c[0][i])
                      << " at t = " << format("%.3f", c[1][i])
                      << ", BSMPM-coarse " << format("%.4f", c[2][i])
                      << "; at cMPM's max, share of the error in the soft "
                         "inclusions "
                      << format("%.2f", c[3][i]) << ", within 3 m of the ends "
                      << format("%.2f", c[4][i]) << std::endl;
      if (i == layouts)
        continue;
      smallest   = std::min(smallest, c[0][i]);
      largest    = std::max(largest, c[0][i]);
      below_half = below_half && c[0][i] < 0.5 * c[2][i];
      if (c[1][i] <= 0.1)
        mostly_soft = mostly_soft && c[3][i] > 0.5 && c[4][i] > 0.5;
    }
  dealii::deallog << "max r_u of cMPM over the layouts: "
                  << format("%.4f", smallest) << " to "
                  << format("%.4f", largest) << " (seed, 3D: 0.016)"
                  << std::endl;
  check(below_half,
        "in every layout max r_u of cMPM below half of "
        "BSMPM-coarse's");
  check(mostly_soft,
        "where cMPM's max r_u comes before t = 0.1 s, most of "
        "its error in the soft inclusions and near the ends");
  check(c[0][layouts] < smallest,
        "the homogeneous beam's max r_u below every layout's");
  check(c[0][0] >= smallest && c[0][0] <= largest,
        "prm/cmpm's layout within the spread");
}
