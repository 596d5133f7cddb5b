// cMPM's interior body-load modes (`cmpm/interior modes = body load`,
// bfemp's addition beyond seed 002, doc/cmpm.md) and the coarse node span
// L = H/3 on the 2D bending beam of prm/cmpm/bending_beam_2d.prm (seed 002
// Section 8.1.2, layout seed 2002): doc/experiments/cmpm_beam_layouts.py
// runs cMPM without and with the modes, cMPM with L = H/3 and the modes
// (bending_beam_2d_h3_modes.prm), BSMPM-fine (the reference) and
// BSMPM-coarse (about 50 s). The beam's largest cMPM errors sit in soft
// inclusions that sag inside a stiff matrix next to the clamps, a motion of
// an element's interior that eq. 30 (f_i = 0) leaves out and the modes add;
// what is left sits where inclusions cross element faces, whose fine rows
// the face curves set: L = H/3 gives those curves two nodes inside every
// element edge. Checked: the modes lower max r_u by at least 5 % and r_u at
// every output time; both cMPM variants at L = H/2 stay below half of
// BSMPM-coarse's max r_u; with L = H/3 and the modes max r_u is below the
// seed's 0.016 (3D) and below 0.85 of that with the modes at L = H/2. The
// numbers go to the output (4 digits): the maxima and r_u of the runs at
// every output time (the layout's series.csv).

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

  check(bfemp_tests::run_study(
          "cmpm_beam_layouts.py",
          "modes",
          "--seeds 2002 --no-homogeneous --interior-modes --h3-modes"),
        "cmpm_beam_layouts.py ran the beam five times");

  const auto c = bfemp_tests::read_columns("modes/layouts.csv",
                                           {"max_r_u_cmpm",
                                            "max_r_u_modes",
                                            "time_of_max_modes",
                                            "max_r_u_coarse",
                                            "max_r_u_h3_modes",
                                            "time_of_max_h3_modes"});
  check(c[0].size() == 1, "one layout");
  const double plain = c[0][0], modes = c[1][0], coarse = c[3][0],
               h3_modes = c[4][0];
  dealii::deallog << "2D beam, layout seed 2002: max r_u cMPM "
                  << format("%.4f", plain) << ", with interior modes "
                  << format("%.4f", modes)
                  << " (at t = " << format("%.3f", c[2][0])
                  << "), BSMPM-coarse " << format("%.4f", coarse)
                  << " (seed, 3D: cMPM 0.016)" << std::endl;
  check(modes < 0.95 * plain,
        "the interior modes lower cMPM's max r_u by at least 5 %");
  check(plain < 0.5 * coarse && modes < 0.5 * coarse,
        "both cMPM variants below half of BSMPM-coarse's max r_u");
  dealii::deallog << "L = H/3 with interior modes: max r_u "
                  << format("%.4f", h3_modes)
                  << " (at t = " << format("%.3f", c[5][0]) << ")" << std::endl;
  check(h3_modes < 0.016,
        "L = H/3 with interior modes: max r_u below the seed's 0.016");
  check(h3_modes < 0.85 * modes,
        "L = H/3 with interior modes: max r_u below 0.85 of L = H/2's");

  const auto s = bfemp_tests::read_columns(
    "modes/layout_2002/series.csv",
    {"time", "r_u_cmpm", "r_u_modes", "r_u_coarse", "r_u_h3_modes"});
  check(s[0].size() == 24, "r_u at the 24 output times");
  dealii::deallog << "t, r_u: cMPM, with interior modes, BSMPM-coarse, "
                     "L = H/3 with interior modes"
                  << std::endl;
  bool lower_everywhere = true;
  for (std::size_t k = 0; k < s[0].size(); ++k)
    {
      dealii::deallog << format("%.3f", s[0][k]) << "  "
                      << format("%.4f", s[1][k]) << "  "
                      << format("%.4f", s[2][k]) << "  "
                      << format("%.4f", s[3][k]) << "  "
                      << format("%.4f", s[4][k]) << std::endl;
      lower_everywhere = lower_everywhere && s[2][k] < s[1][k];
    }
  check(lower_everywhere,
        "with the interior modes, r_u is lower at every output time");
}
