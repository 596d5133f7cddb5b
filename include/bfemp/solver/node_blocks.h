#ifndef bfemp_solver_node_blocks_h
#define bfemp_solver_node_blocks_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The ranks of the nodes @p nodes (ascending) among the nodes that node
   * @p node couples with in a pattern of full dim x dim node blocks
   * (NodeSparsity::build): rank(j) is the index of node j in node @p node's
   * coupled nodes in ascending order, numbers::invalid_unsigned_int where
   * j does not couple. Returns the rank of @p node itself.
   *
   * deal.II keeps a square matrix's diagonal first in each row and the
   * other columns ascending, so the dim rows of a node hold the same
   * columns and differ only in where their diagonal went; the ranks locate
   * every column of every row of the node (node_block_position). One walk
   * along the node's first row finds them all.
   */
  template <int dim>
  unsigned int
  node_ranks(const SparsityPattern           &pattern,
             const unsigned int               node,
             const std::vector<unsigned int> &nodes,
             std::vector<unsigned int>       &ranks)
  {
    const types::global_dof_index row    = dim * node;
    const unsigned int            length = pattern.row_length(row);
    // columns below the diagonal: stored at 1..below, sorted position - 1
    unsigned int low = 1, high = length;
    while (low < high)
      {
        const unsigned int mid = (low + high) / 2;
        if (pattern.column_number(row, mid) < row)
          low = mid + 1;
        else
          high = mid;
      }
    const unsigned int below = low - 1;
    ranks.resize(nodes.size());
    unsigned int p = 1;
    for (unsigned int j = 0; j < nodes.size(); ++j)
      {
        const types::global_dof_index column = dim * nodes[j];
        ranks[j]                             = numbers::invalid_unsigned_int;
        if (column == row)
          {
            ranks[j] = below / dim;
            continue;
          }
        while (p < length && pattern.column_number(row, p) < column)
          ++p;
        if (p < length && pattern.column_number(row, p) == column)
          ranks[j] = (column < row ? p - 1 : p) / dim;
      }
    return below / dim;
  }



  /** Where column dim rank_j + b of the sorted columns of a node's row
   *  with sorted diagonal index @p diagonal (dim rank_i + a) is stored. */
  inline unsigned int
  node_block_position(const unsigned int sorted, const unsigned int diagonal)
  {
    return sorted == diagonal ? 0 : (sorted < diagonal ? sorted + 1 : sorted);
  }



  /**
   * Adds the dense dim x dim blocks block(i, j) between the unified nodes
   * @p nodes (ascending) for which coupled(i, j) holds to @p matrix, whose
   * pattern must have them (NodeSparsity::build). The positions in the
   * matrix's rows come from one walk per node (node_ranks) and the values
   * are added straight into the row's storage: a sparse row add per DoF row
   * walked the whole row for each of them, the dominant cost of the 3D MPM
   * Hessian. Each entry gets one addition per call, in the same order as a
   * row add would, so the sums are the same to the bit.
   */
  template <int dim, typename Coupled, typename Block>
  void
  add_node_blocks(const std::vector<unsigned int> &nodes,
                  const Coupled                   &coupled,
                  const Block                     &block,
                  SparseMatrix<double>            &matrix)
  {
    Assert(std::is_sorted(nodes.begin(), nodes.end()),
           ExcMessage("add_node_blocks needs the nodes in ascending order"));
    const SparsityPattern &pattern = matrix.get_sparsity_pattern();
    thread_local std::vector<unsigned int> ranks;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const unsigned int rank_i =
          node_ranks<dim>(pattern, nodes[i], nodes, ranks);
        double *rows[dim];
        for (unsigned int a = 0; a < dim; ++a)
          rows[a] = &matrix.diag_element(dim * nodes[i] + a);
        for (unsigned int j = 0; j < nodes.size(); ++j)
          {
            if (!coupled(i, j))
              continue;
            // checked in every build: a block outside the pattern would
            // otherwise be written past the row
            AssertThrow(ranks[j] != numbers::invalid_unsigned_int,
                        ExcMessage("node block outside the Hessian's pattern "
                                   "(or nodes not in ascending order)"));
            const Tensor<2, dim> B = block(i, j);
            if (j == i)
              {
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = 0; b < dim; ++b)
                    rows[a][node_block_position(dim * rank_i + b,
                                                dim * rank_i + a)] += B[a][b];
                continue;
              }
            // another node's columns: contiguous, one further on in rows
            // whose diagonal (stored first) sorts after them
            const unsigned int first =
              dim * ranks[j] + (ranks[j] < rank_i ? 1 : 0);
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                {
                  Assert(pattern.column_number(dim * nodes[i] + a, first + b) ==
                           dim * nodes[j] + b,
                         ExcInternalError());
                  rows[a][first + b] += B[a][b];
                }
          }
      }
  }



  /** add_node_blocks() for blocks between all pairs of @p nodes. */
  template <int dim, typename Block>
  void
  add_node_blocks(const std::vector<unsigned int> &nodes,
                  const Block                     &block,
                  SparseMatrix<double>            &matrix)
  {
    add_node_blocks<dim>(
      nodes,
      [](unsigned int, unsigned int) { return true; },
      block,
      matrix);
  }
} // namespace bfemp

#endif
