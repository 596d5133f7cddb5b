#ifndef bfemp_io_diagnostics_writer_h
#define bfemp_io_diagnostics_writer_h

#include <bfemp/contact/contact_statistics.h>
#include <bfemp/io/step_diagnostics.h>
#include <bfemp/solver/newton_solver.h>

#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * diagnostics.csv: one row per diagnosed step with step, time, dt,
   * energies, linear and angular momentum, mass, min J, max speed and wall
   * time, and the particles inside level-set obstacles (and, last, the
   * substeps of a substepped macro step). Rows are written
   * whole and flushed, so the file always ends with a
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
     * the assembly, factorization, solve and line-search times. A run
     * continued from the checkpoint of step @p resume_after_step appends to
     * the file (open_csv_file()).
     */
    DiagnosticsWriter(
      const std::string                 &path,
      const bool                         implicit          = false,
      const bool                         substepped        = false,
      const std::optional<unsigned int> &resume_after_step = {});

    /**
     * Scenes with particle-mesh contact add its columns: pairs within dhat,
     * particles in contact, particles inside an FEM element (0 unless the
     * barrier failed), the least distance, the barrier energy, friction
     * pairs and updates, the accumulated friction dissipation, the CCD step
     * bound hits, partial moves of prescribed motions and the moves that
     * carried the free DoFs along (summed since the previous row), and the
     * contact force on every FEM body from every MPM body
     * (contact_force_m<m>_f<f>_<axis>).
     */
    DiagnosticsWriter(
      const std::string                 &path,
      const unsigned int                 n_mpm_bodies,
      const unsigned int                 n_fem_bodies,
      const bool                         substepped        = false,
      const std::optional<unsigned int> &resume_after_step = {});

    void
    write(const unsigned int            step,
          const double                  time,
          const double                  dt,
          const StepDiagnostics<dim>   &diagnostics,
          const double                  wall_time,
          const NewtonStatistics       &newton   = NewtonStatistics(),
          const unsigned int            n_dofs   = 0,
          const ContactStatistics<dim> &contact  = ContactStatistics<dim>(),
          const unsigned int            substeps = 0);

    /**
     * The columns that a continued run added to an existing file written by
     * an older bfemp (open_csv_file()); empty for a new file.
     */
    const std::vector<std::string> &
    columns_added_on_resume() const;

  private:
    /** The column names, comma-separated. */
    std::string
    header() const;

    std::ofstream            file;
    std::vector<std::string> added_columns;
    const bool               implicit;
    const bool               with_contact = false;
    /** A last column: the explicit substeps S of the macro step. */
    const bool   substepped   = false;
    unsigned int n_mpm_bodies = 0;
    unsigned int n_fem_bodies = 0;
  };
} // namespace bfemp

#endif
