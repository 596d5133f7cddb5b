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

    /**
     * A run continued from a checkpoint at simulated time @p start_time,
     * after @p earlier_wall_time wall seconds of the earlier parts: the wall
     * time continues from there, the estimate uses this part's pace.
     */
    void
    resume(const double start_time, const double earlier_wall_time);

    /** Wall seconds of the run (since construction, plus earlier parts). */
    double
    wall_time() const;

  private:
    /** Wall seconds since construction. */
    double
    elapsed() const;

    /** Estimated wall seconds to the end time from simulated @p time. */
    double
    remaining(const double time) const;

    std::ostream                         &out;
    double                                end_time;
    bool                                  enabled;
    std::chrono::steady_clock::time_point start;
    double                                start_time        = 0.;
    double                                earlier_wall_time = 0.;
  };
} // namespace bfemp

#endif
