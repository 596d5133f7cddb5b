#ifndef bfemp_io_diagnostics_writer_h
#define bfemp_io_diagnostics_writer_h

#include <bfemp/io/step_diagnostics.h>
#include <bfemp/solver/newton_solver.h>

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
    /**
     * With @p implicit, the rows end with the Newton statistics summed over
     * the steps since the previous row (iterations, line-search backtracks,
     * det F bound hits), the last residual ||p||_inf / dt, the unknowns and
     * the assembly, factorization, solve and line-search times.
     */
    DiagnosticsWriter(const std::string &path, const bool implicit = false);

    void
    write(const unsigned int          step,
          const double                time,
          const double                dt,
          const StepDiagnostics<dim> &diagnostics,
          const double                wall_time,
          const NewtonStatistics     &newton = NewtonStatistics(),
          const unsigned int          n_dofs = 0);

  private:
    std::ofstream file;
    const bool    implicit;
  };
} // namespace bfemp

#endif
