#ifndef bfemp_grid_background_grid_h
#define bfemp_grid_background_grid_h

#include <bfemp/grid/grid_parameters.h>
#include <bfemp/grid/lattice.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_cartesian.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace bfemp
{
  /**
   * The Eulerian MPM background grid: a Cartesian deal.II Triangulation with
   * a DoFHandler whose nodes are its vertices (FE_Q(1)), plus the lattice
   * arithmetic the kernels use and the map from lattice node and cell
   * indices to deal.II's numbering.
   */
  template <int dim>
  class BackgroundGrid
  {
  public:
    using cell_iterator = typename Triangulation<dim>::active_cell_iterator;

    explicit BackgroundGrid(const GridParameters<dim> &parameters);

    const Lattice<dim> &
    lattice() const;

    unsigned int
    kernel_degree() const;

    const Triangulation<dim> &
    triangulation() const;

    const Mapping<dim> &
    mapping() const;

    /** Scalar FE_Q(1) DoFs: one per grid node. */
    const DoFHandler<dim> &
    node_dof_handler() const;

    /** FE_Q(1)^dim DoFs: dim per grid node. */
    const DoFHandler<dim> &
    vector_dof_handler() const;

    /** Scalar DoF of lattice node i. */
    types::global_dof_index
    node_dof(const std::size_t node) const;

    /** Vector DoF of component c of lattice node i. */
    types::global_dof_index
    vector_dof(const std::size_t node, const unsigned int component) const;

    /** The deal.II cell with lattice multi-index @p cell. */
    const cell_iterator &
    cell(const std::array<int, dim> &cell) const;

    /** Lattice multi-index of a deal.II cell. */
    std::array<int, dim>
    lattice_cell(const cell_iterator &cell) const;

    /**
     * True if every node of the kernel stencil of a particle at x exists,
     * i.e. the particle can exchange with the grid without losing mass.
     */
    bool
    stencil_inside(const Point<dim> &x) const;

  private:
    Lattice<dim>                         lattice_;
    unsigned int                         degree;
    Triangulation<dim>                   tria;
    MappingCartesian<dim>                cartesian_mapping;
    FE_Q<dim>                            fe_node;
    FESystem<dim>                        fe_vector;
    DoFHandler<dim>                      dofs_node;
    DoFHandler<dim>                      dofs_vector;
    std::vector<types::global_dof_index> node_dofs;
    std::vector<types::global_dof_index> vector_dofs;
    std::vector<cell_iterator>           cells;
    /** Particles must stay in [usable_lower, usable_upper). */
    Point<dim> usable_lower, usable_upper;
  };
} // namespace bfemp

#endif
