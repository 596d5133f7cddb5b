#include <bfemp/cmpm/element_assembly.h>
#include <bfemp/solver/node_blocks.h>

namespace bfemp
{
  template <int dim>
  CmpmElementAssembly<dim>::CmpmElementAssembly(
    const CmpmDiscretization<dim> &cmpm,
    const DofSpace<dim>           &dofs,
    const Point<dim>              &x)
    : phi(cmpm.shape_functions())
  {
    const CoarseGrid<dim>     &grid  = cmpm.coarse_grid();
    const std::array<int, dim> index = grid.element_of(x);
    element                          = grid.element_index(index);
    corner                           = grid.element_origin(index);
    AssertThrow(phi.is_active(element),
                ExcMessage("cMPM: a coarse element without shape functions "
                           "was assembled (it held no particle when they "
                           "were built)"));
    local_unknowns.resize(grid.n_element_unknowns());
    for (unsigned int I = 0; I < local_unknowns.size(); ++I)
      {
        local_unknowns[I] = dofs.grid_node(grid.unknown_node(index, I));
        if (local_unknowns[I] == DofSpace<dim>::invalid)
          continue;
        valid_unknowns.push_back(local_unknowns[I]);
        valid_local.push_back(I);
      }
  }



  template <int dim>
  void
  CmpmElementAssembly<dim>::fine_stencil(const Point<dim> &x,
                                         FineStencil      &stencil) const
  {
    phi.grid().fine_stencil(Point<dim>(x - corner), stencil);
  }



  template <int dim>
  unsigned int
  CmpmElementAssembly<dim>::n_fine() const
  {
    return phi.grid().n_fine();
  }



  template <int dim>
  void
  CmpmElementAssembly<dim>::gather(const Vector<double>        &u,
                                   std::vector<Tensor<1, dim>> &fine) const
  {
    thread_local std::vector<Tensor<1, dim>> coarse;
    coarse.assign(local_unknowns.size(), Tensor<1, dim>());
    for (unsigned int I = 0; I < coarse.size(); ++I)
      if (local_unknowns[I] != DofSpace<dim>::invalid)
        coarse[I] = DofSpace<dim>::get(u, local_unknowns[I]);
    phi.fine_values(element, coarse, fine);
  }



  template <int dim>
  void
  CmpmElementAssembly<dim>::add_forces(
    const std::vector<Tensor<1, dim>> &fine_forces,
    Vector<double>                    &gradient) const
  {
    thread_local std::vector<Tensor<1, dim>> coarse;
    phi.coarse_forces(element, fine_forces, coarse);
    for (unsigned int I = 0; I < coarse.size(); ++I)
      if (local_unknowns[I] != DofSpace<dim>::invalid)
        for (unsigned int c = 0; c < dim; ++c)
          gradient[dim * local_unknowns[I] + c] += coarse[I][c];
  }



  template <int dim>
  void
  CmpmElementAssembly<dim>::add_stiffness(
    const std::vector<unsigned int>   &fine_nodes,
    const std::vector<Tensor<2, dim>> &upper,
    const std::vector<char>           &coupled,
    SparseMatrix<double>              &hessian) const
  {
    thread_local std::vector<Tensor<2, dim>> coarse;
    phi.condense(element, fine_nodes, upper, coupled, coarse);
    const std::size_t r = local_unknowns.size();
    add_node_blocks<dim>(
      valid_unknowns,
      [&](const unsigned int i,
          const unsigned int j) -> const Tensor<2, dim> & {
        return coarse[valid_local[i] * r + valid_local[j]];
      },
      hessian);
  }



  template <int dim>
  const std::vector<unsigned int> &
  CmpmElementAssembly<dim>::unknowns() const
  {
    return valid_unknowns;
  }



  template class CmpmElementAssembly<2>;
  template class CmpmElementAssembly<3>;
} // namespace bfemp
