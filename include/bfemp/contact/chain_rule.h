#ifndef bfemp_contact_chain_rule_h
#define bfemp_contact_chain_rule_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The chain rule of BFEMP eq. 29 for one contact stencil: the local
   * coordinates of the stencil (blocks of dim: the particle's position,
   * the FEM nodes' positions, or one relative displacement for friction)
   * depend linearly on the unified unknowns,
   *   x_b = sum_{j with block b} F_j u_j,
   * with F_j = c_j I for B-spline grid nodes (c_j = w_jq) and FEM nodes
   * (c_j = 1, or -w_a in the friction's relative displacement), and F_j =
   * Phi_j(x_q) for cMPM's coarse nodes (seed 002, matrix-valued). The
   * barrier and friction terms state their local gradient and Hessian and
   * this class carries them to the unknowns, F_j^T g_b and F_i^T H_bb' F_j,
   * so that both kinds of MPM discretization share one contact assembly.
   *
   * While every factor is scalar the arithmetic is the scalar one (c_i c_j
   * H), bit for bit what it was before cMPM joined.
   */
  template <int dim>
  class ChainRule
  {
  public:
    void
    clear();

    /** Unknown node @p node enters block @p block with factor c I. */
    void
    add(const unsigned int node, const unsigned int block, const double c);

    /** Unknown node @p node enters block @p block with factor F. */
    void
    add(const unsigned int    node,
        const unsigned int    block,
        const Tensor<2, dim> &F);

    unsigned int
    size() const;

    const std::vector<unsigned int> &
    nodes() const;

    /** F_j^T g: the share of unknown j of the local gradient g. */
    Tensor<1, dim>
    pull_back(const unsigned int j, const Tensor<1, dim> &g) const;

    /**
     * gradient_j += F_j^T g_{b(j)} for every unknown j, with
     * local_gradient(b) giving g_b (scaled as the caller wants it).
     */
    template <typename LocalGradient>
    void
    add_gradient(const LocalGradient &local_gradient,
                 Vector<double>      &gradient) const;

    /**
     * Adds scale F_i^T H_{b(i) b(j)} F_j for every pair of unknowns, with
     * local_hessian(row, column) the entries of H in local coordinates
     * (dim b + component). Rows are added with their columns in increasing
     * order, as SparseMatrix::add is fastest with.
     */
    template <typename LocalHessian>
    void
    add_hessian(const LocalHessian   &local_hessian,
                const double          scale,
                SparseMatrix<double> &hessian) const;

  private:
    std::vector<unsigned int>   node_list;
    std::vector<unsigned int>   blocks;
    std::vector<double>         scalars;
    std::vector<Tensor<2, dim>> matrices;
    /** Whether some factor is a matrix: then every factor is in matrices. */
    bool matrix_valued = false;

    /** Scratch of add_hessian. */
    mutable std::vector<unsigned int>            order;
    mutable std::vector<types::global_dof_index> columns;
    mutable std::vector<double>                  values;
    mutable std::vector<Tensor<1, dim>>          row_blocks;
  };



  template <int dim>
  template <typename LocalGradient>
  void
  ChainRule<dim>::add_gradient(const LocalGradient &local_gradient,
                               Vector<double>      &gradient) const
  {
    for (unsigned int j = 0; j < node_list.size(); ++j)
      {
        const Tensor<1, dim> g = pull_back(j, local_gradient(blocks[j]));
        for (unsigned int d = 0; d < dim; ++d)
          gradient[dim * node_list[j] + d] += g[d];
      }
  }



  template <int dim>
  template <typename LocalHessian>
  void
  ChainRule<dim>::add_hessian(const LocalHessian   &local_hessian,
                              const double          scale,
                              SparseMatrix<double> &hessian) const
  {
    const unsigned int n = node_list.size();
    order.resize(n);
    for (unsigned int j = 0; j < n; ++j)
      order[j] = j;
    std::sort(order.begin(),
              order.end(),
              [&](const unsigned int a, const unsigned int b) {
                return node_list[a] < node_list[b];
              });
    columns.resize(dim * n);
    values.resize(dim * n);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int d = 0; d < dim; ++d)
        columns[dim * j + d] = dim * node_list[order[j]] + d;
    unsigned int n_blocks = 0;
    for (const unsigned int b : blocks)
      n_blocks = std::max(n_blocks, b + 1);
    row_blocks.resize(n_blocks);

    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int r = 0; r < dim; ++r)
        {
          if (!matrix_valued)
            for (unsigned int j = 0; j < n; ++j)
              for (unsigned int c = 0; c < dim; ++c)
                values[dim * j + c] = scale * scalars[i] * scalars[order[j]] *
                                      local_hessian(dim * blocks[i] + r,
                                                    dim * blocks[order[j]] + c);
          else
            {
              // row r of F_i^T H_{b(i) b}: sum_s F_i[s][r] H(b(i) s, b t)
              for (unsigned int b = 0; b < n_blocks; ++b)
                for (unsigned int t = 0; t < dim; ++t)
                  {
                    double sum = 0.;
                    for (unsigned int s = 0; s < dim; ++s)
                      sum += matrices[i][s][r] *
                             local_hessian(dim * blocks[i] + s, dim * b + t);
                    row_blocks[b][t] = sum;
                  }
              for (unsigned int j = 0; j < n; ++j)
                {
                  const Tensor<2, dim> &F_j = matrices[order[j]];
                  const Tensor<1, dim> &R   = row_blocks[blocks[order[j]]];
                  for (unsigned int c = 0; c < dim; ++c)
                    {
                      double sum = 0.;
                      for (unsigned int t = 0; t < dim; ++t)
                        sum += R[t] * F_j[t][c];
                      values[dim * j + c] = scale * sum;
                    }
                }
            }
          hessian.add(dim * node_list[i] + r,
                      dim * n,
                      columns.data(),
                      values.data(),
                      false,
                      true);
        }
  }
} // namespace bfemp

#endif
