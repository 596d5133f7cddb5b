#include <bfemp/io/atomic_file.h>
#include <bfemp/io/coarse_grid_output.h>
#include <bfemp/io/vtu_flags.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <tuple>

namespace bfemp
{
  template <int dim>
  CoarseGridOutput<dim>::CoarseGridOutput(const std::string             &folder,
                                          const CmpmDiscretization<dim> &cmpm)
    : folder(folder)
    , cmpm(cmpm)
    , series(folder + "/coarse_grid.pvd")
  {}



  template <int dim>
  std::vector<DataOutBase::Patch<dim, dim>>
  CoarseGridOutput<dim>::build_patches(const GridState<dim> &state) const
  {
    const CoarseGrid<dim>              &grid  = cmpm.coarse_grid();
    const CoarsenedShapeFunctions<dim> &phi   = cmpm.shape_functions();
    const unsigned int                  spans = grid.n_fine_1d() - 2;
    const double                        H     = grid.element_size();
    const unsigned int n_rows = 2 * dim + 1; // displacement, velocity, element
    unsigned int       n_points = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_points *= spans + 1;

    std::vector<DataOutBase::Patch<dim, dim>> patches;
    std::vector<CoarseShapeValue<dim>>        values;
    for (std::size_t e = 0; e < grid.n_elements_total(); ++e)
      {
        if (!phi.is_active(e))
          continue;
        const std::array<int, dim>   index  = grid.element_multi_index(e);
        const Point<dim>             corner = grid.element_origin(index);
        DataOutBase::Patch<dim, dim> patch;
        for (const unsigned int v : GeometryInfo<dim>::vertex_indices())
          {
            patch.vertices[v] = corner;
            for (unsigned int d = 0; d < dim; ++d)
              if (v & (1u << d))
                patch.vertices[v][d] += H;
          }
        patch.reference_cell = ReferenceCells::get_hypercube<dim>();
        patch.n_subdivisions = spans;
        patch.patch_index    = patches.size();
        patch.data.reinit(n_rows, n_points);
        // patch points run lexicographically, direction 0 fastest
        for (unsigned int point = 0; point < n_points; ++point)
          {
            Point<dim>   x    = corner;
            unsigned int rest = point;
            for (unsigned int d = 0; d < dim; ++d)
              {
                x[d] += H * (rest % (spans + 1)) / spans;
                rest /= spans + 1;
              }
            phi.evaluate(index, x, values);
            Tensor<1, dim> u, velocity;
            for (const CoarseShapeValue<dim> &value : values)
              {
                u += value.value * state.displacement[value.node];
                velocity += value.value * state.new_velocity[value.node];
              }
            for (unsigned int d = 0; d < dim; ++d)
              {
                patch.data(d, point)       = u[d];
                patch.data(dim + d, point) = velocity[d];
              }
            patch.data(2 * dim, point) = e;
          }
        patches.push_back(std::move(patch));
      }
    return patches;
  }



  template <int dim>
  void
  CoarseGridOutput<dim>::write(const GridState<dim> &state,
                               const double          time,
                               const unsigned int    snapshot)
  {
    // Before the first step no element is active (and a VTU without points
    // is one VTK's readers reject): the series starts with the first step.
    if (state.displacement.empty())
      return;
    const std::vector<DataOutBase::Patch<dim, dim>> patches =
      build_patches(state);
    if (patches.empty())
      return;

    std::vector<std::string> names(dim, "displacement");
    names.resize(2 * dim, "velocity");
    names.push_back("element");
    const std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
                                vectors = {{0,
                                            dim - 1,
                                            "displacement",
                                            DataComponentInterpretation::component_is_part_of_vector},
                                           {dim,
                                            2 * dim - 1,
                                            "velocity",
                                            DataComponentInterpretation::component_is_part_of_vector}};
    const DataOutBase::VtkFlags flags   = vtu_flags(time);

    const std::string name =
      "coarse_grid_" + Utilities::int_to_string(snapshot, 5) + ".vtu";
    write_file_atomically(folder + "/" + name, [&](std::ostream &out) {
      DataOutBase::write_vtu(patches, names, vectors, flags, out);
    });
    series.add(time, name);
  }



  template <int dim>
  void
  CoarseGridOutput<dim>::resume(const unsigned int next_snapshot)
  {
    series.resume(next_snapshot);
  }



  template class CoarseGridOutput<2>;
  template class CoarseGridOutput<3>;
} // namespace bfemp
