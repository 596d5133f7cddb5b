#ifndef bfemp_io_progress_reporter_h
#define bfemp_io_progress_reporter_h

#include <chrono>
#include <ostream>

namespace bfemp
{
  /**
   * One line per step on the console: step, time, dt (Newton iterations and
   * unknowns for implicit steps, substeps of substepped MPM), wall time and an
   * estimate of the wall time to the end (from the average simulated time per
   * wall second so far). Silent in quiet and test mode.
   */
  class ProgressReporter
  {
  public:
    ProgressReporter(std::ostream &out,
                     const double  end_time,
                     const bool    enabled);

    void
    report(const unsigned int step,
           const double       time,
           const double       dt,
           const unsigned int substeps = 0);

    /** The line of an implicit step: also Newton iterations and unknowns. */
    void
    report(const unsigned int step,
           const double       time,
           const double       dt,
           const unsigned int newton_iterations,
           const unsigned int n_dofs,
           const int          contact_pairs = -1,
           const unsigned int substeps      = 0);

    /** Wall seconds since construction. */
    double
    wall_time() const;

  private:
    std::ostream                         &out;
    double                                end_time;
    bool                                  enabled;
    std::chrono::steady_clock::time_point start;
  };
} // namespace bfemp

#endif
