// add_node_blocks(), the scatter of dense node blocks into the Hessian
// straight into the rows' storage (node_ranks, node_block_position), against
// SparseMatrix::add one entry at a time: random node patterns (cliques of
// random node sets, as the energy terms add them) in 2D and 3D, random node
// sets that couple only partly (as a cell's stencils do) and full cliques,
// random blocks including the diagonal blocks. The two matrices must agree
// to the bit, every entry added where the pattern has it and nowhere else.

#include <bfemp/solver/node_blocks.h>
#include <bfemp/solver/node_sparsity.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(20261127);

  unsigned int
  random_index(const unsigned int n)
  {
    return std::min(n - 1,
                    static_cast<unsigned int>(random_numbers.uniform(0., n)));
  }

  /** @p n distinct random nodes below @p n_nodes, ascending. */
  std::vector<unsigned int>
  random_nodes(const unsigned int n, const unsigned int n_nodes)
  {
    std::vector<unsigned int> nodes;
    while (nodes.size() < n)
      {
        const unsigned int node = random_index(n_nodes);
        if (std::find(nodes.begin(), nodes.end(), node) == nodes.end())
          nodes.push_back(node);
      }
    std::sort(nodes.begin(), nodes.end());
    return nodes;
  }

  template <int dim>
  void
  test(const unsigned int n_nodes, const unsigned int n_sets)
  {
    // sets of nodes, each with random subsets (the "stencils") that couple
    std::vector<std::vector<unsigned int>>              sets;
    std::vector<std::vector<std::vector<unsigned int>>> stencils(n_sets);
    NodeSparsity                                        node_sparsity(n_nodes);
    for (unsigned int s = 0; s < n_sets; ++s)
      {
        sets.push_back(random_nodes(4 + random_index(12), n_nodes));
        const unsigned int n_stencils = 1 + random_index(3);
        for (unsigned int k = 0; k < n_stencils; ++k)
          {
            std::vector<unsigned int> stencil;
            for (const unsigned int node : sets[s])
              if (k == 0 && s % 2 == 0 ? true
                                       : random_numbers.uniform(0., 1.) < 0.6)
                stencil.push_back(node);
            if (stencil.empty())
              stencil.push_back(sets[s][0]);
            node_sparsity.add_clique(stencil.data(), stencil.size());
            stencils[s].push_back(stencil);
          }
      }
    SparsityPattern pattern;
    node_sparsity.build(dim, pattern);
    SparseMatrix<double> fast(pattern), reference(pattern);

    unsigned int n_blocks = 0, n_partial = 0;
    for (unsigned int s = 0; s < n_sets; ++s)
      {
        const std::vector<unsigned int> &nodes = sets[s];
        const unsigned int               m     = nodes.size();
        std::vector<char>                coupled(m * m, 0);
        for (const auto &stencil : stencils[s])
          for (const unsigned int a : stencil)
            for (const unsigned int b : stencil)
              coupled[(std::lower_bound(nodes.begin(), nodes.end(), a) -
                       nodes.begin()) *
                        m +
                      (std::lower_bound(nodes.begin(), nodes.end(), b) -
                       nodes.begin())] = 1;
        std::vector<Tensor<2, dim>> blocks(m * m);
        for (auto &block : blocks)
          block = random_numbers.tensor<dim>(1.);
        const auto is_coupled = [&](const unsigned int i,
                                    const unsigned int j) {
          return coupled[i * m + j] != 0;
        };
        const auto block = [&](const unsigned int i, const unsigned int j) {
          return blocks[i * m + j];
        };
        add_node_blocks<dim>(nodes, is_coupled, block, fast);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < m; ++j)
            {
              if (!is_coupled(i, j))
                {
                  ++n_partial;
                  continue;
                }
              ++n_blocks;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  reference.add(dim * nodes[i] + a,
                                dim * nodes[j] + b,
                                block(i, j)[a][b]);
            }
      }

    unsigned int n_differing = 0, n_nonzero = 0;
    for (unsigned int row = 0; row < pattern.n_rows(); ++row)
      for (auto entry = fast.begin(row); entry != fast.end(row); ++entry)
        {
          const double expected = reference(row, entry->column());
          n_differing += entry->value() != expected ? 1 : 0;
          n_nonzero += entry->value() != 0. ? 1 : 0;
        }
    const std::string what = std::to_string(dim) + "D, " +
                             std::to_string(n_nodes) + " nodes, " +
                             std::to_string(n_sets) + " node sets";
    deallog << what << ": " << n_blocks << " coupled blocks added, "
            << n_partial << " uncoupled pairs skipped, " << n_nonzero
            << " non-zero entries of " << pattern.n_nonzero_elements()
            << std::endl;
    bfemp_tests::check(n_blocks > 0 && n_partial > 0,
                       what + ": both coupled and uncoupled pairs occur");
    bfemp_tests::check(n_differing == 0,
                       what + ": entries differing from SparseMatrix::add: " +
                         std::to_string(n_differing));

    // a block between two nodes that do not couple is refused, not written
    // past the row
    unsigned int a = 0, b = 1;
    while (pattern.exists(dim * a, dim * b))
      if (++b == n_nodes)
        b = ++a + 1;
    bool refused = false;
    try
      {
        add_node_blocks<dim>(
          {a, b},
          [](unsigned int, unsigned int) { return Tensor<2, dim>(); },
          fast);
      }
    catch (const ExceptionBase &)
      {
        refused = true;
      }
    bfemp_tests::check(refused,
                       what + ": a block outside the pattern (nodes " +
                         std::to_string(a) + ", " + std::to_string(b) +
                         ") is refused");
  }
} // namespace

int
main()
{
  bfemp_tests::initlog();
  test<2>(40, 30);
  test<2>(400, 200);
  test<3>(30, 20);
  test<3>(300, 150);
}
