#include <bfemp/contact/distance.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <limits>

namespace bfemp
{
  namespace
  {
    constexpr double epsilon = std::numeric_limits<double>::epsilon();

    /**
     * Fills @p result with d^2 = |v|^2 and its exact derivatives, where
     * v = p - c is the offset from the closest point c = sum_k lambda_k x_k
     * on the affine hull of the n_primitive nodes x_k of a primitive, in the
     * interior of the region where that hull is the closest feature (a
     * single node: a vertex; two: the line of an edge; three: the plane of a
     * triangle). nodes[k] is the index of x_k in the output layout (node 0
     * is p); rows and columns of nodes not listed stay zero.
     *
     * Derivation, with the parameters t_j = lambda_j, j = 1..m
     * (m = n_primitive - 1; lambda_0 = 1 - sum_j t_j), the edges
     * e_j = x_j - x_0 and the coordinates q:
     * - v(q, t) = W(t) q with the node blocks W = [I, -lambda_0 I, ...,
     *   -lambda_m I], and the optimal t makes e_j.v = 0 (the normal
     *   equations G t = (e_j.(p - x_0))_j with G_jk = e_j.e_k).
     * - Envelope theorem: t minimizes |v|^2, so dd^2/dq = 2 W^T v.
     * - Differentiating g = 2 W^T v once more, H = 2 W^T W + 2 sum_j
     *   (W^T dv/dt_j + dW^T/dt_j v) (dt_j/dq)^T with dv/dt_j = -e_j. The
     *   implicit function theorem on e_j.v = 0 gives G dt/dq = Y with the
     *   rows y_j = W^T e_j - dW^T/dt_j v (the second term is the derivative
     *   of e_j with respect to q, contracted with v). Hence
     *     H = 2 W^T W - 2 sum_jk (G^-1)_jk y_j y_k^T,
     *   symmetric, the Gauss-Newton term minus a rank-m correction.
     * - dW^T/dt_j v has the blocks +v at node x_0 and -v at node x_j, so
     *   y_j has the blocks e_j at p and -lambda_k e_j + v (delta_kj -
     *   delta_k0) at node x_k.
     * For a single node (m = 0) this is the point-point Hessian.
     */
    template <int dim, int n_primitive, int n_coordinates>
    void
    fill_hull_squared_distance(
      const Tensor<1, dim>                              &v,
      const std::array<double, n_primitive>             &lambda,
      const std::array<Tensor<1, dim>, n_primitive - 1> &edges,
      const std::array<std::array<double, n_primitive - 1>, n_primitive - 1>
                                                  &gram_inverse,
      const std::array<unsigned int, n_primitive> &nodes,
      SquaredDistance<n_coordinates>              &result)
    {
      constexpr unsigned int n_nodes      = n_coordinates / dim;
      constexpr unsigned int n_parameters = n_primitive - 1;

      result.value   = v * v;
      result.weights = {{0., 0., 0.}};

      // The node coefficients of v at fixed parameters, W = w (x) I.
      std::array<double, n_nodes> w{};
      w[0] = 1.;
      for (unsigned int k = 0; k < n_primitive; ++k)
        {
          w[nodes[k]]                  = -lambda[k];
          result.weights[nodes[k] - 1] = lambda[k];
        }

      for (unsigned int a = 0; a < n_nodes; ++a)
        for (unsigned int i = 0; i < dim; ++i)
          result.gradient[a * dim + i] = 2. * w[a] * v[i];

      // y_j, and G^-1 applied to them.
      std::array<std::array<double, n_coordinates>, n_parameters> y{};
      std::array<std::array<double, n_coordinates>, n_parameters> g_inv_y{};
      for (unsigned int j = 0; j < n_parameters; ++j)
        {
          for (unsigned int i = 0; i < dim; ++i)
            y[j][i] = edges[j][i];
          for (unsigned int k = 0; k < n_primitive; ++k)
            {
              const double v_sign = (k == j + 1) ? 1. : (k == 0 ? -1. : 0.);
              for (unsigned int i = 0; i < dim; ++i)
                y[j][nodes[k] * dim + i] =
                  -lambda[k] * edges[j][i] + v_sign * v[i];
            }
        }
      for (unsigned int j = 0; j < n_parameters; ++j)
        for (unsigned int r = 0; r < n_coordinates; ++r)
          {
            double sum = 0.;
            for (unsigned int l = 0; l < n_parameters; ++l)
              sum += gram_inverse[j][l] * y[l][r];
            g_inv_y[j][r] = sum;
          }

      // The upper triangle, mirrored, so the Hessian is exactly symmetric.
      for (unsigned int r = 0; r < n_coordinates; ++r)
        for (unsigned int c = r; c < n_coordinates; ++c)
          {
            double h = (r % dim == c % dim) ? 2. * w[r / dim] * w[c / dim] : 0.;
            for (unsigned int j = 0; j < n_parameters; ++j)
              h -= 2. * y[j][r] * g_inv_y[j][c];
            result.hessian[r][c] = h;
            result.hessian[c][r] = h;
          }
    }



