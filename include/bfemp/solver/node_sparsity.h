#ifndef bfemp_solver_node_sparsity_h
#define bfemp_solver_node_sparsity_h

#include <deal.II/lac/sparsity_pattern.h>

#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * Which nodes of the unified DoF space couple in the Hessian of the
   * incremental potential. Every energy term adds its stencils (an element,
   * a particle's kernel stencil, a contact pair) as cliques of nodes; the
   * DoF-level pattern then has a full dim x dim block for every coupled node
   * pair, so the PSD blocks of projected Newton always fit.
   */
  class NodeSparsity
  {
  public:
    explicit NodeSparsity(const unsigned int n_nodes = 0);

    void
    reinit(const unsigned int n_nodes);

    /** Couples every pair of @p nodes (and each node with itself). */
    void
    add_clique(const unsigned int *nodes, const unsigned int n);

    /**
     * Row @p node couples with @p columns (must include @p node itself for
     * a diagonal). Only row @p node is touched, so different rows may be
     * filled from different threads.
     */
    void
    add_row_entries(const unsigned int               node,
                    const std::vector<unsigned int> &columns);

    /** Sorts the rows and builds the DoF pattern with dim x dim blocks. */
    void
    build(const unsigned int dim, SparsityPattern &pattern);

  private:
    std::vector<std::vector<unsigned int>> rows;
  };
} // namespace bfemp

#endif
