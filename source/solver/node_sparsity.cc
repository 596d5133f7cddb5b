#include <bfemp/solver/node_sparsity.h>

#include <deal.II/base/parallel.h>

#include <algorithm>

namespace bfemp
{
  NodeSparsity::NodeSparsity(const unsigned int n_nodes)
  {
    reinit(n_nodes);
  }



  void
  NodeSparsity::reinit(const unsigned int n_nodes)
  {
    rows.assign(n_nodes, std::vector<unsigned int>());
  }



  void
  NodeSparsity::add_clique(const unsigned int *nodes, const unsigned int n)
  {
    for (unsigned int a = 0; a < n; ++a)
      rows[nodes[a]].insert(rows[nodes[a]].end(), nodes, nodes + n);
  }



  void
  NodeSparsity::add_row_entries(const unsigned int               node,
                                const std::vector<unsigned int> &columns)
  {
    rows[node].insert(rows[node].end(), columns.begin(), columns.end());
  }



  void
  NodeSparsity::build(const unsigned int dim, SparsityPattern &pattern)
  {
    const unsigned int n_nodes = rows.size();
    parallel::apply_to_subranges(
      0u,
      n_nodes,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int i = begin; i < end; ++i)
          {
            rows[i].push_back(i);
            std::sort(rows[i].begin(), rows[i].end());
            rows[i].erase(std::unique(rows[i].begin(), rows[i].end()),
                          rows[i].end());
          }
      },
      256);

    std::vector<unsigned int> row_lengths(dim * n_nodes);
    for (unsigned int i = 0; i < n_nodes; ++i)
      for (unsigned int a = 0; a < dim; ++a)
        row_lengths[dim * i + a] = dim * rows[i].size();
    pattern.reinit(dim * n_nodes, dim * n_nodes, row_lengths);
    std::vector<types::global_dof_index> columns;
    for (unsigned int i = 0; i < n_nodes; ++i)
      {
        columns.clear();
        for (const unsigned int j : rows[i])
          for (unsigned int b = 0; b < dim; ++b)
            columns.push_back(dim * j + b);
        for (unsigned int a = 0; a < dim; ++a)
          pattern.add_entries(dim * i + a,
                              columns.begin(),
                              columns.end(),
                              true);
      }
    pattern.compress();
  }
} // namespace bfemp