    /** The closest point of a segment [a, b] to p and its feature. */
    template <int dim>
    struct EdgeProjection
    {
      enum Region
      {
        vertex_a,
        vertex_b,
        interior
      };

      Region region;

      /** The line parameter of the closest point (interior only). */
      double t;

      /** e = b - a and |e|^2. */
      Tensor<1, dim> e;
      double         e_squared;

      /** p minus the closest point, and its squared norm. */
      Tensor<1, dim> v;
      double         value;
    };



    /**
     * The feature of [a, b] closest to p (see point_edge_squared_distance()
     * for the regions and the degenerate case). Shared by the value-only
     * and the full versions, so both select the same feature and return
     * the same value.
     */
    template <int dim>
    inline EdgeProjection<dim>
    project_onto_edge(const Point<dim> &p,
                      const Point<dim> &a,
                      const Point<dim> &b)
    {
      EdgeProjection<dim> projection;
      projection.e                     = b - a;
      projection.e_squared             = projection.e * projection.e;
      const Tensor<1, dim> p_a         = p - a;
      const Tensor<1, dim> p_b         = p - b;
      const double         pa2         = p_a * p_a;
      const double         pb2         = p_b * p_b;
      const double         p_a_e       = p_a * projection.e;
      const bool           closer_to_a = pa2 <= pb2;

      // A degenerate edge: the line through a and b is undetermined, and
      // the nearer endpoint is within |e|/2 of every point of the edge.
      if (projection.e_squared <= epsilon * std::max(pa2, pb2))
        {
          projection.region = closer_to_a ? EdgeProjection<dim>::vertex_a
                                          : EdgeProjection<dim>::vertex_b;
          projection.v      = closer_to_a ? p_a : p_b;
        }
      else if (p_a_e <= 0.)
        {
          projection.region = EdgeProjection<dim>::vertex_a;
          projection.v      = p_a;
        }
      else if (p_a_e >= projection.e_squared)
        {
          projection.region = EdgeProjection<dim>::vertex_b;
          projection.v      = p_b;
        }
      else
        {
          projection.region = EdgeProjection<dim>::interior;
          projection.t      = p_a_e / projection.e_squared;
          projection.v      = p_a - projection.t * projection.e;
        }
      projection.value = projection.v * projection.v;
      return projection;
    }



    /** The derivatives of an edge's squared distance, a and b at the
     *  output nodes @p node_a and @p node_b. */
    template <int dim, int n_coordinates>
    void
    fill_edge_squared_distance(const EdgeProjection<dim>      &projection,
                               const unsigned int              node_a,
                               const unsigned int              node_b,
                               SquaredDistance<n_coordinates> &result)
    {
      switch (projection.region)
        {
          case EdgeProjection<dim>::vertex_a:
            fill_hull_squared_distance<dim, 1>(projection.v,
                                               {{1.}},
                                               {},
                                               {},
                                               {{node_a}},
                                               result);
            break;
          case EdgeProjection<dim>::vertex_b:
            fill_hull_squared_distance<dim, 1>(projection.v,
                                               {{1.}},
                                               {},
                                               {},
                                               {{node_b}},
                                               result);
            break;
          case EdgeProjection<dim>::interior:
            fill_hull_squared_distance<dim, 2>(
              projection.v,
              {{1. - projection.t, projection.t}},
              {{projection.e}},
              {{{{1. / projection.e_squared}}}},
              {{node_a, node_b}},
              result);
            break;
        }
    }



    /** The closest feature of a triangle (a, b, c) to p. */
    struct TriangleProjection
    {
      /** Whether the closest point is in the interior of the face. */
      bool face;

      /** Face: the barycentric parameters, edges, |n|^2 and p minus the
       *  closest point. */
      double       beta, gamma;
      Tensor<1, 3> e1, e2;
      double       n_squared;
      Tensor<1, 3> v;
      double       value;

      /** Otherwise: the closest edge (0: ab, 1: bc, 2: ca) and its
       *  projection. */
      unsigned int      edge;
      EdgeProjection<3> edge_projection;
    };



