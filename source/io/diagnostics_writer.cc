#include <bfemp/base/input_error.h>
#include <bfemp/io/csv_file.h>
#include <bfemp/io/diagnostics_writer.h>

#include <iomanip>
#include <sstream>

namespace bfemp
{
  template <int dim>
  DiagnosticsWriter<dim>::DiagnosticsWriter(
    const std::string                 &path,
    const bool                         implicit,
    const bool                         substepped,
    const std::optional<unsigned int> &resume_after_step)
    : implicit(implicit)
    , substepped(substepped)
  {
    added_columns = open_csv_file(file, path, header(), resume_after_step);
  }



  template <int dim>
  DiagnosticsWriter<dim>::DiagnosticsWriter(
    const std::string                 &path,
    const unsigned int                 n_mpm,
    const unsigned int                 n_fem,
    const bool                         substepped,
    const std::optional<unsigned int> &resume_after_step)
    : implicit(true)
    , with_contact(true)
    , substepped(substepped)
    , n_mpm_bodies(n_mpm)
    , n_fem_bodies(n_fem)
  {
    added_columns = open_csv_file(file, path, header(), resume_after_step);
  }



  template <int dim>
  const std::vector<std::string> &
  DiagnosticsWriter<dim>::columns_added_on_resume() const
  {
    return added_columns;
  }



  template <int dim>
  std::string
  DiagnosticsWriter<dim>::header() const
  {
    std::ostringstream file;
    file << "step,time,dt,kinetic_energy,elastic_energy,gravitational_energy,"
            "total_energy,affine_kinetic_energy";
    const char *axis[3] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      file << ",momentum_" << axis[d];
    if (dim == 2)
      file << ",angular_momentum";
    else
      file << ",angular_momentum_x,angular_momentum_y,angular_momentum_z";
    file << ",mass,min_J,max_speed,wall_time,particles_in_level_sets";
    if (implicit)
      file << ",newton_iterations,line_search_backtracks,step_bound_hits,"
              "residual,dofs,assembly_time,factorization_time,solve_time,"
              "line_search_time,projected_hessians,factorizations,"
              "modified_newton_iterations";
    if (with_contact)
      {
        file << ",contact_pairs,contact_particles,particles_in_fem,"
                "min_distance,"
                "barrier_energy,friction_pairs,friction_updates,"
                "friction_dissipation,ccd_bound_hits,partial_constraint_moves,"
                "carried_constraint_moves";
        for (unsigned int m = 0; m < n_mpm_bodies; ++m)
          for (unsigned int f = 0; f < n_fem_bodies; ++f)
            for (unsigned int d = 0; d < dim; ++d)
              file << ",contact_force_m" << m << "_f" << f << '_' << axis[d];
      }
    if (substepped)
      file << ",substeps";
    return file.str();
  }



  template <int dim>
  void
  DiagnosticsWriter<dim>::write(const unsigned int            step,
                                const double                  time,
                                const double                  dt,
                                const StepDiagnostics<dim>   &d,
                                const double                  wall_time,
                                const NewtonStatistics       &newton,
                                const unsigned int            n_dofs,
                                const ContactStatistics<dim> &contact,
                                const unsigned int            substeps)
  {
    std::ostringstream row;
    row << std::setprecision(12) << step << ',' << time << ',' << dt << ','
        << d.kinetic_energy << ',' << d.elastic_energy << ','
        << d.gravitational_energy << ',' << d.total_energy() << ','
        << d.affine_kinetic_energy;
    for (unsigned int c = 0; c < dim; ++c)
      row << ',' << d.linear_momentum[c];
    for (unsigned int c = (dim == 2 ? 2 : 0); c < 3; ++c)
      row << ',' << d.angular_momentum[c];
    row << ',' << d.mass << ',' << d.min_J << ',' << d.max_speed << ','
        << std::setprecision(6) << wall_time << ','
        << d.particles_in_level_sets;
    if (implicit)
      row << ',' << newton.iterations << ',' << newton.backtracks << ','
          << newton.bound_hits << ',' << newton.residual << ',' << n_dofs << ','
          << newton.assembly_time << ',' << newton.factorization_time << ','
          << newton.solve_time << ',' << newton.line_search_time << ','
          << newton.projected_hessians << ',' << newton.factorizations << ','
          << newton.modified_iterations;
    if (with_contact)
      {
        row << std::setprecision(12) << ',' << contact.pairs << ','
            << contact.particles << ',' << contact.particles_inside << ','
            << contact.minimum_distance << ',' << contact.barrier_energy << ','
            << contact.friction_pairs << ',' << contact.friction_updates << ','
            << contact.accumulated_dissipation << ',' << newton.ccd_bound_hits
            << ',' << newton.partial_constraint_moves << ','
            << newton.carried_constraint_moves;
        for (unsigned int m = 0; m < n_mpm_bodies; ++m)
          for (unsigned int f = 0; f < n_fem_bodies; ++f)
            {
              const auto     entry = contact.force.find({m, f});
              Tensor<1, dim> force;
              if (entry != contact.force.end())
                force = entry->second;
              for (unsigned int d = 0; d < dim; ++d)
                row << ',' << force[d];
            }
      }
    if (substepped)
      row << ',' << substeps;
    row << '\n';
    file << row.str() << std::flush;
  }



  template class DiagnosticsWriter<2>;
  template class DiagnosticsWriter<3>;
} // namespace bfemp
