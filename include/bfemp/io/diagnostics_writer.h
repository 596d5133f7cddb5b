#ifndef bfemp_io_diagnostics_writer_h
#define bfemp_io_diagnostics_writer_h

#include <bfemp/io/step_diagnostics.h>

#include <fstream>
#include <string>

namespace bfemp
{
  /**
   * diagnostics.csv: one row per diagnosed step with step, time, dt,
   * energies, linear and angular momentum, mass, min J, max speed and wall
   * time. Rows are written whole and flushed, so the file always ends with a
   * complete row.
   */
  template <int dim>
  class DiagnosticsWriter
  {
  public:
    explicit DiagnosticsWriter(const std::string &path);

    void
    write(const unsigned int          step,
          const double                time,
          const double                dt,
          const StepDiagnostics<dim> &diagnostics,
          const double                wall_time);

  private:
    std::ofstream file;
  };
} // namespace bfemp

#endif