    /**
     * The feature of the triangle closest to p (see
     * point_triangle_squared_distance()), shared by the value-only and the
     * full versions.
     */
    inline TriangleProjection
    project_onto_triangle(const Point<3> &p,
                          const Point<3> &a,
                          const Point<3> &b,
                          const Point<3> &c)
    {
      TriangleProjection projection;
      projection.e1         = b - a;
      projection.e2         = c - a;
      const Tensor<1, 3> e3 = c - b;
      const Tensor<1, 3> n  = cross_product_3d(projection.e1, projection.e2);
      projection.n_squared  = n * n;
      const double longest_edge_squared =
        std::max({projection.e1 * projection.e1,
                  projection.e2 * projection.e2,
                  e3 * e3});

      if (projection.n_squared >
          epsilon * longest_edge_squared * longest_edge_squared)
        {
          // The barycentric coordinates of the projection onto the plane
          // from cross products (Cramer's rule with det G = |n|^2, computed
          // without the cancellation of G11 G22 - G12^2).
          const Tensor<1, 3> w = p - a;
          projection.beta =
            (cross_product_3d(w, projection.e2) * n) / projection.n_squared;
          projection.gamma =
            (cross_product_3d(projection.e1, w) * n) / projection.n_squared;
          if (projection.beta >= 0. && projection.gamma >= 0. &&
              projection.beta + projection.gamma <= 1.)
            {
              projection.face = true;
              projection.v    = w - projection.beta * projection.e1 -
                             projection.gamma * projection.e2;
              projection.value = projection.v * projection.v;
              return projection;
            }
        }

      // The closest point of a convex set outside whose prism p lies is on
      // the set's boundary; for a degenerate triangle the boundary edges
      // cover the whole (flat) set.
      projection.face                              = false;
      const std::array<EdgeProjection<3>, 3> edges = {
        {project_onto_edge(p, a, b),
         project_onto_edge(p, b, c),
         project_onto_edge(p, c, a)}};
      projection.edge = 0;
      for (unsigned int k = 1; k < 3; ++k)
        if (edges[k].value < edges[projection.edge].value)
          projection.edge = k;
      projection.edge_projection = edges[projection.edge];
      projection.value           = projection.edge_projection.value;
      return projection;
    }
  } // namespace



  template <int dim>
  SquaredDistance<2 * dim>
  point_point_squared_distance(const Point<dim> &p, const Point<dim> &a)
  {
    SquaredDistance<2 * dim> result;
    fill_hull_squared_distance<dim, 1>(p - a, {{1.}}, {}, {}, {{1u}}, result);
    return result;
  }



  template <int dim>
  SquaredDistance<3 * dim>
  point_edge_squared_distance(const Point<dim> &p,
                              const Point<dim> &a,
                              const Point<dim> &b)
  {
    SquaredDistance<3 * dim> result;
    fill_edge_squared_distance(project_onto_edge(p, a, b), 1, 2, result);
    return result;
  }



  template <int dim>
  double
  point_edge_squared_distance_value(const Point<dim> &p,
                                    const Point<dim> &a,
                                    const Point<dim> &b)
  {
    return project_onto_edge(p, a, b).value;
  }



  SquaredDistance<12>
  point_triangle_squared_distance(const Point<3> &p,
                                  const Point<3> &a,
                                  const Point<3> &b,
                                  const Point<3> &c)
  {
    const TriangleProjection projection = project_onto_triangle(p, a, b, c);
    SquaredDistance<12>      result;
    if (projection.face)
      {
        const double e11         = projection.e1 * projection.e1;
        const double e12         = projection.e1 * projection.e2;
        const double e22         = projection.e2 * projection.e2;
        const double inverse_det = 1. / projection.n_squared;
        fill_hull_squared_distance<3, 3>(
          projection.v,
          {{1. - projection.beta - projection.gamma,
            projection.beta,
            projection.gamma}},
          {{projection.e1, projection.e2}},
          {{{{e22 * inverse_det, -e12 * inverse_det}},
            {{-e12 * inverse_det, e11 * inverse_det}}}},
          {{1u, 2u, 3u}},
          result);
      }
    else
      {
        // Edge k runs from triangle node k to node k+1 (mod 3).
        const unsigned int k = projection.edge;
        fill_edge_squared_distance(projection.edge_projection,
                                   k + 1,
                                   (k + 1) % 3 + 1,
                                   result);
      }
    return result;
  }



  double
  point_triangle_squared_distance_value(const Point<3> &p,
                                        const Point<3> &a,
                                        const Point<3> &b,
                                        const Point<3> &c)
  {
    return project_onto_triangle(p, a, b, c).value;
  }



  template SquaredDistance<4>
  point_point_squared_distance<2>(const Point<2> &, const Point<2> &);
  template SquaredDistance<6>
  point_point_squared_distance<3>(const Point<3> &, const Point<3> &);
  template SquaredDistance<6>
  point_edge_squared_distance<2>(const Point<2> &,
                                 const Point<2> &,
                                 const Point<2> &);
  template SquaredDistance<9>
  point_edge_squared_distance<3>(const Point<3> &,
                                 const Point<3> &,
                                 const Point<3> &);
  template double
  point_edge_squared_distance_value<2>(const Point<2> &,
                                       const Point<2> &,
                                       const Point<2> &);
  template double
  point_edge_squared_distance_value<3>(const Point<3> &,
                                       const Point<3> &,
                                       const Point<3> &);
} // namespace bfemp
