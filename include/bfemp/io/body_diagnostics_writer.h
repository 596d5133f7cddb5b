#ifndef bfemp_io_body_diagnostics_writer_h
#define bfemp_io_body_diagnostics_writer_h

#include <bfemp/io/step_diagnostics.h>

#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * bodies.csv: one row per diagnosed step with, for every MPM body m and
   * every FEM body f, the mass, the centre of mass, its velocity (momentum /
   * mass), the kinetic and the elastic energy (columns mpm<m>_... and
   * fem<f>_...). The validation scenes read the quantities the BFEMP paper
   * plots per body from it (energies of each ring, the centre-of-mass motion
   * of a sliding box, the centre-of-mass height of a stack). Rows are
   * written whole and flushed.
   */
  template <int dim>
  class BodyDiagnosticsWriter
  {
  public:
    /** @p resume_after_step: see open_csv_file(). */
    BodyDiagnosticsWriter(
      const std::string                 &path,
      const unsigned int                 n_mpm_bodies,
      const unsigned int                 n_fem_bodies,
      const std::optional<unsigned int> &resume_after_step = {});

    /** @p mpm and @p fem hold one measurement per body, in body order. */
    void
    write(const unsigned int                       step,
          const double                             time,
          const std::vector<StepDiagnostics<dim>> &mpm,
          const std::vector<StepDiagnostics<dim>> &fem);

    /** See DiagnosticsWriter::columns_added_on_resume(). */
    const std::vector<std::string> &
    columns_added_on_resume() const;

  private:
    std::ofstream            file;
    std::vector<std::string> added_columns;
  };
} // namespace bfemp

#endif
