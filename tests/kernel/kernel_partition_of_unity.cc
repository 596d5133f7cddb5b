// The consistency conditions of the tensor-product B-spline kernels that the
// transfers rely on (partition of unity and linear reproduction of the
// weights and their gradients), at random points of a lattice with a
// non-trivial origin, and at points on nodes and cell midpoints (the knots
// where the stencil changes). Also checks that KernelStencil's weights are
// the products of the 1D reference form BSplineKernel::value at the nodes
// whose flat indices it reports.

#include <bfemp/grid/kernel_stencil.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(1234);

  template <int dim, int degree>
  void
  test()
  {
    Point<dim>                    origin;
    std::array<unsigned int, dim> n_cells;
    for (unsigned int d = 0; d < dim; ++d)
      {
        origin[d]  = -0.3 + 0.17 * d;
        n_cells[d] = 10 + d;
      }
    const double       dx = 0.1;
    const Lattice<dim> lattice(origin, dx, n_cells);

    double max_sum_w = 0., max_position = 0., max_sum_grad = 0.,
           max_identity = 0., max_reference = 0., min_w = 1.;
    for (unsigned int q = 0; q < 500; ++q)
      {
        // Points well inside, so that every stencil node exists; every tenth
        // point on a node, every tenth shifted by dx/2 (the knots).
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double xi = random_numbers.uniform(3., 7.);
            x[d]            = origin[d] + dx * (q % 10 == 0 ? std::round(xi)
                                                : q % 10 == 1 ? std::round(xi) + 0.5
                                                              : xi);
          }

        KernelStencil<dim, degree> stencil;
        stencil.reinit(lattice, x);
        double         sum_w = 0.;
        Tensor<1, dim> sum_wx, sum_grad;
        Tensor<2, dim> sum_x_grad;
        stencil.for_each_node([&](const std::size_t     node,
                                  const double          w,
                                  const Tensor<1, dim> &grad_w,
                                  const Tensor<1, dim> &r) {
          const Point<dim> x_i = lattice.node_position(node);
          // the offset belongs to the node index
          max_position       = std::max(max_position, (x_i - x - r).norm());
          double w_reference = 1.;
          for (unsigned int d = 0; d < dim; ++d)
            w_reference *= BSplineKernel<degree>::value((x[d] - x_i[d]) / dx);
          max_reference = std::max(max_reference, std::abs(w - w_reference));
          min_w         = std::min(min_w, w);
          sum_w += w;
          sum_wx += w * x_i;
          sum_grad += grad_w;
          sum_x_grad += outer_product(x_i, grad_w);
        });
        max_sum_w    = std::max(max_sum_w, std::abs(sum_w - 1.));
        max_position = std::max(max_position, (sum_wx - x).norm());
        // gradients scale with 1/dx
        max_sum_grad = std::max(max_sum_grad, sum_grad.norm() * dx);
        max_identity =
          std::max(max_identity,
                   (sum_x_grad - unit_symmetric_tensor<dim>()).norm());
      }

    const std::string name =
      std::to_string(dim) + "D degree " + std::to_string(degree) + ": ";
    bfemp_tests::check_below(max_reference,
                             1e-14,
                             name + "w_ip = prod_d N(xi_d - i_d) at the "
                                    "reported nodes: largest difference");
    bfemp_tests::check(min_w >= 0.,
                       name + "w_ip >= 0: smallest w_ip " +
                         bfemp_tests::format("%.1e", min_w));
    bfemp_tests::check_below(max_sum_w,
                             1e-12,
                             name + "sum_i w_ip = 1: largest |sum - 1|");
    bfemp_tests::check_below(max_position,
                             1e-12,
                             name + "sum_i w_ip x_i = x_p (and r = x_i - x_p): "
                                    "largest distance");
    bfemp_tests::check_below(max_sum_grad,
                             1e-12,
                             name + "sum_i grad w_ip = 0: largest |sum| dx");
    bfemp_tests::check_below(max_identity,
                             1e-12,
                             name + "sum_i x_i (grad w_ip)^T = I: largest "
                                    "|sum - I|");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  test<2, 1>();
  test<2, 2>();
  test<2, 3>();
  test<3, 1>();
  test<3, 2>();
  test<3, 3>();
}
