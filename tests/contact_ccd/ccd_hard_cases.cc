// point_edge_time_of_impact() (2D and 3D) and point_triangle_time_of_impact()
// against an independent reference time of impact in long double:
// - point-edge: at a contact p lies on the line through a and b, so every
//   component of (b - a) x (p - a) (one in 2D, three in 3D), a quadratic in
//   t, vanishes; the candidates are the roots of these quadratics in [0, 1]
//   (bisection on the pieces where they are monotone, plus their critical
//   points for double roots), and the first candidate at which the long
//   double point-segment distance is below a tolerance of 4e-15 times the
//   size of the configuration is the time of impact. If the quadratics vanish
//   identically (the point moves on the line of the segment, or the
//   segment is a point), contact first happens where p meets a or b, found
//   from the linear p - a and p - b;
// - point-triangle: the same with the coplanarity cubic
//   det(b - a, c - a, p - a), and the closed triangle's distance at the
//   candidates: this covers contacts with
//   the faces, edges and vertices. If the cubic vanishes identically (the
//   point moves in the triangle's plane, or the triangle is degenerate at
//   every t), contact first happens on the triangle's boundary: the minimum
//   over the three edges' references;
// - in these degenerate cases a dense sampling of the distance (with golden
//   section search at its local minima) gives a second reference; the
//   smaller of the two times is used.
// Requirements checked for every case: no false negative (when the
// reference has a contact at T, the CCD returns t <= T), and the distance
// at the returned t (and on a sample of [0, t]) is positive. Counted and
// printed: false positives (a finite t although there is no contact before
// t_max = 1), capped searches, the ratio t / T and the iterations.

