#include <bfemp/io/atomic_file.h>
#include <bfemp/io/grid_output.h>
#include <bfemp/io/vtu_flags.h>

#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>

namespace bfemp
{
  template <int dim>
  GridOutput<dim>::GridOutput(const std::string         &folder,
                              const BackgroundGrid<dim> &grid)
    : folder(folder)
    , grid(grid)
    , series(folder + "/grid.pvd")
  {}



  template <int dim>
  void
  GridOutput<dim>::write(const GridState<dim> &state,
                         const double          time,
                         const unsigned int    snapshot)
  {
    // Before the first step no node has mass: there is no active grid, and
    // deal.II would write a VTU without a Points element, which VTK's
    // readers reject. The series starts at the first step's snapshot.
    if (std::none_of(state.mass.begin(), state.mass.end(), [](const double m) {
          return m > 0.;
        }))
      return;

    Vector<double> mass(grid.node_dof_handler().n_dofs());
    Vector<double> velocity(grid.vector_dof_handler().n_dofs());
    for (std::size_t node = 0; node < state.mass.size(); ++node)
      {
        mass[grid.node_dof(node)] = state.mass[node];
        for (unsigned int c = 0; c < dim; ++c)
          velocity[grid.vector_dof(node, c)] = state.new_velocity[node][c];
      }

    using cell_iterator = typename Triangulation<dim>::cell_iterator;
    // Masses are indexed by DoF, so go through the DoFHandler's cells.
    const auto has_mass = [&](const cell_iterator &cell) {
      const typename DoFHandler<dim>::active_cell_iterator dof_cell(
        &grid.triangulation(),
        cell->level(),
        cell->index(),
        &grid.node_dof_handler());
      for (const unsigned int v : dof_cell->vertex_indices())
        if (mass[dof_cell->vertex_dof_index(v, 0)] > 0.)
          return true;
      return false;
    };
    DataOut<dim> data_out;
    data_out.set_cell_selection(
      [&](const Triangulation<dim> &tria) {
        for (auto cell = tria.begin_active(); cell != tria.end(); ++cell)
          if (has_mass(cell))
            return cell_iterator(cell);
        return cell_iterator(tria.end());
      },
      [&](const Triangulation<dim> &tria, const cell_iterator &previous) {
        typename Triangulation<dim>::active_cell_iterator cell(previous);
        for (++cell; cell != tria.end(); ++cell)
          if (has_mass(cell))
            return cell_iterator(cell);
        return cell_iterator(tria.end());
      });
    data_out.add_data_vector(grid.node_dof_handler(), mass, "mass");
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_kind(dim,
                  DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(grid.vector_dof_handler(),
                             velocity,
                             std::vector<std::string>(dim, "velocity"),
                             vector_kind);
    data_out.build_patches();

    const std::string name =
      "grid_" + Utilities::int_to_string(snapshot, 5) + ".vtu";
    const DataOutBase::VtkFlags flags = vtu_flags(time);
    data_out.set_flags(flags);
    write_file_atomically(folder + "/" + name,
                          [&](std::ostream &out) { data_out.write_vtu(out); });
    series.add(time, name);
  }



  template class GridOutput<2>;
  template <int dim>
  void
  GridOutput<dim>::resume(const unsigned int next_snapshot)
  {
    series.resume(next_snapshot);
  }



  template class GridOutput<3>;
} // namespace bfemp
