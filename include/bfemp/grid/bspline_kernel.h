#ifndef bfemp_grid_bspline_kernel_h
#define bfemp_grid_bspline_kernel_h

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <type_traits>

namespace bfemp
{
  /**
   * Uniform B-spline kernels N(d) of degree 1 (hat, C0), 2 (quadratic, C1) and
   * 3 (cubic, C2) on a grid of unit spacing (MPM principles, seed 001,
   * "Shape Functions, Consistency, and Cell-Crossing Error"; BFEMP Section
   * 3.2 uses degree 2). The support is degree + 1 cells, so a particle sees
   * degree + 1 nodes per direction. All arguments are in lattice units
   * xi = (x - x_0) / dx; derivatives are d/dxi, the caller scales by 1/dx.
   */
  template <int degree>
  struct BSplineKernel
  {
    static_assert(degree >= 1 && degree <= 3, "B-spline degree 1, 2 or 3");

    static constexpr unsigned int n_nodes_1d = degree + 1;

    /**
     * Lattice index of the first of the n_nodes_1d nodes that carry
     * nonzero weight at xi. Linear: floor(xi); quadratic: floor(xi - 1/2),
     * cubic: floor(xi) - 1.
     */
    static inline int
    first_node(const double xi)
    {
      if constexpr (degree == 2)
        return floor_to_int(xi - 0.5);
      else if constexpr (degree == 1)
        return floor_to_int(xi);
      else
        return floor_to_int(xi) - 1;
    }

    /**
     * floor() as an int without the libm call that the baseline x86-64
     * instruction set needs for std::floor (this sits in every particle loop).
     */
    static inline int
    floor_to_int(const double x)
    {
      const int truncated = static_cast<int>(x);
      return truncated - (x < truncated);
    }

    /**
     * Weights w[a] = N(xi - (base + a)) and derivatives dw[a] = N'(.) for the
     * nodes base, ..., base + degree. Returns base.
     */
    static inline int
    evaluate(const double xi, double *w, double *dw)
    {
      const int base = first_node(xi);
      if constexpr (degree == 1)
        {
          const double t = xi - base;
          w[0]           = 1. - t;
          w[1]           = t;
          dw[0]          = -1.;
          dw[1]          = 1.;
        }
      else if constexpr (degree == 2)
        {
          // t in [0.5, 1.5): distance to the first node
          const double t = xi - base;
          const double a = 1.5 - t, b = t - 1., c = t - 0.5;
          w[0]  = 0.5 * a * a;
          w[1]  = 0.75 - b * b;
          w[2]  = 0.5 * c * c;
          dw[0] = -a;
          dw[1] = -2. * b;
          dw[2] = c;
        }
      else
        {
          // t in [0, 1): distance to the second node
          const double t = xi - (base + 1);
          const double s = 1. - t;
          w[0]           = s * s * s / 6.;
          w[1]           = 0.5 * t * t * t - t * t + 2. / 3.;
          w[2]           = 0.5 * s * s * s - s * s + 2. / 3.;
          w[3]           = t * t * t / 6.;
          dw[0]          = -0.5 * s * s;
          dw[1]          = 1.5 * t * t - 2. * t;
          dw[2]          = -1.5 * s * s + 2. * s;
          dw[3]          = 0.5 * t * t;
        }
      return base;
    }

    /** N(d) for a signed distance d in cells (reference form for tests). */
    static double
    value(const double d)
    {
      const double r = std::abs(d);
      if constexpr (degree == 1)
        return r < 1. ? 1. - r : 0.;
      else if constexpr (degree == 2)
        return r < 0.5   ? 0.75 - r * r
               : r < 1.5 ? 0.5 * (1.5 - r) * (1.5 - r)
                         : 0.;
      else
        return r < 1.   ? 0.5 * r * r * r - r * r + 2. / 3.
               : r < 2. ? (2. - r) * (2. - r) * (2. - r) / 6.
                        : 0.;
    }
  };



  /**
   * Calls f(std::integral_constant<int, degree>()) for the run-time kernel
   * degree, so the particle loops are compiled once per degree with fixed
   * stencil sizes.
   */
  template <typename Function>
  inline decltype(auto)
  dispatch_kernel_degree(const unsigned int degree, Function &&f)
  {
    switch (degree)
      {
        case 1:
          return f(std::integral_constant<int, 1>());
        case 2:
          return f(std::integral_constant<int, 2>());
        case 3:
          return f(std::integral_constant<int, 3>());
        default:
          AssertThrow(false, dealii::ExcMessage("kernel degree must be 1-3"));
      }
    return f(std::integral_constant<int, 2>());
  }
} // namespace bfemp

#endif
