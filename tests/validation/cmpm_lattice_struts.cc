// Seed 002 Section 8.1.3, how the lattice bar's max r_u depends on how many
// knot spans its struts are wide, which the seed's text does not give: the
// 2D bar of prm/cmpm/lattice_bar_2d.prm (pitch 0.5 m, struts 3 knot spans)
// and the same 49 % void on lattices of pitch 2/3 and 1 m (struts 4 and 6
// knot spans), each run to 1.0 s as cMPM on boundary B-spline and on
// B-spline elements and as BSMPM-fine by
// doc/experiments/cmpm_lattice_struts.py (about 2 min). Checked:
// - at every pitch B-spline elements are more accurate than boundary
//   B-spline ones (the seed's Table 3 order);
// - at every pitch both coarse spaces sag less than BSMPM-fine at 1.0 s
//   (they are stiffer), and the B-spline elements' shortfall at 6 knot
//   spans is below 0.6 of the one at 3;
// - B-spline elements' max r_u at 6 knot spans is below 0.6 of the one at
//   3: the error of bfemp's bar above the seed's comes from struts that
//   are only 3 knot spans wide.
// Each pitch's row goes to the test output (4 digits); doc/cmpm.md
// ("Lattice bar") discusses it.

#include <cmath>
#include <cstdlib>
#include <string>

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

  check(bfemp_tests::run_study("cmpm_lattice_struts.py", "struts"),
        "cmpm_lattice_struts.py ran three pitches");

  const auto        c       = bfemp_tests::read_columns("struts/struts.csv",
                                           {"strut_spans",
                                                         "max_r_u_boundary_bspline",
                                                         "max_r_u_bspline",
                                                         "sag_fine",
                                                         "sag_boundary_bspline",
                                                         "sag_bspline"});
  const std::size_t pitches = c[0].size();
  check(pitches == 3, "three pitches");
  bool ordered = true, stiffer = true;
  for (std::size_t i = 0; i < pitches; ++i)
    {
      dealii::deallog << "struts " << format("%.0f", c[0][i])
                      << " knot spans: max r_u boundary B-spline "
                      << format("%.4f", c[1][i]) << ", B-spline "
                      << format("%.4f", c[2][i]) << "; sag at 1.0 s: fine "
                      << format("%.4f", c[3][i]) << " m, boundary B-spline "
                      << format("%.4f", c[4][i]) << " m, B-spline "
                      << format("%.4f", c[5][i]) << " m" << std::endl;
      ordered = ordered && c[2][i] < c[1][i];
      stiffer = stiffer && std::abs(c[4][i]) < std::abs(c[3][i]) &&
                std::abs(c[5][i]) < std::abs(c[3][i]);
    }
  dealii::deallog << "seed (3D, geometry not given): boundary B-spline 0.025, "
                     "B-spline 0.021"
                  << std::endl;
  check(ordered, "B-spline elements below boundary B-spline at every pitch");
  check(stiffer, "both coarse spaces sag less than BSMPM-fine at every pitch");
  const double shortfall_3 = std::abs(c[3][0]) - std::abs(c[5][0]);
  const double shortfall_6 = std::abs(c[3][2]) - std::abs(c[5][2]);
  dealii::deallog << "B-spline elements' sag shortfall: "
                  << format("%.4f", shortfall_3) << " m (3 spans), "
                  << format("%.4f", shortfall_6) << " m (6 spans)" << std::endl;
  check(shortfall_6 < 0.6 * shortfall_3,
        "the B-spline elements' sag shortfall at 6 spans below 0.6 of the "
        "one at 3");
  check(c[2][2] < 0.6 * c[2][0],
        "B-spline elements' max r_u at 6 spans below 0.6 of the one at 3");
}
