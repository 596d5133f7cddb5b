#ifndef bfemp_tests_experiments_sine_wave_check_h
#define bfemp_tests_experiments_sine_wave_check_h

// BFEMP Section 6.2 ("FEM as contact boundary for MPM"), shared by the
// reduced test (tests/experiments/sine_wave) and the full-resolution ones
// (tests/validation/sine_wave_full_{bfemp,level_set}): running a scene of
// prm/experiments/6_2_sine_wave/ into results/, and the quantities the
// checks use. The boundary moves at 1 m/s: down until t_side, left until
// t_up, then up; its lowest point starts at y_start, the box's top at y_box.

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "../implicit/implicit_scene.h"

namespace sine_wave_check
{
  using namespace dealii;
  using namespace implicit_scene;

  struct Path
  {
    double t_side;
    double t_up;
    double y_start;
    double y_box;
    double end_time;
    double dt;

    /** Height of the boundary's lowest point at time @p t. */
    double
    lowest_point(const double t) const
    {
      return y_start - std::min(t, t_side) + std::max(0., t - t_up);
    }

    /** 0 while going down, 1 sideways, 2 up. */
    unsigned int
    phase(const double t) const
    {
      return t < t_side ? 0 : t < t_up ? 1 : 2;
    }
  };

  /** Runs @p prm_file (included) as run @p name into results/ with one
   *  diagnostics row per step and no VTU; returns its diagnostics columns
   *  @p which (time first) and the box's centre-of-mass height from
   *  bodies.csv (last). */
  inline std::vector<std::vector<double>>
  simulate(const std::string       &prm_file,
           const std::string       &name,
           const Path              &path,
           std::vector<std::string> which)
  {
    std::ostringstream prm;
    prm << "include " << prm_file
        << "\n"
           "subsection run\n  set name = "
        << name
        << "\n  set quiet = true\nend\n"
           "subsection output\n  set directory = results\n"
           "  set interval = "
        << path.end_time
        << "\n  set diagnostics interval = 1\n"
           "  set write particles = false\n  set write grid = false\nend\n";
    write(name + ".prm", prm.str());
    const std::string error = run<2>(name + ".prm").error;
    if (!error.empty())
      deallog << name << ": " << error << std::endl;
    bfemp_tests::check(error.empty(), name + ": the run reached the end");
    which.insert(which.begin(), "time");
    auto c = columns(name, which);
    c.push_back(bfemp_tests::read_columns("results/" + name + "/bodies.csv",
                                          {"mpm0_com_y"})[0]);
    bfemp_tests::check(c[0].size() == static_cast<std::size_t>(
                                        std::round(path.end_time / path.dt)) +
                                        1,
                       name + ": one diagnostics row per step");
    bfemp_tests::check(c.back().size() == c[0].size(),
                       name + ": one bodies.csv row per step");
    return c;
  }

  /** How far above the box's initial top the boundary's lowest point is
   *  at the last row where @p touching (a count per row) is positive. */
  inline double
  separation_height(const Path                &path,
                    const std::vector<double> &t,
                    const std::vector<double> &touching)
  {
    double last = 0.;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (touching[k] > 0)
        last = t[k];
    return path.lowest_point(last) - path.y_box;
  }

  /** Largest rise of the centre of mass @p y above y(0) in the up phase. */
  inline double
  lift(const Path                &path,
       const std::vector<double> &t,
       const std::vector<double> &y)
  {
    double rise = -std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k] > path.t_up)
        rise = std::max(rise, y[k] - y[0]);
    return rise;
  }

  struct BfempResult
  {
    double separation;
    double lift;
  };

  /** The BFEMP variant (the boundary a kinematic FEM body, activation
   *  distance @p dhat): contact in every phase and none at the end, no
   *  particle inside the mesh and min_distance > 0 in every row (the
   *  barrier's guarantee, exact). Returns the separation height and the
   *  lift for the caller's adhesion bands. */
  inline BfempResult
  check_bfemp(const std::string &prm_file, const Path &path, const double dhat)
  {
    const auto c =
      simulate(prm_file,
               "bfemp",
               path,
               {"contact_particles", "particles_in_fem", "min_distance"});
    const auto  &t          = c[0];
    bool         contact[3] = {false, false, false};
    unsigned int inside     = 0;
    double       d_min      = std::numeric_limits<double>::max();
    for (std::size_t k = 1; k < t.size(); ++k)
      {
        contact[path.phase(t[k])] = contact[path.phase(t[k])] || c[1][k] > 0;
        inside = std::max(inside, static_cast<unsigned int>(c[2][k]));
        d_min  = std::min(d_min, c[3][k]);
      }
    bfemp_tests::check(contact[0] && contact[1] && contact[2],
                       "bfemp: contact while going down, sideways and up");
    bfemp_tests::check(c[1].back() == 0, "bfemp: separated at the end");
    deallog << "bfemp: max particles_in_fem " << inside
            << ", min_distance / dhat " << rounded(d_min / dhat, 2)
            << std::endl;
    bfemp_tests::check(inside == 0,
                       "bfemp: no particle inside the FEM boundary, any row");
    bfemp_tests::check(d_min > 0., "bfemp: min_distance > 0 in every row");
    const BfempResult result{separation_height(path, t, c[1]),
                             lift(path, t, c[4])};
    deallog << "bfemp: last contact with the boundary "
            << rounded(1e3 * result.separation, 2)
            << " mm above the box's initial top; lift of the centre of mass "
            << rounded(1e3 * result.lift, 2) << " mm" << std::endl;
    return result;
  }

  struct LevelSetResult
  {
    double       separation;
    double       lift;
    unsigned int inside_at_end;
  };

  /** The level-set variant (the same motion as a slip boundary on the
   *  grid): particles get inside the boundary in some row. Returns the
   *  separation height, the lift and the particles inside at the end. */
  inline LevelSetResult
  check_level_set(const std::string &prm_file, const Path &path)
  {
    const auto c =
      simulate(prm_file, "level_set", path, {"particles_in_level_sets"});
    const auto  &t = c[0];
    const double n = max_of(c[1]);
    deallog << "level set: max particles_in_level_sets "
            << static_cast<unsigned int>(n) << std::endl;
    bfemp_tests::check(n > 0, "level set: particles penetrate the boundary");
    const LevelSetResult result{separation_height(path, t, c[1]),
                                lift(path, t, c[2]),
                                static_cast<unsigned int>(c[1].back())};
    deallog << "level set: last particle inside the boundary "
            << rounded(1e3 * result.separation, 2)
            << " mm above the box's initial top; lift of the centre of mass "
            << rounded(1e3 * result.lift, 2) << " mm" << std::endl;
    return result;
  }
} // namespace sine_wave_check

#endif
