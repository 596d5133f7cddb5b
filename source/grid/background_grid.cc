#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/bspline_kernel.h>

#include <deal.II/grid/grid_generator.h>

namespace bfemp
{
  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(const GridParameters<dim> &parameters)
    : lattice_(parameters.lower_corner,
               parameters.cell_size,
               parameters.n_cells())
    , degree(parameters.kernel_degree)
    , fe_node(1)
    , fe_vector(FE_Q<dim>(1), dim)
    , dofs_node(tria)
    , dofs_vector(tria)
  {
    const auto                n = parameters.n_cells();
    std::vector<unsigned int> repetitions(n.begin(), n.end());
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              repetitions,
                                              parameters.lower_corner,
                                              parameters.upper_corner);
    // A stencil's first node is floor(xi - margin), its last that plus the
    // degree; both must exist: xi in [margin, n - margin).
    const double margin = 0.5 * (degree - 1);
    for (unsigned int d = 0; d < dim; ++d)
      {
        usable_lower[d] = lattice_.node_coordinate(d, 0) + margin * lattice_.dx;
        usable_upper[d] =
          lattice_.node_coordinate(d, n[d]) - margin * lattice_.dx;
      }
    dofs_node.distribute_dofs(fe_node);
    dofs_vector.distribute_dofs(fe_vector);

    // Lattice <-> deal.II numbering, found from vertex and cell positions.
    node_dofs.resize(lattice_.n_nodes);
    vector_dofs.resize(lattice_.n_nodes * dim);
    cells.resize(lattice_.n_cells_total());
    auto vector_cell = dofs_vector.begin_active();
    for (const auto &cell : dofs_node.active_cell_iterators())
      {
        cells[lattice_.cell_index(lattice_cell(cell))] = cell;
        for (const unsigned int v : cell->vertex_indices())
          {
            std::array<int, dim> index;
            for (unsigned int d = 0; d < dim; ++d)
              index[d] = static_cast<int>(
                std::round((cell->vertex(v)[d] - lattice_.origin[d]) *
                           lattice_.inverse_dx));
            const std::size_t node = lattice_.node_index(index);
            node_dofs[node]        = cell->vertex_dof_index(v, 0);
            for (unsigned int c = 0; c < dim; ++c)
              vector_dofs[node * dim + c] = vector_cell->vertex_dof_index(v, c);
          }
        ++vector_cell;
      }
  }



  template <int dim>
  const Lattice<dim> &
  BackgroundGrid<dim>::lattice() const
  {
    return lattice_;
  }



  template <int dim>
  unsigned int
  BackgroundGrid<dim>::kernel_degree() const
  {
    return degree;
  }



  template <int dim>
  const Triangulation<dim> &
  BackgroundGrid<dim>::triangulation() const
  {
    return tria;
  }



  template <int dim>
  const Mapping<dim> &
  BackgroundGrid<dim>::mapping() const
  {
    return cartesian_mapping;
  }



  template <int dim>
  const DoFHandler<dim> &
  BackgroundGrid<dim>::node_dof_handler() const
  {
    return dofs_node;
  }



  template <int dim>
  const DoFHandler<dim> &
  BackgroundGrid<dim>::vector_dof_handler() const
  {
    return dofs_vector;
  }



  template <int dim>
  types::global_dof_index
  BackgroundGrid<dim>::node_dof(const std::size_t node) const
  {
    return node_dofs[node];
  }



  template <int dim>
  types::global_dof_index
  BackgroundGrid<dim>::vector_dof(const std::size_t  node,
                                  const unsigned int component) const
  {
    return vector_dofs[node * dim + component];
  }



  template <int dim>
  const typename BackgroundGrid<dim>::cell_iterator &
  BackgroundGrid<dim>::cell(const std::array<int, dim> &cell) const
  {
    return cells[lattice_.cell_index(cell)];
  }



  template <int dim>
  std::array<int, dim>
  BackgroundGrid<dim>::lattice_cell(const cell_iterator &cell) const
  {
    return lattice_.cell_of(cell->center());
  }



  template <int dim>
  bool
  BackgroundGrid<dim>::stencil_inside(const Point<dim> &x) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (!(x[d] >= usable_lower[d] && x[d] < usable_upper[d]))
        return false;
    return true;
  }



  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace bfemp
