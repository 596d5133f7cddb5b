#include <bfemp/base/input_error.h>
#include <bfemp/io/diagnostics_writer.h>

#include <iomanip>
#include <sstream>

namespace bfemp
{
  template <int dim>
  DiagnosticsWriter<dim>::DiagnosticsWriter(const std::string &path,
                                            const bool         implicit)
    : file(path)
    , implicit(implicit)
  {
    if (!file)
      throw SimulationError("cannot open '" + path + "' for writing");
    file << "step,time,dt,kinetic_energy,elastic_energy,gravitational_energy,"
            "total_energy";
    const char *axis[3] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      file << ",momentum_" << axis[d];
    if (dim == 2)
      file << ",angular_momentum";
    else
      file << ",angular_momentum_x,angular_momentum_y,angular_momentum_z";
    file << ",mass,min_J,max_speed,wall_time";
    if (implicit)
      file << ",newton_iterations,line_search_backtracks,step_bound_hits,"
              "residual,dofs,assembly_time,factorization_time,solve_time,"
              "line_search_time";
    file << std::endl;
  }



  template <int dim>
  void
  DiagnosticsWriter<dim>::write(const unsigned int          step,
                                const double                time,
                                const double                dt,
                                const StepDiagnostics<dim> &d,
                                const double                wall_time,
                                const NewtonStatistics     &newton,
                                const unsigned int          n_dofs)
  {
    std::ostringstream row;
    row << std::setprecision(12) << step << ',' << time << ',' << dt << ','
        << d.kinetic_energy << ',' << d.elastic_energy << ','
        << d.gravitational_energy << ',' << d.total_energy();
    for (unsigned int c = 0; c < dim; ++c)
      row << ',' << d.linear_momentum[c];
    for (unsigned int c = (dim == 2 ? 2 : 0); c < 3; ++c)
      row << ',' << d.angular_momentum[c];
    row << ',' << d.mass << ',' << d.min_J << ',' << d.max_speed << ','
        << std::setprecision(6) << wall_time;
    if (implicit)
      row << ',' << newton.iterations << ',' << newton.backtracks << ','
          << newton.bound_hits << ',' << newton.residual << ',' << n_dofs << ','
          << newton.assembly_time << ',' << newton.factorization_time << ','
          << newton.solve_time << ',' << newton.line_search_time;
    row << '\n';
    file << row.str() << std::flush;
  }



  template class DiagnosticsWriter<2>;
  template class DiagnosticsWriter<3>;
} // namespace bfemp
