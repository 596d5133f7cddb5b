#ifndef bfemp_contact_collision_detection_h
#define bfemp_contact_collision_detection_h

// Conservative continuous collision detection (CCD) of a particle against a
// boundary primitive of an FEM mesh (a segment in 2D, a triangle in 3D).
// Along Newton's search direction every vertex moves linearly, x + t dx;
// the line search of the implicit solve (paper Section 5) starts at 0.9
// times the smallest step fraction t at which some particle-primitive
// distance would reach zero. Missing such a t (a false negative) lets a
// particle tunnel through the mesh and is never acceptable; stopping a bit
// early (a false positive, or a t below the exact time of impact) only
// shortens the step. The functions here therefore return a lower bound of
// the time of impact, rigorous also in floating point.

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * Parameters of the additive CCD (see point_edge_time_of_impact()).
   */
  struct CcdSettings
  {
    /**
     * The search stops, reporting a time of impact, once the distance has
     * dropped below this fraction of the distance at t = 0 (s in Li et al.
     * 2021). Smaller values give a time closer to the exact time of impact
     * at the cost of more iterations. In (0, 1).
     */
    double gap_fraction = 0.1;

    /**
     * Each step advances t by this fraction of the largest step that the
     * distance bound allows (current distance / l_p), so the distance can
     * drop to at most (1 - step_fraction) times its current value within
     * one step and never to zero. In (0, 1).
     */
    double step_fraction = 0.9;

    /**
     * Cap on the distance evaluations after the first. A query that hits the
     * cap returns the t it reached, which is still safe (there is no
     * contact before it) but may be far below the time of impact; such
     * queries are counted in CcdStatistics::capped. The cap is reached when
     * the primitive and the point slide past each other at a distance that
     * is tiny compared with their relative motion: every step then advances
     * t by only about distance / motion.
     */
    unsigned int max_iterations = 10000;
  };



  /**
   * Work counters that the CCD functions add to when given a pointer to one.
   * Not synchronized: use one object per thread and add them up.
   */
  struct CcdStatistics
  {
    /** Number of calls. */
    unsigned long queries = 0;

    /** Distance evaluations after the first one of each call, summed. */
    unsigned long iterations = 0;

    /**
     * Calls that stopped early because they hit
     * CcdSettings::max_iterations or because the next step was below the
     * resolution of t in double precision; their result is safe but may be
     * a (counted) false positive.
     */
    unsigned long capped = 0;

    CcdStatistics &
    operator+=(const CcdStatistics &other);
  };



  /**
   * A lower bound of the time of impact of the point p + t dp with the
   * segment between a + t da and b + t db for t in [0, t_max]: the
   * returned t satisfies
   * - the distance is positive on all of [0, t] (no contact up to t, which
   *   holds rigorously, including the rounding errors of the evaluation);
   * - t < t_max, and the distance at t dropped below
   *   settings.gap_fraction times the distance at 0 (or the search was
   *   capped, see CcdSettings::max_iterations);
   * or it is +infinity: there is no contact for t in [0, t_max].
   *
   * The result is 0 if the point touches the segment at t = 0 or is so
   * close to it that the distance cannot be told from zero within the
   * rounding errors of evaluating it (about 1e-14 times the size of the
   * configuration). With no relative motion the result is +infinity unless
   * it is 0.
   *
   * Algorithm: the additive CCD (ACCD) of M. Li, D. M. Kaufman, C. Jiang,
   * "Codimensional incremental potential contact", ACM Trans. Graph. 40(4),
   * 2021, Section 5. The mean displacement of the vertices (here: the point
   * and the segment's ends) is subtracted from every displacement, which
   * changes no distance. The distance d(t) then changes no faster than
   * l_p = |dp| + max(|da|, |db|) (the relative displacements), since the
   * point moves by at most |dp| dt and every point of the primitive, a
   * convex combination of its vertices, by at most max(|da|, |db|) dt.
   * Hence, starting from t = 0, a step of step_fraction * d(t) / l_p can
   * at most reduce the distance to (1 - step_fraction) d(t) > 0; the steps
   * are repeated until the distance falls below gap_fraction * d(0)
   * (reported as the time of impact) or t would pass t_max (no contact).
   *
   * Floating point: the distance used in the steps is a lower bound of the
   * exact one, namely the computed distance minus a bound of its rounding
   * errors (including those of the positions at t); l_p is rounded up; and
   * a step that rounding of t would make longer than the distance bound
   * allows is shortened by ulps. If t can no longer advance, the current t
   * is returned (counted as capped).
   *
   * @p t_max must be finite and >= 0, the settings' fractions in (0, 1),
   * max_iterations >= 1, and the coordinates finite (all checked, throwing
   * an exception). If @p statistics is not null, the work of the call is
   * added to it.
   *
   * Instantiated for dim = 2 (point-edge contact of 2D particles) and
   * dim = 3.
   */
  template <int dim>
  double
  point_edge_time_of_impact(const Point<dim>     &p,
                            const Point<dim>     &a,
                            const Point<dim>     &b,
                            const Tensor<1, dim> &dp,
                            const Tensor<1, dim> &da,
                            const Tensor<1, dim> &db,
                            const double          t_max      = 1.,
                            const CcdSettings    &settings   = CcdSettings(),
                            CcdStatistics        *statistics = nullptr);

  /**
   * A lower bound of the time of impact of the point p + t dp with the
   * (closed) triangle with the vertices a + t da, b + t db, c + t dc, for t
   * in [0, t_max], with the same meaning, algorithm and guarantees as
   * point_edge_time_of_impact() (here l_p = |dp| + max(|da|, |db|, |dc|)
   * after subtracting the mean displacement of the four vertices).
   *
   * Degenerate triangles (collinear or coincident vertices, at any t) are
   * handled: the distance is then that to the union of the edges, which is
   * what the closed degenerate triangle is. Near-degenerate triangles are
   * handled conservatively: where the plane of the triangle cannot be
   * computed accurately the distance bound falls back to the distance to the
   * edges minus the triangle's inradius.
   */
  double
  point_triangle_time_of_impact(const Point<3>     &p,
                                const Point<3>     &a,
                                const Point<3>     &b,
                                const Point<3>     &c,
                                const Tensor<1, 3> &dp,
                                const Tensor<1, 3> &da,
                                const Tensor<1, 3> &db,
                                const Tensor<1, 3> &dc,
                                const double        t_max      = 1.,
                                const CcdSettings  &settings   = CcdSettings(),
                                CcdStatistics      *statistics = nullptr);
} // namespace bfemp

#endif