#include <bfemp/contact/collision_detection.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  using Real = long double;

  const double infinity      = std::numeric_limits<double>::infinity();
  const Real   real_infinity = std::numeric_limits<Real>::infinity();
  const Real   real_epsilon  = std::numeric_limits<Real>::epsilon();

  /** @p x with @p digits significant digits. */
  std::string
  format(const double x, const int digits)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << x;
    return s.str();
  }

  // ------------------------------------------------------------------------
  // Cases: index 0 is the point, 1 .. n the primitive's vertices.

  template <int dim, std::size_t n>
  struct Case
  {
    std::string                       name;
    std::array<Point<dim>, n + 1>     x;
    std::array<Tensor<1, dim>, n + 1> dx;
  };

  template <int dim>
  using RealVector = std::array<Real, dim>;

  /** A point moving linearly, start + t velocity, in long double. */
  template <int dim>
  struct Trajectory
  {
    RealVector<dim> start, velocity;

    RealVector<dim>
    at(const Real t) const
    {
      RealVector<dim> x;
      for (int d = 0; d < dim; ++d)
        x[d] = start[d] + t * velocity[d];
      return x;
    }
  };

  template <int dim, std::size_t n>
  Trajectory<dim>
  trajectory(const Case<dim, n> &c, const unsigned int j)
  {
    Trajectory<dim> result;
    for (int d = 0; d < dim; ++d)
      {
        result.start[d]    = c.x[j][d];
        result.velocity[d] = c.dx[j][d];
      }
    return result;
  }

  template <int dim>
  RealVector<dim>
  difference(const RealVector<dim> &a, const RealVector<dim> &b)
  {
    RealVector<dim> r;
    for (int d = 0; d < dim; ++d)
      r[d] = a[d] - b[d];
    return r;
  }

  template <int dim>
  Real
  dot(const RealVector<dim> &a, const RealVector<dim> &b)
  {
    Real r = 0;
    for (int d = 0; d < dim; ++d)
      r += a[d] * b[d];
    return r;
  }

  RealVector<3>
  cross(const RealVector<3> &a, const RealVector<3> &b)
  {
    return {{a[1] * b[2] - a[2] * b[1],
             a[2] * b[0] - a[0] * b[2],
             a[0] * b[1] - a[1] * b[0]}};
  }

  // ------------------------------------------------------------------------
  // Reference distances in long double.

  template <int dim>
  Real
  segment_distance(const RealVector<dim> &p,
                   const RealVector<dim> &a,
                   const RealVector<dim> &b)
  {
    const RealVector<dim> e  = difference<dim>(b, a);
    const RealVector<dim> w  = difference<dim>(p, a);
    const Real            ee = dot<dim>(e, e);
    Real                  s  = ee > 0 ? dot<dim>(w, e) / ee : 0;
    s                        = std::min<Real>(std::max<Real>(s, 0), 1);
    RealVector<dim> r;
    for (int d = 0; d < dim; ++d)
      r[d] = w[d] - s * e[d];
    return std::sqrt(dot<dim>(r, r));
  }

  /**
   * The distance to the closed triangle: to its plane if the projection of
   * p lies inside (the three triple products n . ((b - p) x (c - p)) etc.,
   * which are accurate for points near slivers, have the sign of n . n),
   * and to the nearest edge otherwise. Triangles without interior are the
   * union of their edges.
   */
  Real
  triangle_distance(const RealVector<3> &p,
                    const RealVector<3> &a,
                    const RealVector<3> &b,
                    const RealVector<3> &c)
  {
    const RealVector<3> ab = difference<3>(b, a), ac = difference<3>(c, a);
    const RealVector<3> n     = cross(ab, ac);
    const Real          nn    = dot<3>(n, n);
    const Real          edges = std::min({segment_distance<3>(p, a, b),
                                          segment_distance<3>(p, b, c),
                                          segment_distance<3>(p, c, a)});
    if (nn == 0)
      return edges;
    const RealVector<3> pa = difference<3>(a, p), pb = difference<3>(b, p),
                        pc = difference<3>(c, p);
    if (dot<3>(n, cross(pb, pc)) >= 0 && dot<3>(n, cross(pc, pa)) >= 0 &&
        dot<3>(n, cross(pa, pb)) >= 0)
      return std::min(edges, std::abs(dot<3>(n, pa)) / std::sqrt(nn));
    return edges;
  }

  template <int dim, std::size_t n>
  Real
  reference_distance(const Case<dim, n> &c, const Real t)
  {
    std::array<RealVector<dim>, n + 1> x;
    for (unsigned int j = 0; j <= n; ++j)
      x[j] = trajectory(c, j).at(t);
    if constexpr (n == 2)
      return segment_distance<dim>(x[0], x[1], x[2]);
    else
      return triangle_distance(x[0], x[1], x[2], x[3]);
  }

  /** Largest relative distance a vertex can reach, for the tolerances. */
  template <int dim, std::size_t n>
  Real
  configuration_scale(const Case<dim, n> &c)
  {
    Real scale = 0;
    for (unsigned int j = 1; j <= n; ++j)
      scale =
        std::max<Real>(scale,
                       (c.x[j] - c.x[0]).norm() + (c.dx[j] - c.dx[0]).norm());
    return scale;
  }

  // ------------------------------------------------------------------------
  // Polynomials in t with the magnitude of the products each coefficient
  // is summed from, so that coefficients that vanish in exact arithmetic
  // can be told from rounding noise.

  struct Polynomial
  {
    std::array<Real, 4> c         = {{0, 0, 0, 0}};
    std::array<Real, 4> magnitude = {{0, 0, 0, 0}};
  };

  struct Linear
  {
    Real c0, c1;
  };

  Polynomial
  product(const Linear &a, const Linear &b)
  {
    Polynomial p;
    p.c[0]         = a.c0 * b.c0;
    p.c[1]         = a.c0 * b.c1 + a.c1 * b.c0;
    p.c[2]         = a.c1 * b.c1;
    p.magnitude[0] = std::abs(p.c[0]);
    p.magnitude[1] = std::abs(a.c0 * b.c1) + std::abs(a.c1 * b.c0);
    p.magnitude[2] = std::abs(p.c[2]);
    return p;
  }

  Polynomial
  product(const Polynomial &a, const Linear &b)
  {
    Polynomial p;
    for (unsigned int k = 0; k < 3; ++k)
      {
        p.c[k] += a.c[k] * b.c0;
        p.c[k + 1] += a.c[k] * b.c1;
        p.magnitude[k] += a.magnitude[k] * std::abs(b.c0);
        p.magnitude[k + 1] += a.magnitude[k] * std::abs(b.c1);
      }
    return p;
  }

  Polynomial
  combine(const Polynomial &a, const Polynomial &b, const Real sign)
  {
    Polynomial p;
    for (unsigned int k = 0; k < 4; ++k)
      {
        p.c[k]         = a.c[k] + sign * b.c[k];
        p.magnitude[k] = a.magnitude[k] + b.magnitude[k];
      }
    return p;
  }

  /** Coefficients within rounding noise of zero are set to zero. */
  Polynomial
  without_noise(Polynomial p)
  {
    for (unsigned int k = 0; k < 4; ++k)
      if (std::abs(p.c[k]) <= 64 * real_epsilon * p.magnitude[k])
        p.c[k] = 0;
    return p;
  }

  bool
  vanishes(const Polynomial &p)
  {
    return p.c[0] == 0 && p.c[1] == 0 && p.c[2] == 0 && p.c[3] == 0;
  }

  Real
  evaluate(const Polynomial &p, const Real t)
  {
    return ((p.c[3] * t + p.c[2]) * t + p.c[1]) * t + p.c[0];
  }

  /** Real roots of c0 + c1 t + c2 t^2 (c2 != 0), cancellation free. */
  std::vector<Real>
  quadratic_roots(const Real c0, const Real c1, const Real c2)
  {
    const Real discriminant = c1 * c1 - 4 * c2 * c0;
    if (discriminant < 0)
      return {-c1 / (2 * c2)}; // nearest real point, a harmless candidate
    const Real q = -(c1 + std::copysign(std::sqrt(discriminant), c1)) / 2;
    if (q == 0)
      return {0};
    return {q / c2, c0 / q};
  }

  /**
   * Candidate roots of p in [0, 1]: on each piece between critical points
   * p is monotone and a sign change is bisected to adjacent long doubles
   * (both are returned); the critical points themselves are candidates for
   * roots of even multiplicity.
   */
  std::vector<Real>
  candidate_roots(const Polynomial &p)
  {
    unsigned int degree = 3;
    while (degree > 0 && p.c[degree] == 0)
      --degree;
    std::vector<Real> candidates;
    if (degree == 0)
      return candidates;

    std::vector<Real> breaks = {0, 1};
    std::vector<Real> critical;
    if (degree == 3)
      critical = quadratic_roots(p.c[1], 2 * p.c[2], 3 * p.c[3]);
    else if (degree == 2)
      critical = {-p.c[1] / (2 * p.c[2])};
    for (const Real t : critical)
      if (t > 0 && t < 1)
        {
          breaks.push_back(t);
          candidates.push_back(t);
        }
    std::sort(breaks.begin(), breaks.end());

    for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
      {
        Real       lo = breaks[k], hi = breaks[k + 1];
        const Real f_lo = evaluate(p, lo), f_hi = evaluate(p, hi);
        if (f_lo == 0)
          candidates.push_back(lo);
        if (f_hi == 0)
          candidates.push_back(hi);
        if ((f_lo < 0) == (f_hi < 0) || f_lo == 0 || f_hi == 0)
          continue;
        for (unsigned int i = 0; i < 200; ++i)
          {
            const Real mid = lo + (hi - lo) / 2;
            if (mid <= lo || mid >= hi)
              break;
            if ((evaluate(p, mid) < 0) == (f_lo < 0))
              lo = mid;
            else
              hi = mid;
          }
        candidates.push_back(lo);
        candidates.push_back(hi);
      }
    return candidates;
  }

  template <int dim>
  Linear
  component(const Trajectory<dim> &a, const Trajectory<dim> &b, const int d)
  {
    return {a.start[d] - b.start[d], a.velocity[d] - b.velocity[d]};
  }

  /** The root in [0, 1] of the linear vector a(t) - b(t), if any. */
  template <int dim>
  void
  add_meeting_time(const Trajectory<dim> &a,
                   const Trajectory<dim> &b,
                   std::vector<Real>     &candidates)
  {
    int  largest = 0;
    Real speed   = 0;
    for (int d = 0; d < dim; ++d)
      {
        const Real v = std::abs(a.velocity[d] - b.velocity[d]);
        if (v > speed)
          speed = v, largest = d;
      }
    if (speed == 0)
      return; // constant: a contact at all, if any, is at t = 0
    const Linear w = component<dim>(a, b, largest);
    const Real   t = -w.c0 / w.c1;
    if (t >= 0 && t <= 1)
      candidates.push_back(t);
  }

  template <int dim>
  Real
  first_contact(std::vector<Real>                candidates,
                const std::function<Real(Real)> &distance,
                const Real                       tolerance)
  {
    candidates.push_back(0);
    std::sort(candidates.begin(), candidates.end());
    for (const Real t : candidates)
      if (t >= 0 && t <= 1 && distance(t) <= tolerance)
        return t;
    return real_infinity;
  }

  // ------------------------------------------------------------------------
  // Exact references.

  /** Time of impact of p with the segment [a, b], or infinity. */
  template <int dim>
  Real
  edge_reference(const Trajectory<dim> &p,
                 const Trajectory<dim> &a,
                 const Trajectory<dim> &b,
                 const Real             tolerance,
                 bool                  &degenerate)
  {
    // (b - a) x (p - a), componentwise: e_i w_j - e_j w_i.
    std::vector<Polynomial> components;
    const auto              cross_component = [&](const int i, const int j) {
      return without_noise(
        combine(product(component<dim>(b, a, i), component<dim>(p, a, j)),
                product(component<dim>(b, a, j), component<dim>(p, a, i)),
                -1));
    };
    if (dim == 2)
      components.push_back(cross_component(0, 1));
    else
      {
        components.push_back(cross_component(1, 2));
        components.push_back(cross_component(2, 0));
        components.push_back(cross_component(0, 1));
      }

    std::vector<Real> candidates;
    degenerate = true;
    for (const Polynomial &poly : components)
      if (!vanishes(poly))
        {
          degenerate                    = false;
          const std::vector<Real> roots = candidate_roots(poly);
          candidates.insert(candidates.end(), roots.begin(), roots.end());
        }
    if (degenerate)
      {
        // p always on the line of the segment (or the segment a point):
        // the contact starts where p meets an end.
        add_meeting_time<dim>(p, a, candidates);
        add_meeting_time<dim>(p, b, candidates);
      }
    return first_contact<dim>(
      candidates,
      [&](const Real t) {
        return segment_distance<dim>(p.at(t), a.at(t), b.at(t));
      },
      tolerance);
  }

  Real
  triangle_reference(const Trajectory<3> &p,
                     const Trajectory<3> &a,
                     const Trajectory<3> &b,
                     const Trajectory<3> &c,
                     const Real           tolerance,
                     bool                &degenerate)
  {
    // det(b - a, c - a, p - a) = (b - a) . ((c - a) x (p - a))
    Polynomial cubic;
    for (int i = 0; i < 3; ++i)
      {
        const int        j = (i + 1) % 3, k = (i + 2) % 3;
        const Polynomial cross_i =
          combine(product(component<3>(c, a, j), component<3>(p, a, k)),
                  product(component<3>(c, a, k), component<3>(p, a, j)),
                  -1);
        cubic = combine(cubic, product(cross_i, component<3>(b, a, i)), 1);
      }
    cubic = without_noise(cubic);

    const auto distance = [&](const Real t) {
      return triangle_distance(p.at(t), a.at(t), b.at(t), c.at(t));
    };
    degenerate = vanishes(cubic);
    if (degenerate)
      {
        // Coplanar at every t: the first contact is on the boundary.
        if (distance(0) <= tolerance)
          return 0;
        bool unused;
        return std::min({edge_reference<3>(p, a, b, tolerance, unused),
                         edge_reference<3>(p, b, c, tolerance, unused),
                         edge_reference<3>(p, c, a, tolerance, unused)});
      }
    return first_contact<3>(candidate_roots(cubic), distance, tolerance);
  }

  /**
   * The second reference: the first t in [0, 1] where the sampled distance
   * is below the tolerance, with golden section search at each local
   * minimum of the samples (to find contacts at a single instant) and
   * bisection for the first crossing.
   */
  template <typename Distance>
  Real
  sampled_reference(const Distance &distance, const Real tolerance)
  {
    const unsigned int n_samples = 4096;
    const auto         bisect    = [&](Real lo, Real hi) {
      // distance(lo) > tolerance >= distance(hi)
      for (unsigned int i = 0; i < 100; ++i)
        {
          const Real mid = lo + (hi - lo) / 2;
          if (distance(mid) <= tolerance)
            hi = mid;
          else
            lo = mid;
        }
      return hi;
    };
    const auto local_minimum = [&](Real lo, Real hi) {
      const Real ratio = (std::sqrt(5.L) - 1) / 2;
      Real       x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
      Real       f1 = distance(x1), f2 = distance(x2);
      for (unsigned int i = 0; i < 120; ++i)
        if (f1 < f2)
          {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - ratio * (hi - lo), f1 = distance(x1);
          }
        else
          {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + ratio * (hi - lo), f2 = distance(x2);
          }
      return f1 < f2 ? x1 : x2;
    };

    std::vector<Real> d(n_samples + 1);
    for (unsigned int i = 0; i <= n_samples; ++i)
      {
        const Real t = static_cast<Real>(i) / n_samples;
        d[i]         = distance(t);
        if (d[i] <= tolerance)
          return i == 0 ? 0 : bisect(static_cast<Real>(i - 1) / n_samples, t);
        if (i >= 2 && d[i - 1] <= d[i - 2] && d[i - 1] <= d[i])
          {
            const Real lo = static_cast<Real>(i - 2) / n_samples;
            const Real m  = local_minimum(lo, t);
            if (distance(m) <= tolerance)
              return bisect(lo, m);
          }
      }
    return real_infinity;
  }

  struct Reference
  {
    Real time       = real_infinity;
    bool degenerate = false;
    bool agree      = true; // exact and sampled (degenerate cases only)
  };

  template <int dim, std::size_t n>
  Reference
  reference(const Case<dim, n> &c)
  {
    const Real      tolerance = 4e-15L * configuration_scale(c);
    Reference       r;
    Trajectory<dim> p = trajectory(c, 0), a = trajectory(c, 1),
                    b = trajectory(c, 2);
    if constexpr (n == 2)
      r.time = edge_reference<dim>(p, a, b, tolerance, r.degenerate);
    else
      r.time =
        triangle_reference(p, a, b, trajectory(c, 3), tolerance, r.degenerate);
    if (r.degenerate)
      {
        const Real sampled = sampled_reference(
          [&](const Real t) { return reference_distance(c, t); },
          tolerance);
        r.agree = (std::isinf(sampled) && std::isinf(r.time)) ||
                  std::abs(sampled - r.time) <= 1e-9L;
        r.time = std::min(r.time, sampled);
      }
    return r;
  }

  // ------------------------------------------------------------------------
  // The CCD and the checks.

  template <int dim, std::size_t n>
  double
  ccd(const Case<dim, n> &c, CcdStatistics &statistics)
  {
    if constexpr (n == 2)
      return point_edge_time_of_impact<dim>(c.x[0],
                                            c.x[1],
                                            c.x[2],
                                            c.dx[0],
                                            c.dx[1],
                                            c.dx[2],
                                            1.,
                                            CcdSettings(),
                                            &statistics);
    else
      return point_triangle_time_of_impact(c.x[0],
                                           c.x[1],
                                           c.x[2],
                                           c.x[3],
                                           c.dx[0],
                                           c.dx[1],
                                           c.dx[2],
                                           c.dx[3],
                                           1.,
                                           CcdSettings(),
                                           &statistics);
  }

  struct Outcome
  {
    Reference     reference;
    double        t = infinity;
    CcdStatistics statistics;
    bool          false_negative = false;
    bool          unsafe         = false;
    bool          false_positive = false;
  };

  template <int dim, std::size_t n>
  Outcome
  run(const Case<dim, n> &c)
  {
    Outcome o;
    o.reference = reference(c);
    o.t         = ccd(c, o.statistics);
    if (std::isfinite(static_cast<double>(o.reference.time)))
      o.false_negative = !(o.t <= o.reference.time);
    else
      o.false_positive = std::isfinite(o.t);
    if (std::isfinite(o.t) && o.t > 0.)
      {
        // safe: t < t_max, and positive distances on [0, t]
        o.unsafe = !(o.t < 1.) || !(reference_distance(c, o.t) > 0);
        for (unsigned int i = 0; i < 256 && !o.unsafe; ++i)
          o.unsafe = !(reference_distance(c, o.t * i / 256.L) > 0);
      }
    return o;
  }

  /** Counts over a group of cases. */
  struct Summary
  {
    std::string  name;
    unsigned int cases = 0, contacts = 0, false_negatives = 0, unsafe = 0,
                 false_positives = 0, degenerate = 0, disagreements = 0;
    CcdStatistics statistics;
    unsigned long max_iterations = 0;
    double        min_ratio = infinity, ratio_sum = 0.;
    unsigned int  n_ratios = 0;

    void
    add(const Outcome &o)
    {
      ++cases;
      const bool contact = std::isfinite(static_cast<double>(o.reference.time));
      contacts += contact;
      false_negatives += o.false_negative;
      unsafe += o.unsafe;
      false_positives += o.false_positive;
      degenerate += o.reference.degenerate;
      disagreements += !o.reference.agree;
      statistics += o.statistics;
      max_iterations = std::max(max_iterations, o.statistics.iterations);
      if (contact && o.reference.time > 0 && std::isfinite(o.t))
        {
          const double ratio = o.t / static_cast<double>(o.reference.time);
          min_ratio          = std::min(min_ratio, ratio);
          ratio_sum += ratio;
          ++n_ratios;
        }
    }

    void
    print() const
    {
      deallog << name << ": " << cases << " cases, " << contacts
              << " with contact, " << false_negatives << " false negatives, "
              << unsafe << " unsafe, " << false_positives
              << " false positives (" << statistics.capped << " capped), "
              << degenerate << " degenerate references (" << disagreements
              << " disagreeing with sampling)" << std::endl;
      deallog << name << ": t/T min "
              << format(n_ratios > 0 ? min_ratio : 0., 3) << " mean "
              << format(n_ratios > 0 ? ratio_sum / n_ratios : 0., 3)
              << ", iterations mean "
              << format(static_cast<double>(statistics.iterations) / cases, 3)
              << " max " << max_iterations << std::endl;
      bfemp_tests::check(false_negatives == 0, name + ": no false negatives");
      bfemp_tests::check(unsafe == 0,
                         name + ": positive distance up to the result");
    }
  };

  template <int dim, std::size_t n>
  void
  print_case(const Case<dim, n> &c, const Outcome &o)
  {
    deallog << c.name << ": reference ";
    if (std::isfinite(static_cast<double>(o.reference.time)))
      deallog << "contact at "
              << format(static_cast<double>(o.reference.time), 8);
    else
      deallog << "none";
    if (o.reference.degenerate)
      deallog << " (degenerate" << (o.reference.agree ? ")" : ", disagree)");
    deallog << ", CCD ";
    if (std::isfinite(o.t))
      deallog << format(o.t, 6);
    else
      deallog << "none";
    deallog << ", " << o.statistics.iterations << " iterations"
            << (o.statistics.capped ? " (capped)" : "")
            << (o.false_negative   ? " FALSE NEGATIVE"
                : o.unsafe         ? " UNSAFE"
                : o.false_positive ? " (false positive)"
                                   : "")
            << std::endl;
  }

  // ------------------------------------------------------------------------
  // Hard cases.

  template <int dim>
  Point<dim>
  make_point(const double x, const double y, const double z = 0.)
  {
    Point<dim> p;
    p[0] = x;
    p[1] = y;
    if (dim == 3)
      p[dim - 1] = z;
    return p;
  }

  template <int dim>
  Tensor<1, dim>
  make_vector(const double x, const double y, const double z = 0.)
  {
    return make_point<dim>(x, y, z);
  }

  template <int dim>
  Case<dim, 2>
  edge_case(const std::string    &name,
            const Point<dim>     &p,
            const Point<dim>     &a,
            const Point<dim>     &b,
            const Tensor<1, dim> &dp,
            const Tensor<1, dim> &da = Tensor<1, dim>(),
            const Tensor<1, dim> &db = Tensor<1, dim>())
  {
    return {name, {{p, a, b}}, {{dp, da, db}}};
  }

  /** The edge a = (0, 0), b = (1, 0) (z = 0 in 3D) with moving points. */
  template <int dim>
  std::vector<Case<dim, 2>>
  hard_edge_cases()
  {
    using P      = Point<dim>;
    const auto p = [](double x, double y, double z = 0.) {
      return make_point<dim>(x, y, z);
    };
    const auto v = [](double x, double y, double z = 0.) {
      return make_vector<dim>(x, y, z);
    };
    const P                   a = p(0, 0), b = p(1, 0);
    std::vector<Case<dim, 2>> cases = {
      edge_case<dim>("head-on", p(0.5, 0.5), a, b, v(0, -1)),
      edge_case<dim>("receding", p(0.5, 0.5), a, b, v(0, 1)),
      edge_case<dim>("parallel from outside at 1e-3",
                     p(-0.5, 1e-3),
                     a,
                     b,
                     v(2, 0)),
      edge_case<dim>("parallel from outside at 1e-6",
                     p(-0.5, 1e-6),
                     a,
                     b,
                     v(2, 0)),
      edge_case<dim>("on the line into a", p(-0.5, 0), a, b, v(1, 0)),
      edge_case<dim>("on the line, short of a", p(-0.5, 0), a, b, v(0.25, 0)),
      // (b - a) x (p - a) = (t - 1/2)^2: touches at t = 1/2 only
      edge_case<dim>("grazing (double root)",
                     p(0.75, -0.125),
                     a,
                     p(1, -0.5),
                     v(-1, 0.25),
                     v(0, 0),
                     v(0, 1)),
      edge_case<dim>("start at 1e-3, approaching",
                     p(0.5, 1e-3),
                     a,
                     b,
                     v(0, -1)),
      edge_case<dim>("start at 1e-6, approaching",
                     p(0.5, 1e-6),
                     a,
                     b,
                     v(0, -1)),
      edge_case<dim>("start at 1e-6, receding", p(0.5, 1e-6), a, b, v(0, 1)),
      edge_case<dim>("start at 1e-3, sliding", p(0.25, 1e-3), a, b, v(0.5, 0)),
      edge_case<dim>("start at 1e-6, sliding", p(0.25, 1e-6), a, b, v(0.5, 0)),
      edge_case<dim>("start touching", p(0.5, 0), a, b, v(0, 1)),
      edge_case<dim>("start at 1e-14", p(0.5, 1e-14), a, b, v(0, 1)),
      edge_case<dim>("start at 1e-15", p(0.5, 1e-15), a, b, v(0, 1)),
      edge_case<dim>("hit vertex a", p(-0.5, 0.5), a, b, v(1, -1)),
      edge_case<dim>("pass vertex a at 2^-20",
                     p(-0.5 - std::ldexp(1., -20), 0.5),
                     a,
                     b,
                     v(1, -1)),
      edge_case<dim>("hit vertex b from beyond", p(1.5, 0.5), a, b, v(-1, -1)),
      edge_case<dim>("degenerate edge, hit", p(0.5, 0.5), a, a, v(-1, -1)),
      edge_case<dim>("degenerate edge, miss by 1e-3",
                     p(0.5, 0.5 + 1e-3),
                     a,
                     a,
                     v(-1, -1)),
      edge_case<dim>("degenerate moving edge, hit",
                     p(0.5, 0.5),
                     a,
                     a,
                     v(-0.5, -0.5),
                     v(0.5, 0.5),
                     v(0.5, 0.5)),
      edge_case<dim>("tiny motion 1e-12 at 1e-3",
                     p(0.5, 1e-3),
                     a,
                     b,
                     v(0, -1e-12)),
      edge_case<dim>("tiny motion 2^-40 at 2^-42",
                     p(0.5, std::ldexp(1., -42)),
                     a,
                     b,
                     v(0, -std::ldexp(1., -40))),
      edge_case<dim>("huge motion 1e6 through", p(0.5, 1), a, b, v(0, -1e6)),
      edge_case<dim>("huge motion 1e6 past", p(-0.5, 1), a, b, v(1e6, 0)),
      edge_case<dim>("huge common translation",
                     p(0.5, 0.5),
                     a,
                     b,
                     v(1e6, 1e6 - 1),
                     v(1e6, 1e6),
                     v(1e6, 1e6)),
      edge_case<dim>("huge common translation, no relative motion",
                     p(0.5, 1e-6),
                     a,
                     b,
                     v(1e6, -3e5),
                     v(1e6, -3e5),
                     v(1e6, -3e5)),
      edge_case<dim>("no motion", p(0.5, 1e-9), a, b, v(0, 0)),
      // the distance is below the rounding error of evaluating it (the
      // ulp of 5e7 is 7e-9), so only the error bound keeps the CCD safe
      edge_case<dim>("edge of length 1e8, approaching from 1e-9",
                     p(0.5, 1e-9),
                     p(-5e7, 0),
                     p(5e7, 0),
                     v(0, -1)),
      edge_case<dim>("edge of length 1e8, approaching from 1e-6",
                     p(0.5, 1e-6),
                     p(-5e7, 0),
                     p(5e7, 0),
                     v(0, -1)),
      edge_case<dim>("both moving",
                     p(0.5, 0.5),
                     a,
                     b,
                     v(0, -0.5),
                     v(0, 0.5),
                     v(0, 0.5)),
      edge_case<dim>("edge moving onto resting point",
                     p(0.5, 0.5),
                     a,
                     b,
                     v(0, 0),
                     v(0.25, 1),
                     v(-0.25, 1)),
      // a: (-1, -1) -> (-1, 1), b: (1, 1) -> (1, -1); the line y = (1 - 2t) x
      // sweeps over (0.5, 0.25) at t = 1/4
      edge_case<dim>("rotating edge sweeps the point",
                     p(0.5, 0.25),
                     p(-1, -1),
                     p(1, 1),
                     v(0, 0),
                     v(0, 2),
                     v(0, -2)),
      // the ends swap: the edge shrinks to its midpoint and flips
      edge_case<dim>("flipping edge, point above the midpoint",
                     p(0.5, 1e-3),
                     a,
                     b,
                     v(0, 0),
                     v(1, 0),
                     v(-1, 0)),
      edge_case<dim>("flipping edge, point on the line beyond b",
                     p(1.25, 0),
                     a,
                     b,
                     v(0, 0),
                     v(1, 0),
                     v(-1, 0)),
      edge_case<dim>("edge shrinking away from point on its line",
                     p(1.25, 0),
                     a,
                     b,
                     v(0, 0),
                     v(0, 0),
                     v(-0.5, 0)),
      edge_case<dim>("edge growing onto point on its line",
                     p(1.25, 0),
                     a,
                     b,
                     v(0, 0),
                     v(0, 0),
                     v(0.5, 0)),
    };
    if (dim == 3)
      {
        cases.push_back(edge_case<dim>("skew pass at 1e-3",
                                       p(0.5, -0.5, 1e-3),
                                       a,
                                       b,
                                       v(0, 1, 0)));
        cases.push_back(
          edge_case<dim>("skew hit", p(0.5, -0.5, 0.5), a, b, v(0, 1, -1)));
        cases.push_back(edge_case<dim>("rotating about the edge's axis",
                                       p(0.5, 0.5, 0.5),
                                       p(0, -1, 0),
                                       p(1, 1, 0),
                                       v(0, 0, 0),
                                       v(0, 2, 0),
                                       v(0, -2, 0)));
      }
    return cases;
  }

  Case<3, 3>
  triangle_case(const std::string  &name,
                const Point<3>     &p,
                const Point<3>     &a,
                const Point<3>     &b,
                const Point<3>     &c,
                const Tensor<1, 3> &dp,
                const Tensor<1, 3> &da = Tensor<1, 3>(),
                const Tensor<1, 3> &db = Tensor<1, 3>(),
                const Tensor<1, 3> &dc = Tensor<1, 3>())
  {
    return {name, {{p, a, b, c}}, {{dp, da, db, dc}}};
  }

  /** The triangle (0, 0, 0), (1, 0, 0), (0, 1, 0) with moving points. */
  std::vector<Case<3, 3>>
  hard_triangle_cases()
  {
    using P      = Point<3>;
    const auto V = [](const double x, const double y, const double z) {
      return make_vector<3>(x, y, z);
    };
    const P            a = P(0, 0, 0), b = P(1, 0, 0), c = P(0, 1, 0);
    const Tensor<1, 3> none;
    return {
      triangle_case("head-on", P(0.25, 0.25, 0.5), a, b, c, V(0, 0, -1)),
      triangle_case("receding", P(0.25, 0.25, 0.5), a, b, c, V(0, 0, 1)),
      triangle_case("parallel from outside at 1e-3",
                    P(-0.5, 0.25, 1e-3),
                    a,
                    b,
                    c,
                    V(2, 0, 0)),
      triangle_case("parallel from outside at 1e-6",
                    P(-0.5, 0.25, 1e-6),
                    a,
                    b,
                    c,
                    V(2, 0, 0)),
      triangle_case("in the plane into edge ca",
                    P(-0.5, 0.25, 0),
                    a,
                    b,
                    c,
                    V(1, 0, 0)),
      triangle_case("in the plane, short of edge ca",
                    P(-0.5, 0.25, 0),
                    a,
                    b,
                    c,
                    V(0.25, 0, 0)),
      // det = z - gamma y = (t - 1/2)^2 with c moving: touches at t = 1/2
      triangle_case("grazing (double root)",
                    P(0.125, 0.75, -0.125),
                    a,
                    b,
                    P(0, 1, -0.5),
                    V(0, -1, 0.25),
                    none,
                    none,
                    V(0, 0, 1)),
      triangle_case("start at 1e-3, approaching",
                    P(0.25, 0.25, 1e-3),
                    a,
                    b,
                    c,
                    V(0, 0, -1)),
      triangle_case("start at 1e-6, approaching",
                    P(0.25, 0.25, 1e-6),
                    a,
                    b,
                    c,
                    V(0, 0, -1)),
      triangle_case("start at 1e-6, receding",
                    P(0.25, 0.25, 1e-6),
                    a,
                    b,
                    c,
                    V(0, 0, 1)),
      triangle_case("start at 1e-3, sliding",
                    P(0.25, 0.25, 1e-3),
                    a,
                    b,
                    c,
                    V(0.25, 0.25, 0)),
      triangle_case("start at 1e-6, sliding",
                    P(0.25, 0.25, 1e-6),
                    a,
                    b,
                    c,
                    V(0.25, 0.25, 0)),
      triangle_case("start touching", P(0.25, 0.25, 0), a, b, c, V(0, 0, 1)),
      triangle_case("start at 1e-14",
                    P(0.25, 0.25, 1e-14),
                    a,
                    b,
                    c,
                    V(0, 0, 1)),
      triangle_case("start at 1e-15",
                    P(0.25, 0.25, 1e-15),
                    a,
                    b,
                    c,
                    V(0, 0, 1)),
      triangle_case("hit vertex a", P(-0.5, -0.5, 0.5), a, b, c, V(1, 1, -1)),
      triangle_case("pass vertex a at 2^-20",
                    P(-0.5, -0.5 - std::ldexp(1., -20), 0.5),
                    a,
                    b,
                    c,
                    V(1, 1, -1)),
      triangle_case("hit edge ab", P(0.5, -0.5, 0.5), a, b, c, V(0, 1, -1)),
      triangle_case("hit edge bc from outside",
                    P(1, 1, 0.5),
                    a,
                    b,
                    c,
                    V(-1, -1, -1)),
      triangle_case("pass edge ab at 2^-20",
                    P(0.5, -0.5 - std::ldexp(1., -20), 0.5),
                    a,
                    b,
                    c,
                    V(0, 1, -1)),
      triangle_case("collinear triangle, hit",
                    P(1.5, 0.5, 0.5),
                    a,
                    b,
                    P(2, 0, 0),
                    V(0, -1, -1)),
      triangle_case("collinear triangle, miss beyond the ends",
                    P(2.5, 0.5, 0.5),
                    a,
                    b,
                    P(2, 0, 0),
                    V(0, -1, -1)),
      triangle_case("coincident vertices a = b, hit edge",
                    P(0, 0.5, 0.5),
                    a,
                    a,
                    c,
                    V(0, 0, -1)),
      triangle_case("all vertices coincident, hit",
                    P(0.5, 0.5, 0.5),
                    a,
                    a,
                    a,
                    V(-1, -1, -1)),
      triangle_case("all vertices coincident, miss by 1e-3",
                    P(0.5, 0.5 + 1e-3, 0.5),
                    a,
                    a,
                    a,
                    V(-1, -1, -1)),
      triangle_case("tiny motion 1e-12 at 1e-3",
                    P(0.25, 0.25, 1e-3),
                    a,
                    b,
                    c,
                    V(0, 0, -1e-12)),
      triangle_case("tiny motion 2^-40 at 2^-42",
                    P(0.25, 0.25, std::ldexp(1., -42)),
                    a,
                    b,
                    c,
                    V(0, 0, -std::ldexp(1., -40))),
      triangle_case("huge motion 1e6 through",
                    P(0.25, 0.25, 1),
                    a,
                    b,
                    c,
                    V(0, 0, -1e6)),
      triangle_case("huge motion 1e6 past",
                    P(-0.5, 0.25, 1),
                    a,
                    b,
                    c,
                    V(1e6, 0, 0)),
      triangle_case("huge common translation",
                    P(0.25, 0.25, 0.5),
                    a,
                    b,
                    c,
                    V(1e6, -1e6, 1e6 - 1),
                    V(1e6, -1e6, 1e6),
                    V(1e6, -1e6, 1e6),
                    V(1e6, -1e6, 1e6)),
      triangle_case("triangle of size 1e8, approaching from 1e-9",
                    P(0.5, 0.25, 1e-9),
                    P(-5e7, -5e7, 0),
                    P(5e7, -5e7, 0),
                    P(0, 5e7, 0),
                    V(0, 0, -1)),
      triangle_case("triangle of size 1e8, approaching from 1e-6",
                    P(0.5, 0.25, 1e-6),
                    P(-5e7, -5e7, 0),
                    P(5e7, -5e7, 0),
                    P(0, 5e7, 0),
                    V(0, 0, -1)),
      triangle_case("sliver triangle (height 1e-9), approaching from 1e-6",
                    P(0.5, 0.25e-9, 1e-6),
                    a,
                    b,
                    P(0.75, 1e-9, 0),
                    V(0, 0, -1)),
      triangle_case("both moving",
                    P(0.25, 0.25, 0.5),
                    a,
                    b,
                    c,
                    V(0, 0, -0.5),
                    V(0, 0, 0.5),
                    V(0, 0, 0.5),
                    V(0, 0, 0.5)),
      // c: (0, 1, 0) -> (0, -1, 0): flips through a collinear triangle
      triangle_case("flipping triangle, point above",
                    P(0.25, 0, 1e-3),
                    a,
                    b,
                    c,
                    none,
                    none,
                    none,
                    V(0, -2, 0)),
      triangle_case("flipping triangle sweeps a point in its plane",
                    P(0.25, -0.5, 0),
                    a,
                    b,
                    c,
                    none,
                    none,
                    none,
                    V(0, -2, 0)),
      // c: (0, 1, 0) -> (0, 0, 1): rotation-like tilt about edge ab
      triangle_case("tilting triangle hits a point",
                    P(0.125, 0.25, 0.25),
                    a,
                    b,
                    c,
                    none,
                    none,
                    none,
                    V(0, -1, 1)),
      triangle_case("tilting triangle misses a point",
                    P(0.75, 0.5, 0.5),
                    a,
                    b,
                    c,
                    none,
                    none,
                    none,
                    V(0, -1, 1)),
    };
  }

  // ------------------------------------------------------------------------
  // Random cases.

  bfemp_tests::RandomNumbers random_numbers(20241121);

  double
  log_uniform(const double low, const double high)
  {
    return std::pow(10.,
                    random_numbers.uniform(std::log10(low), std::log10(high)));
  }

  template <int dim>
  Tensor<1, dim>
  random_direction()
  {
    while (true)
      {
        const Tensor<1, dim> v    = random_numbers.vector<dim>(1.);
        const double         norm = v.norm();
        if (norm > 0.1 && norm <= 1.)
          return v / norm;
      }
  }

  /**
   * A random primitive in [-1, 1]^dim (sometimes degenerate), a point near
   * a random point of it, and random displacements of varied magnitude: in
   * half of the cases the point heads towards the primitive, in some the
   * primitive rotates (vertex motions (R - I)(x - center)), sometimes all
   * of it is translated by a large common displacement. In about a third of
   * the cases the start of the point is then chosen so that it meets a
   * random point of the primitive (often a vertex or an edge) at a random
   * time, which is the only way to get contacts of a point with a segment
   * in 3D.
   */
  template <int dim, std::size_t n>
  Case<dim, n>
  random_case(const unsigned int index)
  {
    Case<dim, n> c;
    c.name = "random " + std::to_string(index);
    for (unsigned int j = 1; j <= n; ++j)
      c.x[j] = Point<dim>(random_numbers.vector<dim>(1.));
    const double kind = random_numbers.uniform(0., 1.);
    if (kind < 0.05) // two coincident vertices
      c.x[2] = c.x[1];
    else if (kind < 0.1) // collinear vertices (or a zero-length edge)
      c.x[n] = c.x[1] + random_numbers.uniform(-1., 2.) * (c.x[2] - c.x[1]);

    // a point of the primitive and an offset of random size
    Point<dim> on     = c.x[1];
    double     weight = 1.;
    for (unsigned int j = 2; j <= n; ++j)
      {
        const double w = random_numbers.uniform(0., weight);
        on += w * (c.x[j] - c.x[1]);
        weight -= w;
      }
    const Tensor<1, dim> offset =
      log_uniform(1e-6, 0.3) * random_direction<dim>();
    c.x[0] = on + offset;

    const double scale = log_uniform(1e-3, 3.);
    c.dx[0]            = scale * random_direction<dim>();
    if (random_numbers.uniform(0., 1.) < 0.5)
      c.dx[0] = -random_numbers.uniform(0.5, 3.) * offset + 0.1 * c.dx[0];
    const double primitive_kind = random_numbers.uniform(0., 1.);
    for (unsigned int j = 1; j <= n; ++j)
      c.dx[j] = primitive_kind < 0.3
                  ? Tensor<1, dim>()
                  : log_uniform(1e-3, 1.) * random_numbers.vector<dim>(1.);
    if (primitive_kind > 0.8)
      {
        // rotation-like: (R - I)(x - center), up to a half turn
        Point<dim> center;
        for (unsigned int j = 1; j <= n; ++j)
          center += (1. / n) * c.x[j];
        const auto R = bfemp_tests::rotation(random_numbers.uniform(-3.2, 3.2),
                                             random_direction<dim>());
        for (unsigned int j = 1; j <= n; ++j)
          c.dx[j] = R * (c.x[j] - center) - (c.x[j] - center);
      }
    if (random_numbers.uniform(0., 1.) < 0.1)
      {
        const Tensor<1, dim> common = 1e4 * random_numbers.vector<dim>(1.);
        for (unsigned int j = 0; j <= n; ++j)
          c.dx[j] += common;
      }
    if (random_numbers.uniform(0., 1.) < 0.35)
      {
        // An exact contact (up to the rounding of the start position) at
        // a random T with a random point of the primitive, often a vertex
        // or a point of an edge.
        const double          T    = random_numbers.uniform(0.01, 1.);
        const double          kind = random_numbers.uniform(0., 1.);
        std::array<double, n> weights;
        double                left = 1.;
        for (unsigned int j = 0; j + 1 < n; ++j)
          {
            weights[j] = random_numbers.uniform(0., left);
            left -= weights[j];
          }
        weights[n - 1] = left;
        if (kind < 0.2) // a vertex
          for (unsigned int j = 0; j < n; ++j)
            weights[j] = (j == 0);
        else if (kind < 0.5 && n == 3) // a point of the first edge
          {
            weights[0]     = 1. - weights[1];
            weights[n - 1] = 0.;
          }
        Point<dim> target;
        for (unsigned int j = 0; j < n; ++j)
          target += weights[j] * (c.x[j + 1] + T * c.dx[j + 1]);
        c.x[0] = target - T * c.dx[0];
      }
    return c;
  }

  template <int dim, std::size_t n>
  void
  run_hard(const std::string &group, const std::vector<Case<dim, n>> &cases)
  {
    Summary summary;
    summary.name = group;
    deallog.push(group);
    for (const Case<dim, n> &c : cases)
      {
        const Outcome o = run(c);
        print_case(c, o);
        summary.add(o);
      }
    deallog.pop();
    summary.print();
  }

  template <int dim, std::size_t n>
  void
  run_random(const std::string &group, const unsigned int n_cases)
  {
    Summary summary;
    summary.name = group;
    for (unsigned int i = 0; i < n_cases; ++i)
      {
        const Case<dim, n> c = random_case<dim, n>(i);
        const Outcome      o = run(c);
        if (o.false_negative || o.unsafe)
          print_case(c, o);
        summary.add(o);
      }
    summary.print();
  }

  template <typename Function>
  bool
  throws(const Function &f)
  {
    try
      {
        f();
      }
    catch (const ExceptionBase &)
      {
        return true;
      }
    return false;
  }

  /** t_max, the settings, the statistics and the argument checks. */
  void
  check_interface()
  {
    deallog.push("interface");
    using V                = Tensor<1, 2>;
    const Point<2> p       = make_point<2>(0.5, 0.5);
    const Point<2> a       = make_point<2>(0, 0);
    const Point<2> b       = make_point<2>(1, 0);
    const V        down    = make_vector<2>(0, -1);
    const V        zero    = V();
    const auto     contact = [&](const double       t_max,
                             const CcdSettings &settings,
                             CcdStatistics     *statistics) {
      return point_edge_time_of_impact<2>(p,
                                          a,
                                          b,
                                          down,
                                          zero,
                                          zero,
                                          t_max,
                                          settings,
                                          statistics);
    };

    bfemp_tests::check(contact(0.4, CcdSettings(), nullptr) == infinity,
                       "contact at 0.5 beyond t_max = 0.4: none");
    bfemp_tests::check(contact(0., CcdSettings(), nullptr) == infinity,
                       "t_max = 0: none");
    const double t_06 = contact(0.6, CcdSettings(), nullptr);
    const double t_2  = contact(2., CcdSettings(), nullptr);
    bfemp_tests::check(t_06 > 0.4 && t_06 <= 0.5 && t_2 == t_06,
                       "t_max = 0.6 and 2: the same t in (0.4, 0.5]");

    CcdSettings   tight;
    CcdStatistics statistics;
    tight.gap_fraction = 1e-3;
    const double t     = contact(1., tight, &statistics);
    deallog << "gap fraction 1e-3: t = " << format(t, 8) << " after "
            << statistics.iterations << " iterations" << std::endl;
    bfemp_tests::check(t > t_06 && t <= 0.5,
                       "a smaller gap fraction gives a larger t <= 0.5");

    // sliding at 1e-6 with a cap of 5 iterations: a small, safe t
    CcdSettings capped;
    capped.max_iterations = 5;
    statistics            = CcdStatistics();
    const double t_capped =
      point_edge_time_of_impact<2>(make_point<2>(0.25, 1e-6),
                                   a,
                                   b,
                                   make_vector<2>(0.5, 0),
                                   zero,
                                   zero,
                                   1.,
                                   capped,
                                   &statistics);
    deallog << "capped at 5 iterations: t = " << format(t_capped, 6)
            << ", statistics " << statistics.queries << " "
            << statistics.iterations << " " << statistics.capped << std::endl;
    bfemp_tests::check(t_capped > 0. && t_capped < 1e-4 &&
                         statistics.capped == 1 && statistics.iterations == 5,
                       "the cap stops the search and is counted");

    const double nan = std::numeric_limits<double>::quiet_NaN();
    bfemp_tests::check(throws([&]() {
                         point_edge_time_of_impact<2>(p,
                                                      a,
                                                      b,
                                                      make_vector<2>(nan, 0),
                                                      zero,
                                                      zero);
                       }),
                       "a NaN displacement throws");
    bfemp_tests::check(throws([&]() { contact(-1., CcdSettings(), nullptr); }),
                       "t_max < 0 throws");
    CcdSettings invalid;
    invalid.gap_fraction = 0.;
    bfemp_tests::check(throws([&]() { contact(1., invalid, nullptr); }),
                       "gap_fraction = 0 throws");
    deallog.pop();
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();

  run_hard<2, 2>("point-edge 2D", hard_edge_cases<2>());
  run_hard<3, 2>("point-edge 3D", hard_edge_cases<3>());
  run_hard<3, 3>("point-triangle", hard_triangle_cases());

  run_random<2, 2>("random point-edge 2D", 4000);
  run_random<3, 2>("random point-edge 3D", 2000);
  run_random<3, 3>("random point-triangle", 4000);

  check_interface();
}
