#include <bfemp/base/input_error.h>
#include <bfemp/io/body_diagnostics_writer.h>
#include <bfemp/io/csv_file.h>

#include <iomanip>
#include <sstream>

namespace bfemp
{
  namespace
  {
    void
    write_body_header(std::ostream &out, const std::string &prefix, int dim)
    {
      const char *axis[3] = {"x", "y", "z"};
      out << ',' << prefix << "_mass";
      for (int d = 0; d < dim; ++d)
        out << ',' << prefix << "_com_" << axis[d];
      for (int d = 0; d < dim; ++d)
        out << ',' << prefix << "_com_velocity_" << axis[d];
      out << ',' << prefix << "_kinetic_energy," << prefix << "_elastic_energy";
    }



    template <int dim>
    void
    write_body(std::ostream &out, const StepDiagnostics<dim> &d)
    {
      const Point<dim>     com      = d.center_of_mass();
      const Tensor<1, dim> velocity = d.center_of_mass_velocity();
      out << ',' << d.mass;
      for (unsigned int c = 0; c < dim; ++c)
        out << ',' << com[c];
      for (unsigned int c = 0; c < dim; ++c)
        out << ',' << velocity[c];
      out << ',' << d.kinetic_energy << ',' << d.elastic_energy;
    }
  } // namespace



  template <int dim>
  BodyDiagnosticsWriter<dim>::BodyDiagnosticsWriter(
    const std::string                 &path,
    const unsigned int                 n_mpm_bodies,
    const unsigned int                 n_fem_bodies,
    const std::optional<unsigned int> &resume_after_step)
  {
    std::ostringstream header;
    header << "step,time";
    for (unsigned int m = 0; m < n_mpm_bodies; ++m)
      write_body_header(header, "mpm" + std::to_string(m), dim);
    for (unsigned int f = 0; f < n_fem_bodies; ++f)
      write_body_header(header, "fem" + std::to_string(f), dim);
    added_columns = open_csv_file(file, path, header.str(), resume_after_step);
  }



  template <int dim>
  const std::vector<std::string> &
  BodyDiagnosticsWriter<dim>::columns_added_on_resume() const
  {
    return added_columns;
  }



  template <int dim>
  void
  BodyDiagnosticsWriter<dim>::write(
    const unsigned int                       step,
    const double                             time,
    const std::vector<StepDiagnostics<dim>> &mpm,
    const std::vector<StepDiagnostics<dim>> &fem)
  {
    std::ostringstream row;
    row << std::setprecision(15) << step << ',' << time;
    for (const auto &d : mpm)
      write_body(row, d);
    for (const auto &d : fem)
      write_body(row, d);
    row << '\n';
    file << row.str() << std::flush;
  }



  template class BodyDiagnosticsWriter<2>;
  template class BodyDiagnosticsWriter<3>;
} // namespace bfemp
