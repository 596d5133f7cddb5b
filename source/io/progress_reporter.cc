#include <bfemp/io/progress_reporter.h>

#include <algorithm>
#include <iomanip>

namespace bfemp
{
  ProgressReporter::ProgressReporter(std::ostream &out,
                                     const double  end_time,
                                     const bool    enabled)
    : out(out)
    , end_time(end_time)
    , enabled(enabled)
    , start(std::chrono::steady_clock::now())
  {}



  void
  ProgressReporter::resume(const double start_time,
                           const double earlier_wall_time)
  {
    this->start_time        = start_time;
    this->earlier_wall_time = earlier_wall_time;
  }



  double
  ProgressReporter::elapsed() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start)
      .count();
  }



  double
  ProgressReporter::wall_time() const
  {
    return earlier_wall_time + elapsed();
  }



  double
  ProgressReporter::remaining(const double time) const
  {
    // the last step may end a round-off beyond end_time: no "-0.0 s" left
    return time > start_time
             ? std::max(0., elapsed() * (end_time - time) / (time - start_time))
             : 0.;
  }



  void
  ProgressReporter::report(const unsigned int step,
                           const double       time,
                           const double       dt,
                           const unsigned int newton_iterations,
                           const unsigned int n_dofs,
                           const int          contact_pairs,
                           const unsigned int substeps)
  {
    if (!enabled)
      return;
    // The console is shared: leave its format as it was.
    const std::ios::fmtflags flags     = out.flags();
    const std::streamsize    precision = out.precision();
    out << "step " << std::setw(7) << step << "  t = " << std::setw(11)
        << std::scientific << std::setprecision(4) << time << "  dt = " << dt
        << std::defaultfloat << "  Newton " << std::setw(3) << newton_iterations
        << "  dofs " << n_dofs;
    if (contact_pairs >= 0)
      out << "  contacts " << contact_pairs;
    if (substeps > 0)
      out << "  substeps " << substeps;
    out << std::fixed << std::setprecision(1) << "  wall " << wall_time()
        << " s  left ~" << remaining(time) << " s" << std::endl;
    out.flags(flags);
    out.precision(precision);
  }



  void
  ProgressReporter::report(const unsigned int step,
                           const double       time,
                           const double       dt,
                           const unsigned int substeps)
  {
    if (!enabled)
      return;
    // The console is shared: leave its format as it was.
    const std::ios::fmtflags flags     = out.flags();
    const std::streamsize    precision = out.precision();
    out << "step " << std::setw(7) << step << "  t = " << std::setw(11)
        << std::scientific << std::setprecision(4) << time << "  dt = " << dt
        << std::defaultfloat;
    if (substeps > 0)
      out << "  substeps " << substeps;
    out << std::fixed << std::setprecision(1) << "  wall " << wall_time()
        << " s  left ~" << remaining(time) << " s" << std::endl;
    out.flags(flags);
    out.precision(precision);
  }
} // namespace bfemp
