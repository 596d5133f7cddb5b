// Checks the squared distances of contact/distance.h (point-point, point-edge
// in 2D and 3D, point-triangle) in every region of closest feature:
// - values against a brute-force reference (golden-section minimization of
//   |p - x(t)|^2 over the segment, nested over the triangle: it uses no
//   projection formula) and, for configurations built with a known closest
//   point, against the constructed distance and barycentric weights; the
//   weights reproduce the value; the value-only functions agree;
// - gradients against central finite differences of the value and Hessians
//   against central finite differences of the gradient, for targeted
//   configurations in each region (vertex regions of both endpoints, edge
//   interior; face interior, each edge region, each vertex region) and for
//   random ones (a configuration whose finite-difference stencil crosses a
//   region boundary is skipped and counted);
// - continuity of the value, the gradient and the weights across every
//   region boundary;
// - degenerate primitives (coincident endpoints, collinear triangles, two
//   or three coincident vertices, nearly degenerate ones): the value against
//   the reference, the derivatives with respect to the query point, and the
//   first and second directional derivatives along motions that keep the
//   primitive degenerate (the distance is not differentiable across the
//   degeneracy, so only those are defined).
// Maximum errors go to stdout; the output records pass/fail against the
// stated tolerances.

#include <bfemp/contact/distance.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{

  /** The larger of two errors, a NaN counting as the largest (std::max
   *  would drop a NaN in its second argument and hide a failure). */
  double
  worse(const double a, const double b)
  {
    if (std::isnan(a))
      return a;
    return (std::isnan(b) || b > a) ? b : a;
  }



  bfemp_tests::RandomNumbers random_numbers(20240815);

  // Values and weights: absolute, relative to the squared diameter of the
  // configuration (the rounding of d^2 is of that order).
  constexpr double value_tolerance = 1e-12;
  // Gradients: relative to max(|g|_inf, diameter); Hessians: relative to
  // |H|_inf. Central differences with step 1e-6 diameter (1e-4 for second
  // differences of the value).
  constexpr double gradient_tolerance = 1e-7;
  constexpr double hessian_tolerance  = 1e-6;
  // Jumps across region boundaries at +-1e-8 diameter from the boundary.
  constexpr double continuity_tolerance = 1e-6;

  template <int dim, std::size_t n_nodes>
  using Nodes = std::array<Point<dim>, n_nodes>;

  template <int dim, std::size_t n_nodes>
  using Coordinates = std::array<double, dim * n_nodes>;

  using Weights = std::array<double, 3>;



  /** The minimum of a convex function on [lo, hi] by golden sections. */
  template <typename Function>
  double
  golden_minimum(const Function &f, double lo, double hi)
  {
    const double ratio = 0.5 * (std::sqrt(5.) - 1.);
    const double f_lo = f(lo), f_hi = f(hi);
    double       x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
    double       f1 = f(x1), f2 = f(x2);
    for (unsigned int i = 0; i < 100; ++i)
      if (f1 <= f2)
        {
          hi = x2;
          x2 = x1;
          f2 = f1;
          x1 = hi - ratio * (hi - lo);
          f1 = f(x1);
        }
      else
        {
          lo = x1;
          x1 = x2;
          f1 = f2;
          x2 = lo + ratio * (hi - lo);
          f2 = f(x2);
        }
    return std::min({f1, f2, f_lo, f_hi});
  }



  /** The function under test and its brute-force reference, per
   *  primitive: nodes (p, primitive nodes...). */
  template <int dim, std::size_t n_nodes>
  struct Kernel;

  template <int dim>
  struct Kernel<dim, 2>
  {
    static SquaredDistance<2 * dim>
    full(const Nodes<dim, 2> &x)
    {
      return point_point_squared_distance<dim>(x[0], x[1]);
    }

    static double
    value(const Nodes<dim, 2> &x)
    {
      return full(x).value;
    }

    static double
    reference(const Nodes<dim, 2> &x)
    {
      return (x[0] - x[1]).norm_square();
    }
  };

  template <int dim>
  struct Kernel<dim, 3>
  {
    static SquaredDistance<3 * dim>
    full(const Nodes<dim, 3> &x)
    {
      return point_edge_squared_distance<dim>(x[0], x[1], x[2]);
    }

    static double
    value(const Nodes<dim, 3> &x)
    {
      return point_edge_squared_distance_value<dim>(x[0], x[1], x[2]);
    }

    static double
    reference(const Nodes<dim, 3> &x)
    {
      return golden_minimum(
        [&x](const double t) {
          return (x[0] - ((1. - t) * x[1] + t * x[2])).norm_square();
        },
        0.,
        1.);
    }
  };

  template <>
  struct Kernel<3, 4>
  {
    static SquaredDistance<12>
    full(const Nodes<3, 4> &x)
    {
      return point_triangle_squared_distance(x[0], x[1], x[2], x[3]);
    }

    static double
    value(const Nodes<3, 4> &x)
    {
      return point_triangle_squared_distance_value(x[0], x[1], x[2], x[3]);
    }

    static double
    reference(const Nodes<3, 4> &x)
    {
      const auto f = [&x](const double beta, const double gamma) {
        return (x[0] -
                ((1. - beta - gamma) * x[1] + beta * x[2] + gamma * x[3]))
          .norm_square();
      };
      // min over beta of (min over gamma in [0, 1 - beta]): both convex.
      return golden_minimum(
        [&f](const double beta) {
          return golden_minimum(
            [&f, beta](const double gamma) { return f(beta, gamma); },
            0.,
            std::max(0., 1. - beta));
        },
        0.,
        1.);
    }
  };



  template <int dim, std::size_t n_nodes>
  double
  diameter(const Nodes<dim, n_nodes> &x)
  {
    double result = 0.;
    for (unsigned int i = 0; i < n_nodes; ++i)
      for (unsigned int j = i + 1; j < n_nodes; ++j)
        result = std::max(result, x[i].distance(x[j]));
    return result;
  }

  template <int n_coordinates>
  std::array<bool, 3>
  feature(const SquaredDistance<n_coordinates> &s)
  {
    return {{s.weights[0] != 0., s.weights[1] != 0., s.weights[2] != 0.}};
  }

  template <int dim, std::size_t n_nodes>
  Nodes<dim, n_nodes>
  displaced(const Nodes<dim, n_nodes>       &x,
            const Coordinates<dim, n_nodes> &u,
            const double                     h)
  {
    Nodes<dim, n_nodes> result = x;
    for (unsigned int a = 0; a < n_nodes; ++a)
      for (unsigned int i = 0; i < dim; ++i)
        result[a][i] += h * u[a * dim + i];
    return result;
  }

  template <int dim, std::size_t n_nodes>
  std::vector<Coordinates<dim, n_nodes>>
  coordinate_directions(const unsigned int n_directions = dim * n_nodes)
  {
    std::vector<Coordinates<dim, n_nodes>> directions(n_directions);
    for (unsigned int k = 0; k < n_directions; ++k)
      {
        directions[k].fill(0.);
        directions[k][k] = 1.;
      }
    return directions;
  }



  /** Maximum errors of a group of configurations. */
  struct Summary
  {
    explicit Summary(const std::string &name)
      : name(name)
    {}

    std::string  name;
    unsigned int n_configurations    = 0;
    unsigned int n_differentiated    = 0;
    unsigned int n_skipped           = 0;
    double       value_error         = 0.;
    double       gradient_error      = 0.;
    double       hessian_error       = 0.;
    bool         derivatives_checked = false;
    bool         degenerate          = false;

    void
    report() const
    {
      bfemp_tests::check_below(value_error,
                               value_tolerance,
                               name +
                                 ": d^2 and weights match the reference (" +
                                 std::to_string(n_configurations) +
                                 " configurations, relative to diameter^2): "
                                 "largest error");
      if (!derivatives_checked)
        return;
      const std::string skipped = n_skipped > 0
                                    ? ", " + std::to_string(n_skipped) +
                                        " next to a region boundary skipped"
                                    : "";
      bfemp_tests::check(
        gradient_error <= gradient_tolerance && n_differentiated > 0,
        name + ": " +
          (degenerate ? "gradient in p and directional derivatives along "
                        "motions keeping it degenerate match"
                      : "gradient matches") +
          " central differences (" + std::to_string(n_differentiated) +
          " configurations" + skipped + "): largest relative error " +
          bfemp_tests::measured(gradient_error, gradient_tolerance));
      bfemp_tests::check(
        hessian_error <= hessian_tolerance && n_differentiated > 0,
        name + ": " +
          (degenerate ? "Hessian rows of p and second directional "
                        "derivatives along those motions match"
                      : "Hessian matches") +
          " central differences: largest relative error " +
          bfemp_tests::measured(hessian_error, hessian_tolerance));
    }
  };



  /**
   * The value against the brute-force reference and, if given, against the
   * constructed value and weights; weights nonnegative, summing to one and
   * reproducing the value; the value-only function agrees.
   */
  template <int dim, std::size_t n_nodes>
  void
  check_value(Summary                   &summary,
              const Nodes<dim, n_nodes> &x,
              const double               expected_value   = -1.,
              const Weights             *expected_weights = nullptr)
  {
    const auto   s  = Kernel<dim, n_nodes>::full(x);
    const double L2 = std::max(diameter(x) * diameter(x), 1e-300);

    double error = std::abs(s.value - Kernel<dim, n_nodes>::reference(x)) / L2;
    error =
      worse(error, std::abs(s.value - Kernel<dim, n_nodes>::value(x)) / L2);
    if (expected_value >= 0.)
      error = worse(error, std::abs(s.value - expected_value) / L2);

    Point<dim> closest;
    double     weight_sum = 0.;
    for (unsigned int k = 0; k + 1 < n_nodes; ++k)
      {
        closest += s.weights[k] * x[k + 1];
        weight_sum += s.weights[k];
        if (s.weights[k] < 0.)
          error = worse(error, 1.);
        if (expected_weights != nullptr)
          error = worse(error, std::abs(s.weights[k] - (*expected_weights)[k]));
      }
    for (unsigned int k = n_nodes - 1; k < 3; ++k)
      if (s.weights[k] != 0.)
        error = worse(error, 1.);
    error = worse(error, std::abs(weight_sum - 1.));
    error =
      worse(error, std::abs((x[0] - closest).norm_square() - s.value) / L2);

    summary.value_error = worse(summary.value_error, error);
    ++summary.n_configurations;
  }



  /**
   * Central differences along each of @p directions (unit vectors): the
   * value against g.u and the first @p n_rows gradient entries against
   * (H u)_r. Invariants: the Hessian is symmetric, and the gradient and the
   * Hessian's rows vanish when summed over the nodes (translation
   * invariance). Skips (and counts) a configuration whose stencil changes
   * the closest feature, unless @p require_same_feature is false (for
   * degenerate primitives, where equivalent features tie and only the rows
   * of p are compared, which all of them share).
   */
  template <int dim, std::size_t n_nodes>
  void
  check_derivatives(Summary                                      &summary,
                    const Nodes<dim, n_nodes>                    &x,
                    const std::vector<Coordinates<dim, n_nodes>> &directions,
                    const unsigned int n_rows               = dim * n_nodes,
                    const bool         require_same_feature = true)
  {
    constexpr unsigned int n    = dim * n_nodes;
    summary.derivatives_checked = true;

    const auto   s = Kernel<dim, n_nodes>::full(x);
    const double L = diameter(x);
    const double h = 1e-6 * L;

    double g_scale = L, h_scale = 0.;
    for (unsigned int r = 0; r < n; ++r)
      {
        g_scale = std::max(g_scale, std::abs(s.gradient[r]));
        for (unsigned int c = 0; c < n; ++c)
          h_scale = std::max(h_scale, std::abs(s.hessian[r][c]));
      }

    double gradient_error = 0., hessian_error = 0.;
    for (const auto &u : directions)
      {
        const auto plus  = Kernel<dim, n_nodes>::full(displaced(x, u, h));
        const auto minus = Kernel<dim, n_nodes>::full(displaced(x, u, -h));
        if (require_same_feature &&
            (feature(plus) != feature(s) || feature(minus) != feature(s)))
          {
            ++summary.n_skipped;
            return;
          }
        double g_u = 0.;
        for (unsigned int k = 0; k < n; ++k)
          g_u += s.gradient[k] * u[k];
        gradient_error =
          worse(gradient_error,
                std::abs((plus.value - minus.value) / (2. * h) - g_u) /
                  g_scale);
        for (unsigned int r = 0; r < n_rows; ++r)
          {
            double h_u = 0.;
            for (unsigned int k = 0; k < n; ++k)
              h_u += s.hessian[r][k] * u[k];
            hessian_error =
              worse(hessian_error,
                    std::abs((plus.gradient[r] - minus.gradient[r]) / (2. * h) -
                             h_u) /
                      h_scale);
          }
      }

    // Symmetry (exact) and translation invariance.
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int c = 0; c < n; ++c)
        if (s.hessian[r][c] != s.hessian[c][r])
          hessian_error = worse(hessian_error, 1.);
    for (unsigned int i = 0; i < dim; ++i)
      {
        double g_sum = 0.;
        for (unsigned int a = 0; a < n_nodes; ++a)
          g_sum += s.gradient[a * dim + i];
        gradient_error = worse(gradient_error, std::abs(g_sum) / g_scale);
        for (unsigned int r = 0; r < n; ++r)
          {
            double h_sum = 0.;
            for (unsigned int a = 0; a < n_nodes; ++a)
              h_sum += s.hessian[r][a * dim + i];
            hessian_error = worse(hessian_error, std::abs(h_sum) / h_scale);
          }
      }

    summary.gradient_error = worse(summary.gradient_error, gradient_error);
    summary.hessian_error  = worse(summary.hessian_error, hessian_error);
    ++summary.n_differentiated;
  }



  /**
   * First and second directional derivatives g.u and u^T H u against
   * central differences of the value along straight paths that keep a
   * degenerate primitive degenerate (where only those derivatives exist).
   */
  template <int dim, std::size_t n_nodes>
  void
  check_directional(Summary                                      &summary,
                    const Nodes<dim, n_nodes>                    &x,
                    const std::vector<Coordinates<dim, n_nodes>> &directions)
  {
    constexpr unsigned int n    = dim * n_nodes;
    summary.derivatives_checked = true;
    summary.degenerate          = true;

    const auto   s  = Kernel<dim, n_nodes>::full(x);
    const double L  = diameter(x);
    const double h1 = 1e-6 * L;
    const double h2 = 1e-4 * L;

    double g_scale = L, h_scale = 0.;
    for (unsigned int r = 0; r < n; ++r)
      {
        g_scale = std::max(g_scale, std::abs(s.gradient[r]));
        for (unsigned int c = 0; c < n; ++c)
          h_scale = std::max(h_scale, std::abs(s.hessian[r][c]));
      }

    for (auto u : directions)
      {
        double norm = 0.;
        for (const double c : u)
          norm += c * c;
        for (double &c : u)
          c /= std::sqrt(norm);

        double g_u = 0., u_h_u = 0.;
        for (unsigned int r = 0; r < n; ++r)
          {
            g_u += s.gradient[r] * u[r];
            for (unsigned int c = 0; c < n; ++c)
              u_h_u += u[r] * s.hessian[r][c] * u[c];
          }
        const double first =
          (Kernel<dim, n_nodes>::value(displaced(x, u, h1)) -
           Kernel<dim, n_nodes>::value(displaced(x, u, -h1))) /
          (2. * h1);
        const double second =
          (Kernel<dim, n_nodes>::value(displaced(x, u, h2)) - 2. * s.value +
           Kernel<dim, n_nodes>::value(displaced(x, u, -h2))) /
          (h2 * h2);
        summary.gradient_error =
          worse(summary.gradient_error, std::abs(first - g_u) / g_scale);
        summary.hessian_error =
          worse(summary.hessian_error, std::abs(second - u_h_u) / h_scale);
      }
  }



  /**
   * The value, gradient and weights at @p x +- 1e-8 diameter along @p
   * direction (moving the query point), where @p x lies on the boundary
   * between two regions: the two sides have different closest features,
   * yet the jumps vanish with the distance to the boundary.
   */
  template <int dim, std::size_t n_nodes>
  void
  check_continuity(const std::string         &name,
                   const Nodes<dim, n_nodes> &x,
                   const Tensor<1, dim>      &direction)
  {
    constexpr unsigned int n   = dim * n_nodes;
    const double           L   = diameter(x);
    const double           eta = 1e-8 * L;

    Nodes<dim, n_nodes> x_plus = x, x_minus = x;
    x_plus[0] += eta * direction / direction.norm();
    x_minus[0] -= eta * direction / direction.norm();
    const auto plus  = Kernel<dim, n_nodes>::full(x_plus);
    const auto minus = Kernel<dim, n_nodes>::full(x_minus);

    double g_scale = L;
    for (unsigned int r = 0; r < n; ++r)
      g_scale = std::max(g_scale, std::abs(plus.gradient[r]));
    double jump = std::abs(plus.value - minus.value) / (L * L);
    for (unsigned int r = 0; r < n; ++r)
      jump =
        worse(jump, std::abs(plus.gradient[r] - minus.gradient[r]) / g_scale);
    for (unsigned int k = 0; k < 3; ++k)
      jump = worse(jump, std::abs(plus.weights[k] - minus.weights[k]));

    bfemp_tests::check(feature(plus) != feature(minus) &&
                         jump <= continuity_tolerance,
                       name +
                         ": value, gradient and weights continuous across "
                         "the boundary (closest features differ): "
                         "largest relative jump " +
                         bfemp_tests::measured(jump, continuity_tolerance));
  }



  template <int dim>
  Point<dim>
  random_point(const double amplitude = 1.)
  {
    return Point<dim>(random_numbers.vector<dim>(amplitude));
  }

  /** A random unit vector perpendicular to @p e. */
  template <int dim>
  Tensor<1, dim>
  unit_normal(const Tensor<1, dim> &e)
  {
    Tensor<1, dim> m;
    if (dim == 2)
      {
        m[0] = -e[1];
        m[1] = e[0];
      }
    else
      {
        m = random_numbers.vector<dim>(1.);
        m -= (m * e) / e.norm_square() * e;
      }
    return m / m.norm();
  }

  /** The unit in-plane normal of the edge (a, b), pointing away from c. */
  Tensor<1, 3>
  outward_normal(const Point<3> &a, const Point<3> &b, const Point<3> &c)
  {
    const Tensor<1, 3> n = cross_product_3d(b - a, c - a);
    Tensor<1, 3>       m = cross_product_3d(b - a, n);
    if (m * (c - a) > 0.)
      m = -m;
    return m / m.norm();
  }

  /** A triangle with area at least 0.15 times its longest edge squared. */
  std::array<Point<3>, 3>
  random_triangle()
  {
    while (true)
      {
        const std::array<Point<3>, 3> t = {
          {random_point<3>(), random_point<3>(), random_point<3>()}};
        const double L = std::max(
          {t[0].distance(t[1]), t[1].distance(t[2]), t[2].distance(t[0])});
        if (cross_product_3d(t[1] - t[0], t[2] - t[0]).norm() >= 0.3 * L * L)
          return t;
      }
  }



  template <int dim>
  void
  point_point()
  {
    const std::string name = std::to_string(dim) + "D point-point";
    Summary           summary(name);
    for (unsigned int k = 0; k < 20; ++k)
      {
        const Nodes<dim, 2> x = {{random_point<dim>(), random_point<dim>()}};
        const Weights       w = {{1., 0., 0.}};
        check_value(summary, x, (x[0] - x[1]).norm_square(), &w);
        check_derivatives(summary, x, coordinate_directions<dim, 2>());
      }
    summary.report();
  }



  template <int dim>
  void
  point_edge()
  {
    const std::string prefix = std::to_string(dim) + "D point-edge, ";

    // Configurations built from a known closest point: p = closest point
    // + an offset in the normal cone of the feature.
    Summary vertex_a(prefix + "vertex region of a");
    Summary vertex_b(prefix + "vertex region of b");
    Summary interior(prefix + "edge interior");
    Summary on_edge(prefix + "query point on the edge");
    for (unsigned int k = 0; k < 20; ++k)
      {
        Point<dim> a, b;
        do
          {
            a = random_point<dim>();
            b = random_point<dim>();
        } while (a.distance(b) < 0.5);
        const Tensor<1, dim> e     = b - a;
        const Tensor<1, dim> unit  = e / e.norm();
        const Tensor<1, dim> m     = unit_normal(e);
        const double         along = random_numbers.uniform(0.1, 1.);
        const double         side  = random_numbers.uniform(-1., 1.);
        const double         t     = random_numbers.uniform(0.1, 0.9);
        const double height = std::copysign(random_numbers.uniform(0.05, 1.),
                                            random_numbers.uniform(-1., 1.));
        const auto   all    = coordinate_directions<dim, 3>();

        {
          const Nodes<dim, 3> x = {{a - along * unit + side * m, a, b}};
          const Weights       w = {{1., 0., 0.}};
          check_value(vertex_a, x, along * along + side * side, &w);
          check_derivatives(vertex_a, x, all);
        }
        {
          const Nodes<dim, 3> x = {{b + along * unit + side * m, a, b}};
          const Weights       w = {{0., 1., 0.}};
          check_value(vertex_b, x, along * along + side * side, &w);
          check_derivatives(vertex_b, x, all);
        }
        {
          const Nodes<dim, 3> x = {{a + t * e + height * m, a, b}};
          const Weights       w = {{1. - t, t, 0.}};
          check_value(interior, x, height * height, &w);
          check_derivatives(interior, x, all);
        }
        {
          const Nodes<dim, 3> x = {{a + t * e, a, b}};
          const Weights       w = {{1. - t, t, 0.}};
          check_value(on_edge, x, 0., &w);
          check_derivatives(on_edge, x, all);
        }
      }
    vertex_a.report();
    vertex_b.report();
    interior.report();
    on_edge.report();

    // Random configurations.
    {
      Summary                     random(prefix + "random");
      std::array<unsigned int, 2> regions = {{0, 0}};
      for (unsigned int k = 0; k < 300; ++k)
        {
          const Nodes<dim, 3> x = {
            {random_point<dim>(), random_point<dim>(), random_point<dim>()}};
          check_value(random, x);
          check_derivatives(random, x, coordinate_directions<dim, 3>());
          const auto f = feature(Kernel<dim, 3>::full(x));
          ++regions[f[0] && f[1] ? 1 : 0];
        }
      random.report();
      bfemp_tests::check(regions[0] > 50 && regions[1] > 50,
                         prefix +
                           "random: both vertex and interior regions "
                           "hit (more than 50 each): " +
                           std::to_string(regions[0]) + " vertex, " +
                           std::to_string(regions[1]) + " interior");
    }

    // Continuity across the boundaries t = 0 and t = 1.
    {
      Point<dim> a, b;
      do
        {
          a = random_point<dim>();
          b = random_point<dim>();
      } while (a.distance(b) < 0.5);
      const Tensor<1, dim> e = b - a;
      const Tensor<1, dim> m = unit_normal(e);
      check_continuity<dim, 3>(prefix + "vertex a | interior",
                               {{a + 0.3 * m, a, b}},
                               e);
      check_continuity<dim, 3>(prefix + "vertex b | interior",
                               {{b - 0.7 * m, a, b}},
                               e);
    }

    // Degenerate edges.
    {
      Summary coincident(prefix + "coincident endpoints");
      for (unsigned int k = 0; k < 10; ++k)
        {
          const Point<dim>    a = random_point<dim>();
          const Nodes<dim, 3> x = {{random_point<dim>(), a, a}};
          const Weights       w = {{1., 0., 0.}};
          check_value(coincident, x, (x[0] - a).norm_square(), &w);
          // Derivatives with respect to p; motions of a and b together.
          check_derivatives(coincident,
                            x,
                            coordinate_directions<dim, 3>(dim),
                            dim,
                            false);
          std::vector<Coordinates<dim, 3>> together(4);
          for (auto &u : together)
            {
              const Tensor<1, dim> shift = random_numbers.vector<dim>(1.);
              const Tensor<1, dim> move  = random_numbers.vector<dim>(1.);
              for (unsigned int i = 0; i < dim; ++i)
                {
                  u[i]           = move[i];
                  u[dim + i]     = shift[i];
                  u[2 * dim + i] = shift[i];
                }
            }
          check_directional(coincident, x, together);
        }
      coincident.report();

      // Nearly coincident endpoints, below (|e| = 1e-14) and above
      // (|e| = 1e-7) the degeneracy threshold |e| <= 1.5e-8 |p - a|.
      Summary nearly(prefix + "endpoints 1e-14 and 1e-7 apart");
      for (unsigned int k = 0; k < 10; ++k)
        for (const double length : {1e-14, 1e-7})
          {
            const Point<dim> a = random_point<dim>();
            Tensor<1, dim>   e = random_numbers.vector<dim>(1.);
            e *= length / e.norm();
            const Nodes<dim, 3> x = {{random_point<dim>(), a, a + e}};
            check_value(nearly, x);
          }
      nearly.report();
    }
  }



  void
  point_triangle()
  {
    const std::string prefix = "3D point-triangle, ";
    const auto        all    = coordinate_directions<3, 4>();

    Summary                face(prefix + "face interior");
    Summary                on_face(prefix + "query point on the face");
    std::array<Summary, 3> edge   = {{Summary(prefix + "edge region of ab"),
                                      Summary(prefix + "edge region of bc"),
                                      Summary(prefix + "edge region of ca")}};
    std::array<Summary, 3> vertex = {{Summary(prefix + "vertex region of a"),
                                      Summary(prefix + "vertex region of b"),
                                      Summary(prefix + "vertex region of c")}};
    for (unsigned int k = 0; k < 20; ++k)
      {
        const auto         t      = random_triangle();
        const Tensor<1, 3> n      = cross_product_3d(t[1] - t[0], t[2] - t[0]);
        const Tensor<1, 3> unit_n = n / n.norm();
        const double       height = random_numbers.uniform(-1., 1.);

        // face: p = a + beta e1 + gamma e2 + h n
        {
          double beta, gamma;
          do
            {
              beta  = random_numbers.uniform(0.05, 0.95);
              gamma = random_numbers.uniform(0.05, 0.95);
          } while (beta + gamma > 0.95);
          const Point<3> c =
            t[0] + beta * (t[1] - t[0]) + gamma * (t[2] - t[0]);
          const Weights     w = {{1. - beta - gamma, beta, gamma}};
          const Nodes<3, 4> x = {{c + height * unit_n, t[0], t[1], t[2]}};
          check_value(face, x, height * height, &w);
          check_derivatives(face, x, all);
          const Nodes<3, 4> y = {{c, t[0], t[1], t[2]}};
          check_value(on_face, y, 0., &w);
          check_derivatives(on_face, y, all);
        }

        // edge j from node j to node j+1: closest point in its interior,
        // offset outward in the plane and along n.
        for (unsigned int j = 0; j < 3; ++j)
          {
            const Point<3> &from = t[j], &to = t[(j + 1) % 3],
                           &opposite = t[(j + 2) % 3];
            const double       s     = random_numbers.uniform(0.1, 0.9);
            const double       out   = random_numbers.uniform(0.05, 1.);
            const Tensor<1, 3> m     = outward_normal(from, to, opposite);
            Weights            w     = {{0., 0., 0.}};
            w[j]                     = 1. - s;
            w[(j + 1) % 3]           = s;
            const Nodes<3, 4> x      = {
                   {from + s * (to - from) + out * m + height * unit_n,
                    t[0],
                    t[1],
                    t[2]}};
            check_value(edge[j], x, out * out + height * height, &w);
            check_derivatives(edge[j], x, all);
          }

        // vertex j: offset in its normal cone, spanned by the outward
        // normals of its two edges (and n).
        for (unsigned int j = 0; j < 3; ++j)
          {
            const Point<3> &v = t[j], &next = t[(j + 1) % 3],
                           &previous  = t[(j + 2) % 3];
            const Tensor<1, 3> offset = random_numbers.uniform(0.05, 1.) *
                                          outward_normal(v, next, previous) +
                                        random_numbers.uniform(0.05, 1.) *
                                          outward_normal(previous, v, next) +
                                        height * unit_n;
            Weights w           = {{0., 0., 0.}};
            w[j]                = 1.;
            const Nodes<3, 4> x = {{v + offset, t[0], t[1], t[2]}};
            check_value(vertex[j], x, offset.norm_square(), &w);
            check_derivatives(vertex[j], x, all);
          }
      }
    face.report();
    on_face.report();
    for (const auto &s : edge)
      s.report();
    for (const auto &s : vertex)
      s.report();

    // Random configurations, including slivers.
    {
      Summary                     random(prefix + "random");
      std::array<unsigned int, 3> regions = {{0, 0, 0}};
      for (unsigned int k = 0; k < 300; ++k)
        {
          const Nodes<3, 4> x = {{random_point<3>(),
                                  random_point<3>(),
                                  random_point<3>(),
                                  random_point<3>()}};
          check_value(random, x);
          check_derivatives(random, x, all);
          const auto f = feature(Kernel<3, 4>::full(x));
          ++regions[f[0] + f[1] + f[2] - 1];
        }
      random.report();
      bfemp_tests::check(regions[0] > 30 && regions[1] > 30 && regions[2] > 30,
                         prefix +
                           "random: vertex, edge and face regions hit "
                           "(more than 30 each): " +
                           std::to_string(regions[0]) + " vertex, " +
                           std::to_string(regions[1]) + " edge, " +
                           std::to_string(regions[2]) + " face");
    }

    // Continuity across the boundaries face | edge and edge | vertex.
    {
      const auto         t      = random_triangle();
      const Tensor<1, 3> n      = cross_product_3d(t[1] - t[0], t[2] - t[0]);
      const Tensor<1, 3> unit_n = n / n.norm();
      const std::array<std::string, 3> edge_names = {{"ab", "bc", "ca"}};
      const std::array<std::string, 3> node_names = {{"a", "b", "c"}};
      for (unsigned int j = 0; j < 3; ++j)
        {
          const Point<3> &from = t[j], &to = t[(j + 1) % 3],
                         &opposite = t[(j + 2) % 3];
          const Tensor<1, 3> m     = outward_normal(from, to, opposite);
          check_continuity<3, 4>(
            prefix + "face | edge " + edge_names[j],
            {{from + 0.4 * (to - from) + 0.3 * unit_n, t[0], t[1], t[2]}},
            m);
          check_continuity<3, 4>(
            prefix + "edge " + edge_names[j] + " | vertex " + node_names[j],
            {{from + 0.5 * m - 0.2 * unit_n, t[0], t[1], t[2]}},
            to - from);
          check_continuity<3, 4>(
            prefix + "edge " + edge_names[j] + " | vertex " +
              node_names[(j + 1) % 3],
            {{to + 0.6 * m + 0.1 * unit_n, t[0], t[1], t[2]}},
            to - from);
        }
    }

    // Degenerate triangles: the value, derivatives in p, and directional
    // derivatives along motions that keep the triangle degenerate.
    const auto degenerate =
      [&](const std::string                                 &name,
          const std::vector<Nodes<3, 4>>                    &configurations,
          const std::vector<std::vector<Coordinates<3, 4>>> &motions) {
        Summary summary(prefix + name);
        for (unsigned int k = 0; k < configurations.size(); ++k)
          {
            check_value(summary, configurations[k]);
            check_derivatives(summary,
                              configurations[k],
                              coordinate_directions<3, 4>(3),
                              3,
                              false);
            check_directional(summary, configurations[k], motions[k]);
          }
        summary.report();
      };

    // u moving node a by @p node_shift[a] (node 0 is p).
    const auto motion = [](const std::array<Tensor<1, 3>, 4> &node_shift) {
      Coordinates<3, 4> u;
      for (unsigned int a = 0; a < 4; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          u[a * 3 + i] = node_shift[a][i];
      return u;
    };
    const auto random_vector = []() { return random_numbers.vector<3>(1.); };
    const Tensor<1, 3> zero;

    {
      // Collinear: c = a + s (b - a), inside and outside [a, b]; moving the
      // vertices along the line, translating, and moving p.
      std::vector<Nodes<3, 4>>                    configurations;
      std::vector<std::vector<Coordinates<3, 4>>> motions;
      for (unsigned int k = 0; k < 12; ++k)
        {
          const Point<3>     a = random_point<3>(), b = random_point<3>();
          const double       s = std::array<double, 3>{{-0.5, 0.3, 1.7}}[k % 3];
          const Point<3>     c = a + s * (b - a);
          const Tensor<1, 3> line = b - a;
          configurations.push_back({{random_point<3>(), a, b, c}});
          const Tensor<1, 3> shift = random_vector();
          motions.push_back(
            {motion({{random_vector(), zero, zero, zero}}),
             motion({{shift, shift, shift, shift}}),
             motion({{zero, line, zero, zero}}),
             motion({{zero, zero, -0.5 * line, zero}}),
             motion({{zero, zero, zero, 0.7 * line}}),
             motion({{random_vector(), 0.2 * line, -0.3 * line, 0.4 * line}})});
        }
      degenerate("collinear vertices", configurations, motions);
    }
    {
      // Two coincident vertices (each pair): moving the pair together, the
      // third vertex anywhere, and p.
      std::vector<Nodes<3, 4>>                    configurations;
      std::vector<std::vector<Coordinates<3, 4>>> motions;
      for (unsigned int k = 0; k < 12; ++k)
        {
          const unsigned int single = k % 3; // the vertex that differs
          const Point<3> pair = random_point<3>(), other = random_point<3>();
          Nodes<3, 4>    x = {{random_point<3>(), pair, pair, pair}};
          x[1 + single]    = other;
          configurations.push_back(x);
          const Tensor<1, 3>          together = random_vector();
          const Tensor<1, 3>          apart    = random_vector();
          std::array<Tensor<1, 3>, 4> shift    = {
               {random_vector(), together, together, together}};
          shift[1 + single] = apart;
          motions.push_back(
            {motion(shift), motion({{random_vector(), zero, zero, zero}})});
        }
      degenerate("two coincident vertices", configurations, motions);
    }
    {
      // All three vertices coincident: translating them, and moving p.
      std::vector<Nodes<3, 4>>                    configurations;
      std::vector<std::vector<Coordinates<3, 4>>> motions;
      for (unsigned int k = 0; k < 10; ++k)
        {
          const Point<3> a = random_point<3>();
          configurations.push_back({{random_point<3>(), a, a, a}});
          const Tensor<1, 3> shift = random_vector();
          motions.push_back({motion({{random_vector(), shift, shift, shift}}),
                             motion({{random_vector(), zero, zero, zero}})});
        }
      degenerate("three coincident vertices", configurations, motions);
    }

    // Slivers: c at height 1e-12 above the midpoint of ab (area 5e-13 of
    // the longest edge squared, below the degeneracy threshold 1.5e-8:
    // the edges are used) and at 1e-4 (face branch). The edge fallback is
    // off by at most the height.
    {
      Summary sliver(prefix + "slivers of relative height 1e-12 and 1e-4");
      for (unsigned int k = 0; k < 20; ++k)
        {
          const Point<3> a = random_point<3>(), b = random_point<3>();
          const double   height = (k % 2 == 0 ? 1e-12 : 1e-4) * a.distance(b);
          const Tensor<1, 3> m  = unit_normal<3>(b - a);
          const Point<3>     c  = a + 0.5 * (b - a) + height * m;
          // p above the interior of the sliver's face.
          const Tensor<1, 3> n = cross_product_3d(b - a, m);
          const Nodes<3, 4>  x = {
             {a + 0.3 * (b - a) + 0.2 * height * m + 0.5 * n / n.norm(),
              a,
              b,
              c}};
          check_value(sliver, x);
        }
      sliver.report();
    }
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();

  point_point<2>();
  point_point<3>();
  point_edge<2>();
  point_edge<3>();
  point_triangle();
}
