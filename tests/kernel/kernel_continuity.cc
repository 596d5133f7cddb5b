// The 1D B-spline kernels: the stencil evaluation BSplineKernel::evaluate
// against the reference form BSplineKernel::value (including the support),
// its derivative against central finite differences, and the smoothness
// class at the knots. For the basis function N_j of one node, seen through
// evaluate() (which switches stencils exactly at the knots), the jumps of
// N_j, N_j' and N_j'' (one-sided finite differences of N_j') are measured:
// degree 1 is C0, degree 2 C1, degree 3 C2.

#include <bfemp/grid/bspline_kernel.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(4321);

  /** N_j(xi) (derivative = 0) or N_j'(xi) (derivative = 1) from evaluate(). */
  template <int degree>
  double
  basis(const int j, const double xi, const unsigned int derivative)
  {
    double    w[degree + 1], dw[degree + 1];
    const int base = BSplineKernel<degree>::evaluate(xi, w, dw);
    if (j < base || j > base + degree)
      return 0.;
    return derivative == 0 ? w[j - base] : dw[j - base];
  }

  template <int degree>
  void
  test()
  {
    using Kernel           = BSplineKernel<degree>;
    const std::string name = "degree " + std::to_string(degree) + ": ";

    // evaluate() against value(), and the support of degree + 1 cells.
    double max_value = 0., max_outside = 0., max_derivative = 0.;
    for (unsigned int q = 0; q < 1000; ++q)
      {
        const double xi = random_numbers.uniform(0., 10.);
        double       w[degree + 1], dw[degree + 1];
        const int    base = Kernel::evaluate(xi, w, dw);
        for (int a = 0; a <= degree; ++a)
          {
            const double d = xi - (base + a);
            max_value = std::max(max_value, std::abs(w[a] - Kernel::value(d)));
            // Central differences, away from the knots of degree 1 (where
            // N' jumps); truncation O(h^2), round-off O(1e-16 / h).
            const double h = 1e-6;
            if (degree > 1 || std::abs(d - std::round(d)) > 1e-3)
              {
                const double fd =
                  (Kernel::value(d + h) - Kernel::value(d - h)) / (2. * h);
                max_derivative = std::max(max_derivative,
                                          std::abs(dw[a] - fd) /
                                            std::max(1., std::abs(dw[a])));
              }
          }
        max_outside =
          std::max({max_outside,
                    std::abs(Kernel::value(xi - (base - 1))),
                    std::abs(Kernel::value(xi - (base + degree + 1)))});
      }
    bfemp_tests::check(max_value < 1e-14, name + "evaluate() == value()");
    bfemp_tests::check(max_outside == 0.,
                       name + "value() vanishes at the nodes next to the "
                              "stencil");
    bfemp_tests::check(max_derivative < 1e-6,
                       name + "derivative == central differences");

    // Jumps of N_j and its derivatives at the knots j + k: the integers for
    // odd degree, the half integers for degree 2.
    const int           j   = 5;
    const double        eps = 1e-10; // for N and N'
    const double        e   = 1e-5;  // step of the one-sided differences of N'
    std::vector<double> knots;
    for (int k = 0; k <= degree + 1; ++k)
      knots.push_back(j - 0.5 * (degree + 1) + k);

    double jump[3] = {0., 0., 0.};
    for (const double k : knots)
      {
        jump[0] = std::max(jump[0],
                           std::abs(basis<degree>(j, k + eps, 0) -
                                    basis<degree>(j, k - eps, 0)));
        jump[1] = std::max(jump[1],
                           std::abs(basis<degree>(j, k + eps, 1) -
                                    basis<degree>(j, k - eps, 1)));
        const double right =
          (basis<degree>(j, k + 2. * e, 1) - basis<degree>(j, k + e, 1)) / e;
        const double left =
          (basis<degree>(j, k - e, 1) - basis<degree>(j, k - 2. * e, 1)) / e;
        jump[2] = std::max(jump[2], std::abs(right - left));
      }

    // "small" is round-off or O(e) truncation, "large" is O(1).
    const char *order_name[3] = {"N", "N'", "N''"};
    for (int order = 0; order <= std::min(degree, 2); ++order)
      {
        const bool expect_jump = (order == degree);
        dealii::deallog << name << "max jump of " << order_name[order]
                        << " at the knots: "
                        << (jump[order] < 1e-3
                              ? std::string("small")
                              : "large (" +
                                  std::to_string(
                                    static_cast<int>(std::round(jump[order]))) +
                                  ")")
                        << std::endl;
        bfemp_tests::check(expect_jump ? jump[order] > 0.5 : jump[order] < 1e-3,
                           name + order_name[order] +
                             (expect_jump ? " jumps" : " is continuous"));
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  test<1>();
  test<2>();
  test<3>();
}
