#ifndef bfemp_grid_kernel_stencil_h
#define bfemp_grid_kernel_stencil_h

#include <bfemp/grid/bspline_kernel.h>
#include <bfemp/grid/lattice.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * The tensor-product kernel weights w_ip = prod_d N(xi_d - i_d), their
   * gradients grad w_ip (in 1/m) and the offsets x_i - x_p of one particle,
   * evaluated once by reinit() into fixed-size arrays that the transfer loops
   * then run over. Node a of the stencil has the lattice multi-index base +
   * (a_0, a_1, ...) with a_0 running fastest.
   */
  template <int dim, int degree>
  class KernelStencil
  {
  public:
    using Kernel                             = BSplineKernel<degree>;
    static constexpr unsigned int n_nodes_1d = Kernel::n_nodes_1d;
    static constexpr unsigned int n_nodes =
      dim == 2 ? n_nodes_1d * n_nodes_1d : n_nodes_1d * n_nodes_1d * n_nodes_1d;

    /** Evaluates weights, gradients, offsets and node indices at x. */
    DEAL_II_ALWAYS_INLINE inline void
    reinit(const Lattice<dim> &lattice, const Point<dim> &x)
    {
      double w[dim][n_nodes_1d], dw[dim][n_nodes_1d], r[dim][n_nodes_1d];
      std::array<int, dim> base;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double xi = (x[d] - lattice.origin[d]) * lattice.inverse_dx;
          base[d]         = Kernel::evaluate(xi, w[d], dw[d]);
          for (unsigned int a = 0; a < n_nodes_1d; ++a)
            {
              dw[d][a] *= lattice.inverse_dx;
              r[d][a] = (base[d] + static_cast<int>(a) - xi) * lattice.dx;
            }
        }
      const std::size_t first = lattice.node_index(base);
      unsigned int      k     = 0;
      if constexpr (dim == 2)
        for (unsigned int b = 0; b < n_nodes_1d; ++b)
          for (unsigned int a = 0; a < n_nodes_1d; ++a, ++k)
            {
              node[k]        = first + a + b * lattice.stride[1];
              weight[k]      = w[0][a] * w[1][b];
              gradient[k][0] = dw[0][a] * w[1][b];
              gradient[k][1] = w[0][a] * dw[1][b];
              offset[k][0]   = r[0][a];
              offset[k][1]   = r[1][b];
            }
      else
        for (unsigned int c = 0; c < n_nodes_1d; ++c)
          for (unsigned int b = 0; b < n_nodes_1d; ++b)
            for (unsigned int a = 0; a < n_nodes_1d; ++a, ++k)
              {
                node[k] =
                  first + a + b * lattice.stride[1] + c * lattice.stride[2];
                weight[k]      = w[0][a] * w[1][b] * w[2][c];
                gradient[k][0] = dw[0][a] * w[1][b] * w[2][c];
                gradient[k][1] = w[0][a] * dw[1][b] * w[2][c];
                gradient[k][2] = w[0][a] * w[1][b] * dw[2][c];
                offset[k][0]   = r[0][a];
                offset[k][1]   = r[1][b];
                offset[k][2]   = r[2][c];
              }
    }

    /** Calls f(node_index, w_ip, grad w_ip, x_i - x_p) for every node. */
    template <typename Function>
    inline void
    for_each_node(const Function &f) const
    {
      for (unsigned int k = 0; k < n_nodes; ++k)
        f(node[k], weight[k], gradient[k], offset[k]);
    }

    /** Lattice index of each stencil node. */
    std::size_t node[n_nodes];
    /** w_ip. */
    double weight[n_nodes];
    /** grad w_ip [1/m]. */
    Tensor<1, dim> gradient[n_nodes];
    /** x_i - x_p [m]. */
    Tensor<1, dim> offset[n_nodes];
  };
} // namespace bfemp

#endif
