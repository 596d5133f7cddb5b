#ifndef bfemp_solver_node_blocks_h
#define bfemp_solver_node_blocks_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>

#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * Adds the dense dim x dim blocks block(i, j) between the unified nodes
   * @p nodes to @p matrix, one matrix row at a time: a sparse row add walks
   * the whole row whatever the number of entries, so a cell's (or an
   * element's) blocks summed densely first cost one walk per row. Blocks
   * outside the sparsity pattern must be zero (SparseMatrix::add with
   * elide_zero_values).
   */
  template <int dim, typename Block>
  void
  add_node_blocks(const std::vector<unsigned int> &nodes,
                  const Block                     &block,
                  SparseMatrix<double>            &matrix)
  {
    const std::size_t                                 m = nodes.size();
    thread_local std::vector<types::global_dof_index> columns;
    thread_local std::vector<double>                  values;
    columns.resize(m * dim);
    values.resize(m * dim);
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int b = 0; b < dim; ++b)
        columns[dim * j + b] = dim * nodes[j] + b;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int a = 0; a < dim; ++a)
        {
          for (unsigned int j = 0; j < m; ++j)
            {
              const Tensor<2, dim> &B = block(i, j);
              for (unsigned int b = 0; b < dim; ++b)
                values[dim * j + b] = B[a][b];
            }
          matrix.add(dim * nodes[i] + a,
                     m * dim,
                     columns.data(),
                     values.data(),
                     false,
                     true);
        }
  }
} // namespace bfemp

#endif
