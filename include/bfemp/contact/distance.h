#ifndef bfemp_contact_distance_h
#define bfemp_contact_distance_h

// Squared distances between a query point (an MPM particle) and the
// primitives of the FEM boundary (a node, an edge, a triangle), with their
// exact gradients and Hessians. They are the geometric kernel of the contact
// potential of BFEMP Section 4.2 (eqs. 28, 31, 32): the barrier is applied
// to these distances (see barrier.h), and the chain rule needs dd^2/dx and
// d^2(d^2)/dx^2 with respect to the query point and the primitive's nodes.
// The value-only variants serve the broad phase and continuous collision
// detection; they share the code that selects the closest feature and
// computes d^2, so they return the same values.

#include <deal.II/base/point.h>

#include <array>

namespace bfemp
{
  using namespace dealii;

  /**
   * The squared distance d^2 between a query point p and a primitive with
   * nodes x_0, x_1, ... (a point, an edge, a triangle), together with its
   * derivatives with respect to all coordinates involved.
   *
   * The coordinates are node-major, query point first:
   * (p_0 .. p_{dim-1}, x_{0,0} .. x_{0,dim-1}, x_{1,0} .., ...), so entry
   * a*dim + i belongs to component i of node a, with node 0 the query point
   * and node k+1 the primitive's node k (the same convention as
   * SimplexElement).
   *
   * Why the squared distance: it is a polynomial (in a region where the
   * closest point lies in the interior of a primitive, a rational function)
   * of the coordinates, so its derivatives are defined everywhere, also at
   * d = 0, while d itself has an unbounded Hessian there. The barrier is
   * written as a function of s = d^2 for this reason (barrier.h).
   *
   * Everywhere except on the boundaries between the regions of closest
   * feature (vertex, edge interior, face interior) d^2 is smooth and the
   * gradient and Hessian here are exact. Across the region boundaries d^2
   * is C1 (the value and the gradient are continuous, the Hessian jumps), as
   * it is for the exact distance to a convex set.
   */
  template <int n_coordinates>
  struct SquaredDistance
  {
    /** d^2. */
    double value;

    /** d(d^2)/d(coordinates), in the layout described above. */
    std::array<double, n_coordinates> gradient;

    /** d^2(d^2)/d(coordinates)^2, symmetric (exactly, entry by entry). */
    std::array<std::array<double, n_coordinates>, n_coordinates> hessian;

    /**
     * The barycentric weights of the primitive's nodes at the closest point
     * c = sum_k weights[k] x_k: nonnegative, summing to one. A primitive
     * with fewer than three nodes leaves the trailing entries zero. They
     * also tell the closest feature: one nonzero weight for a vertex, two
     * for the interior of an edge, three for the interior of a triangle.
     * (A fixed size of three, since n_coordinates alone does not determine
     * the number of nodes: 6 is a 3D point-point and a 2D point-edge pair.)
     */
    std::array<double, 3> weights;
  };



  /**
   * |p - a|^2, the point-point distance d^PP of eqs. 26, 31 and 32, with
   * gradient (2(p - a), -2(p - a)) and Hessian [[2I, -2I], [-2I, 2I]].
   * Layout (p, a).
   */
  template <int dim>
  SquaredDistance<2 * dim>
  point_point_squared_distance(const Point<dim> &p, const Point<dim> &a);

  /**
   * The squared distance between @p p and the closed segment [a, b], the
   * point-edge distance d^PE of eqs. 28, 31 and 32; dim = 2 or 3. Layout
   * (p, a, b).
   *
   * With e = b - a and t = (p - a).e / |e|^2:
   * - t <= 0 or t >= 1 (vertex regions): |p - a|^2 or |p - b|^2, embedded
   *   with zero rows and columns for the other endpoint;
   * - 0 < t < 1 (edge interior): the distance to the line, |v|^2 with
   *   v = p - a - t e. By the envelope theorem (t minimizes
   *   |p - a - t e|^2) the gradient is 2 W^T v with
   *   W = [I, -(1-t) I, -t I], and differentiating it once more, with dt/dq
   *   from the implicit function theorem applied to the optimality condition
   *   e.v = 0, gives H = 2 W^T W - 2 y y^T / |e|^2, y = W^T e - (0, v, -v)
   *   (see the source for the general form).
   * - a degenerate edge, |e|^2 <= epsilon max(|p - a|^2, |p - b|^2) (machine
   *   epsilon; the edge is shorter than 1.5e-8 times the distance to it),
   *   including coincident endpoints: the distance to the nearer endpoint
   *   (a on a tie). This changes d by at most |e|/2 and avoids dividing by
   *   |e|^2. At exactly coincident endpoints the distance is not
   *   differentiable with respect to a and b (a segment of zero length can
   *   open in any direction); the derivatives returned are those of the
   *   point-point distance to a, which are exact for every motion that
   *   keeps the endpoints together.
   */
  template <int dim>
  SquaredDistance<3 * dim>
  point_edge_squared_distance(const Point<dim> &p,
                              const Point<dim> &a,
                              const Point<dim> &b);

  /** The value of point_edge_squared_distance() alone (the same code). */
  template <int dim>
  double
  point_edge_squared_distance_value(const Point<dim> &p,
                                    const Point<dim> &a,
                                    const Point<dim> &b);

  /**
   * The squared distance between @p p and the closed triangle (a, b, c), the
   * point-triangle distance d^PT of eq. 32. Layout (p, a, b, c).
   *
   * With e1 = b - a, e2 = c - a, n = e1 x e2 and the projection of p onto
   * the plane, a + beta e1 + gamma e2:
   * - face interior (beta >= 0, gamma >= 0, beta + gamma <= 1): the
   *   distance to the plane, |v|^2 with v = p - a - beta e1 - gamma e2.
   *   The derivatives are those of the point-edge case with two parameters:
   *   gradient 2 W^T v with W = [I, -(1-beta-gamma) I, -beta I, -gamma I],
   *   Hessian 2 W^T W - 2 sum_jk (G^-1)_jk y_j y_k^T with the Gram matrix
   *   G_jk = e_j.e_k (det G = |n|^2) and y_j = W^T e_j - dW^T/dt_j v.
   * - otherwise the closest point lies on the boundary: the minimum of the
   *   three point-edge distances (edges ab, bc, ca, the first on a tie),
   *   each with its own vertex and interior regions, embedded into the
   *   four-node layout.
   * - degenerate triangles, |n|^2 <= epsilon L^4 with L the longest edge
   *   (|n|, twice the area, is below 1.5e-8 L^2: collinear or coincident
   *   vertices, or slivers whose plane the rounded coordinates determine
   *   only to about epsilon/1.5e-8 in angle): the minimum over the edges
   *   as well, which is exact for a collinear triangle and off by at most
   *   the triangle's width, 1.5e-8 L, for a sliver. Coincident vertices make an
   * edge degenerate, which point_edge_squared_distance() handles. As for a
   *   degenerate edge, the derivatives are those of the active edge or
   *   vertex, exact for motions that keep the triangle degenerate.
   */
  SquaredDistance<12>
  point_triangle_squared_distance(const Point<3> &p,
                                  const Point<3> &a,
                                  const Point<3> &b,
                                  const Point<3> &c);

  /** The value of point_triangle_squared_distance() alone (the same
   *  code). */
  double
  point_triangle_squared_distance_value(const Point<3> &p,
                                        const Point<3> &a,
                                        const Point<3> &b,
                                        const Point<3> &c);
} // namespace bfemp

#endif
