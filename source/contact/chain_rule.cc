#include <bfemp/contact/chain_rule.h>

namespace bfemp
{
  template <int dim>
  void
  ChainRule<dim>::clear()
  {
    node_list.clear();
    blocks.clear();
    scalars.clear();
    matrices.clear();
    matrix_valued = false;
  }



  template <int dim>
  void
  ChainRule<dim>::add(const unsigned int node,
                      const unsigned int block,
                      const double       c)
  {
    node_list.push_back(node);
    blocks.push_back(block);
    if (matrix_valued)
      matrices.push_back(c * unit_symmetric_tensor<dim>());
    else
      scalars.push_back(c);
  }



  template <int dim>
  void
  ChainRule<dim>::add(const unsigned int    node,
                      const unsigned int    block,
                      const Tensor<2, dim> &F)
  {
    if (!matrix_valued)
      {
        // from now on every factor is a matrix
        for (const double c : scalars)
          matrices.push_back(c * unit_symmetric_tensor<dim>());
        scalars.clear();
        matrix_valued = true;
      }
    node_list.push_back(node);
    blocks.push_back(block);
    matrices.push_back(F);
  }



  template <int dim>
  unsigned int
  ChainRule<dim>::size() const
  {
    return node_list.size();
  }



  template <int dim>
  const std::vector<unsigned int> &
  ChainRule<dim>::nodes() const
  {
    return node_list;
  }



  template <int dim>
  Tensor<1, dim>
  ChainRule<dim>::pull_back(const unsigned int j, const Tensor<1, dim> &g) const
  {
    if (!matrix_valued)
      return scalars[j] * g;
    return transpose(matrices[j]) * g;
  }



  template class ChainRule<2>;
  template class ChainRule<3>;
} // namespace bfemp
