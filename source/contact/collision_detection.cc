#include <bfemp/contact/collision_detection.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace bfemp
{
  namespace
  {
    constexpr double epsilon  = std::numeric_limits<double>::epsilon();
    constexpr double infinity = std::numeric_limits<double>::infinity();

    // Error bounds, in units of epsilon times the size M of the evaluated
    // configuration (the largest |vertex - point|). A forward error analysis
    // of the evaluations below gives factors of about 18 (segment distance)
    // and 7 (1 + kappa) (plane distance), and about 3 for the positions at
    // t; the factors used have a margin of 3 to 4 on top. They assume that
    // no intermediate result underflows (coordinate differences either zero
    // or above about 1e-150), as holds for any mesh in SI units.
    constexpr double evaluation_error = 64.;
    constexpr double position_error   = 8.;



    /**
     * The squared distance from the origin to the segment [A, B] (value
     * only): the point is translated to the origin first, so that rounding
     * errors scale with the size of the configuration, not with the
     * magnitude of the coordinates. A degenerate segment (A = B) is the
     * point A. Any clamped parameter s in [0, 1] gives a point of the
     * segment, so errors in s only ever overestimate the distance, by at
     * most |s - s*| |B - A|, which the error bound covers.
     *
     * This duplicates, in the form the error bounds need (relative to the
     * point), the value-only point_edge_squared_distance_value() of
     * bfemp/contact/distance.h.
     */
    template <int dim>
    double
    segment_squared_distance_to_origin(const Tensor<1, dim> &A,
                                       const Tensor<1, dim> &B)
    {
      const Tensor<1, dim> e  = B - A;
      const double         ee = e * e;
      double               s  = 0.;
      if (ee > 0.)
        {
          s = -(A * e) / ee;
          // written so that a NaN (from an overflow) gives 0
          s = (s > 0.) ? std::min(s, 1.) : 0.;
        }
      const Tensor<1, dim> closest = A + s * e;
      return closest * closest;
    }



    /** max(|A|, |B|, ...) of the relative positions of the vertices. */
    template <int dim, std::size_t n>
    double
    configuration_size(const std::array<Tensor<1, dim>, n> &vertices)
    {
      double largest = 0.;
      for (const Tensor<1, dim> &v : vertices)
        largest = std::max(largest, v.norm_square());
      return std::sqrt(largest) * (1. + 4. * epsilon);
    }



    /**
     * A lower bound of the distance from the origin to the segment with the
     * ends @p vertices, in exact arithmetic: the computed distance minus the
     * bound of its rounding error.
     */
    template <int dim>
    double
    distance_lower_bound(const std::array<Tensor<1, dim>, 2> &vertices)
    {
      const double size = configuration_size(vertices);
      return std::sqrt(
               segment_squared_distance_to_origin(vertices[0], vertices[1])) -
             evaluation_error * epsilon * size;
    }



    /**
     * A lower bound of the distance from the origin to the closed triangle
     * with the vertices A, B, C, in exact arithmetic. Three bounds combine:
     * - the distance to the edges (exact whenever the projection of the
     *   origin onto the plane lies outside the triangle, and for degenerate
     *   triangles, which are the union of their edges);
     * - the distance to the plane, a lower bound everywhere; its error grows
     *   like kappa = |e1| |e2| / |e1 x e2| as the triangle degenerates and
     *   the normal loses accuracy;
     * - the distance to the edges minus the inradius r = |e1 x e2| /
     *   perimeter, also a lower bound everywhere, since every point of a
     *   triangle lies within r of its boundary. This one is accurate where
     *   the plane is not: for thin triangles.
     * The edge distance alone is used only where the barycentric
     * coordinates of the projection show, beyond their rounding errors,
     * that the projection is outside; any doubt keeps the other two bounds,
     * which are valid everywhere, so a misclassification can only
     * underestimate the distance.
     */
    double
    distance_lower_bound(const std::array<Tensor<1, 3>, 3> &vertices)
    {
      const Tensor<1, 3> &A    = vertices[0];
      const Tensor<1, 3> &B    = vertices[1];
      const Tensor<1, 3> &C    = vertices[2];
      const double        size = configuration_size(vertices);

      const double edges =
        std::sqrt(std::min({segment_squared_distance_to_origin(A, B),
                            segment_squared_distance_to_origin(B, C),
                            segment_squared_distance_to_origin(C, A)})) -
        evaluation_error * epsilon * size;

      const Tensor<1, 3> e1        = B - A;
      const Tensor<1, 3> e2        = C - A;
      const Tensor<1, 3> e3        = C - B;
      const double       e1_norm   = e1.norm();
      const double       e2_norm   = e2.norm();
      const double       perimeter = e1_norm + e2_norm + e3.norm();
      // A zero perimeter means A = B = C exactly (a floating-point difference
      // is zero only for equal operands): a point, inradius 0, and the edge
      // distance is exact.
      if (perimeter == 0.)
        return edges;

      const Tensor<1, 3> n      = cross_product_3d(e1, e2);
      const double       n_norm = n.norm();
      // |n| is known up to about 5 u |e1| |e2| <= 10 epsilon size^2.
      const double inradius = (n_norm + 16. * epsilon * size * size) /
                              perimeter * (1. + 8. * epsilon);
      if (n_norm == 0.)
        return edges - inradius;

      const double kappa = e1_norm * e2_norm / n_norm;
      const double plane = std::abs(n * A) / n_norm -
                           evaluation_error * epsilon * size * (1. + kappa);

      // Barycentric coordinates of the projection, unnormalized (they sum to
      // |n|^2), and a bound of their rounding errors (about 22 eps size^4).
      const double tolerance = 64. * epsilon * (size * size) * (size * size);
      const bool   outside   = n * cross_product_3d(B, C) < -tolerance ||
                           n * cross_product_3d(C, A) < -tolerance ||
                           n * cross_product_3d(A, B) < -tolerance;
      if (outside)
        return std::max(edges, plane);
      return std::max(plane, edges - inradius);
    }



    void
    check_arguments(const double       t_max,
                    const CcdSettings &settings,
                    const bool         coordinates_finite)
    {
      AssertThrow(std::isfinite(t_max) && t_max >= 0.,
                  ExcMessage("CCD: t_max = " + std::to_string(t_max) +
                             " must be finite and >= 0"));
      AssertThrow(settings.gap_fraction > 0. && settings.gap_fraction < 1.,
                  ExcMessage("CCD: gap_fraction must be in (0, 1)"));
      AssertThrow(settings.step_fraction > 0. && settings.step_fraction < 1.,
                  ExcMessage("CCD: step_fraction must be in (0, 1)"));
      AssertThrow(settings.max_iterations >= 1,
                  ExcMessage("CCD: max_iterations must be at least 1"));
      AssertThrow(coordinates_finite,
                  ExcMessage("CCD: a position or displacement is not finite"));
    }



    template <int dim>
    bool
    is_finite(const Tensor<1, dim> &v)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (!std::isfinite(v[d]))
          return false;
      return true;
    }



    /**
     * The additive CCD (see point_edge_time_of_impact()) of a point against
     * a primitive with n vertices, all moving linearly.
     *
     * The configuration is evaluated in a frame with the origin at the
     * point at t = 0 and moving with the mean displacement, so that the
     * rounding errors depend on the relative positions and motions only (a
     * body translating by 1e6 does not lose the accuracy of a 1e-3 gap).
     * The computed relative displacements u_j = fl(d_j - mean) differ from
     * the exact ones by at most u |u_j| per component; the frame's own
     * velocity (the rounded mean) is irrelevant, as any common velocity is.
     */
    template <int dim, std::size_t n>
    double
    additive_ccd(const Point<dim>                    &point,
                 const std::array<Point<dim>, n>     &primitive,
                 const Tensor<1, dim>                &point_motion,
                 const std::array<Tensor<1, dim>, n> &primitive_motion,
                 const double                         t_max,
                 const CcdSettings                   &settings,
                 CcdStatistics                       *statistics)
    {
      using Vectors = std::array<Tensor<1, dim>, n>;

      bool finite = is_finite(point) && is_finite(point_motion);
      for (std::size_t j = 0; j < n; ++j)
        finite =
          finite && is_finite(primitive[j]) && is_finite(primitive_motion[j]);
      check_arguments(t_max, settings, finite);

      Tensor<1, dim> mean = point_motion;
      for (const Tensor<1, dim> &d : primitive_motion)
        mean += d;
      mean /= static_cast<double>(n + 1);

      const Tensor<1, dim> point_velocity = point_motion - mean;
      Vectors              start, velocity;
      double               start_size = 0., largest_velocity = 0.;
      for (std::size_t j = 0; j < n; ++j)
        {
          start[j]         = primitive[j] - point;
          velocity[j]      = primitive_motion[j] - mean;
          start_size       = std::max(start_size, start[j].norm());
          largest_velocity = std::max(largest_velocity, velocity[j].norm());
        }
      start_size *= 1. + 4. * epsilon;
      // l_p, rounded up to cover the rounding of the norms and of u_j.
      const double lp =
        (point_velocity.norm() + largest_velocity) * (1. + 8. * epsilon);

      // A lower bound of the exact distance at t: the evaluation's bound at
      // the computed positions minus a bound of the positions' errors, which
      // grow with the travelled distance.
      const auto distance_at = [&](const double t) {
        const Tensor<1, dim> moved_point = t * point_velocity;
        Vectors              relative;
        for (std::size_t j = 0; j < n; ++j)
          relative[j] = (start[j] + t * velocity[j]) - moved_point;
        return distance_lower_bound(relative) -
               position_error * epsilon * (start_size + t * lp);
      };

      if (statistics != nullptr)
        ++statistics->queries;
      unsigned int iterations = 0;
      const auto   finish     = [&](const double result, const bool capped) {
        if (statistics != nullptr)
          {
            statistics->iterations += iterations;
            statistics->capped += capped ? 1 : 0;
          }
        return result;
      };

      const double initial_distance = distance_at(0.);
      if (!(initial_distance > 0.))
        return finish(0., false);
      if (lp == 0.)
        return finish(infinity, false);

      const double target   = settings.gap_fraction * initial_distance;
      double       t        = 0.;
      double       distance = initial_distance;
      while (true)
        {
          // No contact on [t, t + safe]: the exact distance there is at
          // least distance - lp s > 0. The factor keeps the rounded quotient
          // below distance / lp.
          const double safe = distance / lp * (1. - 4. * epsilon);
          const double step = settings.step_fraction * safe;
          // t_max - t is exact or rounded by u relative; the gap between
          // step and safe is far larger than that.
          if (t_max - t <= step)
            return finish(infinity, false);
          if (iterations == settings.max_iterations)
            return finish(t, true);

          // Rounding t + step up can exceed the safe step once the step is
          // comparable to ulp(t); t_next - t is then computed exactly
          // (Sterbenz), so the check is exact.
          double t_next = t + step;
          while (t_next > t && t_next - t > safe)
            t_next = std::nextafter(t_next, 0.);
          if (!(t_next > t))
            return finish(t, true); // t cannot advance any more

          t        = t_next;
          distance = distance_at(t);
          ++iterations;
          if (distance < target)
            return finish(t, false);
        }
    }
  } // namespace



  CcdStatistics &
  CcdStatistics::operator+=(const CcdStatistics &other)
  {
    queries += other.queries;
    iterations += other.iterations;
    capped += other.capped;
    return *this;
  }



  template <int dim>
  double
  point_edge_time_of_impact(const Point<dim>     &p,
                            const Point<dim>     &a,
                            const Point<dim>     &b,
                            const Tensor<1, dim> &dp,
                            const Tensor<1, dim> &da,
                            const Tensor<1, dim> &db,
                            const double          t_max,
                            const CcdSettings    &settings,
                            CcdStatistics        *statistics)
  {
    return additive_ccd<dim, 2>(p,
                                {{a, b}},
                                dp,
                                {{da, db}},
                                t_max,
                                settings,
                                statistics);
  }



  double
  point_triangle_time_of_impact(const Point<3>     &p,
                                const Point<3>     &a,
                                const Point<3>     &b,
                                const Point<3>     &c,
                                const Tensor<1, 3> &dp,
                                const Tensor<1, 3> &da,
                                const Tensor<1, 3> &db,
                                const Tensor<1, 3> &dc,
                                const double        t_max,
                                const CcdSettings  &settings,
                                CcdStatistics      *statistics)
  {
    return additive_ccd<3, 3>(p,
                              {{a, b, c}},
                              dp,
                              {{da, db, dc}},
                              t_max,
                              settings,
                              statistics);
  }



  template double
  point_edge_time_of_impact<2>(const Point<2> &,
                               const Point<2> &,
                               const Point<2> &,
                               const Tensor<1, 2> &,
                               const Tensor<1, 2> &,
                               const Tensor<1, 2> &,
                               const double,
                               const CcdSettings &,
                               CcdStatistics *);
  template double
  point_edge_time_of_impact<3>(const Point<3> &,
                               const Point<3> &,
                               const Point<3> &,
                               const Tensor<1, 3> &,
                               const Tensor<1, 3> &,
                               const Tensor<1, 3> &,
                               const double,
                               const CcdSettings &,
                               CcdStatistics *);
} // namespace bfemp
