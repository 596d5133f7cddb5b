#ifndef bfemp_tests_cmpm_beam_run_h
#define bfemp_tests_cmpm_beam_run_h

// Runs of prm/cmpm/beam_2d.prm (the heterogeneous 2D beam under gravity)
// for the cMPM scene tests, and the entries that turn it into BSMPM-fine.

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "diagnostics_csv.h"
#include "run_scene.h"

namespace bfemp_tests
{
  /** Runs prm/cmpm/beam_2d.prm with @p entries appended; returns the drop of
   *  the centre of mass of both bodies between t = 0 and the end. */
  inline double
  beam_drop(const std::string &name, const std::string &entries)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << "include " << BFEMP_SOURCE_DIR << "/prm/cmpm/beam_2d.prm\n"
          << "subsection run\n  set name = " << name
          << "\n  set quiet = true\nend\n"
          << "subsection output\n  set directory = results\n"
             "  set interval = 0.5\nend\n"
          << entries;
    }
    run_scene<2>(name + ".prm");
    const auto c =
      read_columns("results/" + name + "/bodies.csv",
                   {"mpm0_mass", "mpm0_com_y", "mpm1_mass", "mpm1_com_y"});
    const auto com = [&](const std::size_t row) {
      return (c[0][row] * c[1][row] + c[2][row] * c[3][row]) /
             (c[0][row] + c[2][row]);
    };
    return com(0) - com(c[0].size() - 1);
  }

  /**
   * The entries that run the beam as BSMPM-fine: a quadratic B-spline grid
   * of cell @p s (cMPM's fine knot span, 0.02 for H = 0.1 and n = 7)
   * shifted by s/2 (so that its functions are cMPM's fine patch functions)
   * with its lower edge at y = @p lower_y, 2 particles per cell and
   * direction, clamped at each end
   * - over the same 0.1 m as cMPM (@p matched_clamp false): the fixed fine
   *   nodes end s/2 outside the clamped element face, so the fine space
   *   contains cMPM's;
   * - or as cMPM is (@p matched_clamp true): one more layer, so that the
   *   fixed nodes end s/2 inside that face, where cMPM's boundary B-spline
   *   element takes its fine rows on either side of the face from the fixed
   *   face nodes (doc/experiments/make_cmpm_prms.py, "Matching clamps").
   */
  inline std::string
  beam_bsmpm_fine(const double lower_y,
                  const double s             = 0.02,
                  const bool   matched_clamp = false)
  {
    std::ostringstream entries;
    entries << "subsection cmpm\n  set enabled = false\nend\n"
            << "subsection grid\n"
            << "  set lower corner = " << -0.1 - s / 2 << ", " << lower_y
            << "\n  set upper corner = " << 2.5 + s / 2 << ", " << 0.8 + s / 2
            << "\n  set cell size    = " << s << "\n"
            << "  set kernel       = quadratic\n"
            << "end\n"
            << "subsection boundaries\n  set wall layers = "
            << std::lround(0.2 / s) + (matched_clamp ? 1 : 0) << "\nend\n"
            << "subsection body 0\n  set particles per cell = 2\nend\n"
            << "subsection body 1\n  set particles per cell = 2\nend\n";
    return entries.str();
  }
} // namespace bfemp_tests

#endif
