#include <bfemp/io/atomic_file.h>
#include <bfemp/io/fem_output.h>
#include <bfemp/io/vtu_flags.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/reference_cell.h>

#include <tuple>

namespace bfemp
{
  template <int dim>
  FemOutput<dim>::FemOutput(
    const std::string                                &folder,
    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies)
    : folder(folder)
    , bodies(bodies)
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      series.emplace_back(folder + "/fem_body_" + std::to_string(b) + ".pvd");
  }



  template <int dim>
  void
  FemOutput<dim>::write(const double time, const unsigned int snapshot)
  {
    for (unsigned int b = 0; b < bodies.size(); ++b)
      write_body(b, time, snapshot);
  }



  template <int dim>
  void
  FemOutput<dim>::write_body(const unsigned int b,
                             const double       time,
                             const unsigned int snapshot)
  {
    const FemBody<dim>      &body = *bodies[b];
    std::vector<std::string> names;
    auto add_names = [&](const std::string &name, const unsigned int n) {
      for (unsigned int i = 0; i < n; ++i)
        names.push_back(name);
    };
    add_names("displacement", dim);
    add_names("velocity", dim);
    add_names("cauchy_stress", dim * dim);
    for (const char *name : {"von_mises", "J", "prescribed"})
      names.push_back(name);
    using Range =
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>;
    const std::vector<Range> ranges = {
      Range(0,
            dim - 1,
            "displacement",
            DataComponentInterpretation::component_is_part_of_vector),
      Range(dim,
            2 * dim - 1,
            "velocity",
            DataComponentInterpretation::component_is_part_of_vector),
      Range(2 * dim,
            2 * dim + dim * dim - 1,
            "cauchy_stress",
            DataComponentInterpretation::component_is_part_of_tensor)};

    std::vector<bool> prescribed(body.n_nodes(), false);
    for (const unsigned int a : body.prescribed_nodes())
      prescribed[a] = true;

    // One linear simplex patch per element; deal.II's VTU writer knows the
    // simplex reference cells.
    std::vector<DataOutBase::Patch<dim, dim>> patches;
    patches.reserve(body.elements().size());
    for (unsigned int e = 0; e < body.elements().size(); ++e)
      {
        const auto &nodes = body.element_nodes()[e];
        typename SimplexElement<dim>::NodePositions x;
        for (unsigned int a = 0; a <= dim; ++a)
          x[a] = body.positions()[nodes[a]];
        const Tensor<2, dim> F = body.elements()[e].deformation_gradient(x);
        const double         J = determinant(F);
        const Tensor<2, dim> sigma =
          J > 0. ? body.material().cauchy_stress(F) : Tensor<2, dim>();

        DataOutBase::Patch<dim, dim> patch;
        patch.reference_cell       = ReferenceCells::get_simplex<dim>();
        patch.n_subdivisions       = 1;
        patch.patch_index          = patches.size();
        patch.points_are_available = false;
        patch.data.reinit(names.size(), dim + 1);
        for (unsigned int a = 0; a <= dim; ++a)
          {
            const unsigned int node = nodes[a];
            patch.vertices[a]       = x[a];
            unsigned int field      = 0;
            for (unsigned int d = 0; d < dim; ++d)
              patch.data(field++, a) =
                x[a][d] - body.mesh().rest_position(node)[d];
            for (unsigned int d = 0; d < dim; ++d)
              patch.data(field++, a) = body.velocities()[node][d];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                patch.data(field++, a) = sigma[i][j];
            patch.data(field++, a) = von_mises_stress(sigma);
            patch.data(field++, a) = J;
            patch.data(field++, a) = prescribed[node] ? 1. : 0.;
          }
        patches.push_back(std::move(patch));
      }

    const std::string name = "fem_body_" + std::to_string(b) + "_" +
                             Utilities::int_to_string(snapshot, 5) + ".vtu";
    const DataOutBase::VtkFlags flags = vtu_flags(time);
    write_file_atomically(folder + "/" + name, [&](std::ostream &out) {
      DataOutBase::write_vtu(patches, names, ranges, flags, out);
    });
    series[b].add(time, name);
  }



  template class FemOutput<2>;
  template <int dim>
  void
  FemOutput<dim>::resume(const unsigned int next_snapshot)
  {
    for (PvdSeries &s : series)
      s.resume(next_snapshot);
  }



  template class FemOutput<3>;
} // namespace bfemp
