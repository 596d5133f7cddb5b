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
   * The tensor-product kernel weights w_ip = prod_d N(xi_d - i_d) and their
   * gradients grad w_ip (in 1/m) of one particle, evaluated once and then
   * visited node by node. Node a of the stencil (0 <= a < n_nodes) has the
   * lattice multi-index base + (a_0, a_1, ...) with a_0 running fastest.
   */
  template <int dim, int degree>
  class KernelStencil
  {
  public:
    using Kernel                              = BSplineKernel<degree>;
    static constexpr unsigned int n_nodes_1d  = Kernel::n_nodes_1d;
    static constexpr unsigned int n_nodes     = dim == 2 ?
                                                  n_nodes_1d * n_nodes_1d :
                                                  n_nodes_1d * n_nodes_1d * n_nodes_1d;

    /** Evaluates the 1D factors at particle position x. */
    inline void
    reinit(const Lattice<dim> &lattice, const Point<dim> &x)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double xi = (x[d] - lattice.origin[d]) * lattice.inverse_dx;
          base[d]         = Kernel::evaluate(xi, w[d], dw[d]);
          for (unsigned int a = 0; a < n_nodes_1d; ++a)
            dw[d][a] *= lattice.inverse_dx;
        }
      first_node = lattice.node_index(base);
    }

    /** Calls f(node_index, w_ip, grad w_ip, x_i - x_p) for every node. */
    template <typename Function>
    inline void
    for_each_node(const Lattice<dim> &lattice,
                  const Point<dim>   &x,
                  Function          &&f) const
    {
      Tensor<1, dim> grad;
      Tensor<1, dim> offset;
      if constexpr (dim == 2)
        for (unsigned int b = 0; b < n_nodes_1d; ++b)
          {
            offset[1] = lattice.node_coordinate(1, base[1] + b) - x[1];
            const std::size_t row = first_node + b * lattice.stride[1];
            for (unsigned int a = 0; a < n_nodes_1d; ++a)
              {
                offset[0] = lattice.node_coordinate(0, base[0] + a) - x[0];
                grad[0]   = dw[0][a] * w[1][b];
                grad[1]   = w[0][a] * dw[1][b];
                f(row + a, w[0][a] * w[1][b], grad, offset);
              }
          }
      else
        for (unsigned int c = 0; c < n_nodes_1d; ++c)
          {
            offset[2] = lattice.node_coordinate(2, base[2] + c) - x[2];
            for (unsigned int b = 0; b < n_nodes_1d; ++b)
              {
                offset[1] = lattice.node_coordinate(1, base[1] + b) - x[1];
                const double      wbc = w[1][b] * w[2][c];
                const std::size_t row =
                  first_node + b * lattice.stride[1] + c * lattice.stride[2];
                for (unsigned int a = 0; a < n_nodes_1d; ++a)
                  {
                    offset[0] =
                      lattice.node_coordinate(0, base[0] + a) - x[0];
                    grad[0] = dw[0][a] * wbc;
                    grad[1] = w[0][a] * dw[1][b] * w[2][c];
                    grad[2] = w[0][a] * w[1][b] * dw[2][c];
                    f(row + a, w[0][a] * wbc, grad, offset);
                  }
              }
          }
    }

    /** First node of the stencil in every direction. */
    std::array<int, dim> base;
    std::size_t          first_node = 0;
    double               w[dim][n_nodes_1d];
    double               dw[dim][n_nodes_1d];
  };
} // namespace bfemp

#endif
