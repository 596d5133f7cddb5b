#include <bfemp/solver/dof_space.h>

namespace bfemp
{
  template <int dim>
  void
  DofSpace<dim>::reinit(const std::vector<unsigned int> &fem_nodes_per_body,
                        const std::vector<double>       &grid_mass)
  {
    const std::vector<unsigned int> old_fem_offsets = std::move(fem_offsets);
    const std::vector<std::size_t>  old_grid_to_lattice =
      std::move(grid_to_lattice);
    const unsigned int old_n_fem = n_fem;
    fem_offsets.clear();
    n_fem = 0;
    for (const unsigned int n : fem_nodes_per_body)
      {
        fem_offsets.push_back(n_fem);
        n_fem += n;
      }
    lattice_to_node.assign(grid_mass.size(), invalid);
    grid_to_lattice.clear();
    for (std::size_t i = 0; i < grid_mass.size(); ++i)
      if (grid_mass[i] > 0.)
        {
          lattice_to_node[i] = n_fem + grid_to_lattice.size();
          grid_to_lattice.push_back(i);
        }
    constraint_list.clear();
    node_constraint.assign(n_nodes(), invalid);
    if (n_fem != old_n_fem || fem_offsets != old_fem_offsets ||
        grid_to_lattice != old_grid_to_lattice)
      ++numbering_revision;
  }



  template <int dim>
  void
  DofSpace<dim>::constrain(const unsigned int    node,
                           const Tensor<2, dim> &free_projector,
                           const Tensor<1, dim> &target)
  {
    Assert(node < n_nodes(), ExcIndexRange(node, 0, n_nodes()));
    if (node_constraint[node] == invalid)
      {
        node_constraint[node] = constraint_list.size();
        constraint_list.push_back({node, free_projector, target});
      }
    else
      {
        // A second condition on the same node (a corner): the node keeps
        // only the directions both leave free. Composing the projectors is
        // exact for the orthogonal normals of grid walls.
        Constraint &c = constraint_list[node_constraint[node]];
        c.target = c.target + (unit_symmetric_tensor<dim>() - free_projector) *
                                (target - c.target);
        c.free_projector = free_projector * c.free_projector * free_projector;
      }
  }



  template <int dim>
  void
  DofSpace<dim>::project(Vector<double> &v) const
  {
    for (const Constraint &c : constraint_list)
      set(v, c.node, c.free_projector * get(v, c.node));
  }



  template <int dim>
  void
  DofSpace<dim>::impose(Vector<double> &u) const
  {
    for (const Constraint &c : constraint_list)
      {
        const Tensor<1, dim> free = c.free_projector * get(u, c.node);
        set(u, c.node, free + c.target - c.free_projector * c.target);
      }
  }



  template class DofSpace<2>;
  template class DofSpace<3>;
} // namespace bfemp
