// SpatialHash<dim> (bfemp/contact/spatial_hash.h): query results equal a
// brute-force overlap test on random boxes in 2D and 3D -- ordinary boxes,
// boxes on a coarse lattice (so that many only touch, which counts as
// overlap), degenerate boxes (points, zero width in one direction), huge
// boxes (kept outside the cells), duplicates, and queries that are huge,
// degenerate or outside all boxes -- with the automatic cell size, a tiny
// one (most boxes become large) and a huge one (one cell). Also: the empty
// hash, an invalid box, and that the swept boxes contain the moving point,
// segment and triangle for t in [0, 1].

#include <bfemp/contact/spatial_hash.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(20241122);

  template <int dim>
  bool
  overlap(const BoundingBox<dim> &a, const BoundingBox<dim> &b)
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (a.upper_bound(d) < b.lower_bound(d) ||
          b.upper_bound(d) < a.lower_bound(d))
        return false;
    return true;
  }

  template <int dim>
  BoundingBox<dim>
  make_box(const Point<dim> &lower, const Point<dim> &upper)
  {
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }

  /** A box of the given kind inside about [-0.1, 1.1]^dim. */
  template <int dim>
  BoundingBox<dim>
  random_box(const double size)
  {
    Point<dim>   lower, upper;
    const double kind = random_numbers.uniform(0., 1.);
    for (unsigned int d = 0; d < dim; ++d)
      {
        double lo = random_numbers.uniform(-0.1, 1.1);
        double hi = lo + size * random_numbers.uniform(0., 1.);
        if (kind < 0.3) // on a lattice of spacing 1/64: touching boxes
          {
            lo = std::round(64. * lo) / 64.;
            hi = lo +
                 std::round(64. * size * random_numbers.uniform(0., 2.)) / 64.;
          }
        else if (kind < 0.4) // a point
          hi = lo;
        else if (kind < 0.5 && d == 0) // zero width in x
          hi = lo;
        lower[d] = lo;
        upper[d] = hi;
      }
    return make_box(lower, upper);
  }

  template <int dim>
  std::vector<BoundingBox<dim>>
  random_boxes(const unsigned int n)
  {
    std::vector<BoundingBox<dim>> boxes;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double kind = random_numbers.uniform(0., 1.);
        if (kind < 0.01) // huge: most of the domain
          boxes.push_back(random_box<dim>(random_numbers.uniform(0.5, 2.)));
        else if (kind < 0.03 && !boxes.empty()) // a duplicate
          boxes.push_back(boxes[static_cast<unsigned int>(
            random_numbers.uniform(0., 0.999) * boxes.size())]);
        else
          boxes.push_back(random_box<dim>(random_numbers.uniform(0., 0.05)));
      }
    return boxes;
  }

  template <int dim>
  std::vector<BoundingBox<dim>>
  random_queries(const unsigned int n)
  {
    std::vector<BoundingBox<dim>> queries;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double kind = random_numbers.uniform(0., 1.);
        if (kind < 0.02) // huge
          queries.push_back(random_box<dim>(random_numbers.uniform(0.5, 3.)));
        else if (kind < 0.05) // outside all boxes
          {
            Point<dim> lower;
            for (unsigned int d = 0; d < dim; ++d)
              lower[d] = random_numbers.uniform(-0.5, 1.5);
            lower[0]         = random_numbers.uniform(0., 1.) < 0.5 ? -0.5 : 5.;
            Point<dim> upper = lower;
            for (unsigned int d = 0; d < dim; ++d)
              upper[d] += 0.1;
            queries.push_back(make_box(lower, upper));
          }
        else
          queries.push_back(random_box<dim>(random_numbers.uniform(0., 0.08)));
      }
    return queries;
  }

  template <int dim>
  void
  compare_with_brute_force(const std::string                   &name,
                           const std::vector<BoundingBox<dim>> &boxes,
                           const std::vector<BoundingBox<dim>> &queries,
                           const double                         cell_size)
  {
    const SpatialHash<dim>    hash(boxes, cell_size);
    std::vector<unsigned int> candidates, expected;
    unsigned int              mismatches = 0;
    unsigned long             found      = 0;
    for (const BoundingBox<dim> &query : queries)
      {
        hash.query(query, candidates);
        expected.clear();
        for (unsigned int i = 0; i < boxes.size(); ++i)
          if (overlap(query, boxes[i]))
            expected.push_back(i);
        mismatches += (candidates != expected);
        found += candidates.size();
      }
    deallog << name << ": " << boxes.size() << " boxes, "
            << hash.n_large_boxes() << " large, " << hash.n_cell_entries()
            << " cell entries; " << queries.size() << " queries found " << found
            << " overlaps, " << mismatches << " mismatches" << std::endl;
    bfemp_tests::check(mismatches == 0,
                       name + ": the same boxes as brute force");
  }

  template <int dim>
  void
  check_dimension()
  {
    const std::string                   d       = std::to_string(dim) + "D";
    std::vector<BoundingBox<dim>>       boxes   = random_boxes<dim>(3000);
    const std::vector<BoundingBox<dim>> queries = random_queries<dim>(3000);

    compare_with_brute_force(d + " automatic cell size", boxes, queries, 0.);
    compare_with_brute_force(d + " cell size 1e-3", boxes, queries, 1e-3);
    compare_with_brute_force(d + " cell size 10", boxes, queries, 10.);

    // every box a point (the automatic cell size falls back to the spacing)
    std::vector<BoundingBox<dim>> points;
    for (unsigned int i = 0; i < 2000; ++i)
      {
        Point<dim> x;
        for (unsigned int k = 0; k < dim; ++k)
          x[k] = std::round(32. * random_numbers.uniform(0., 1.)) / 32.;
        points.push_back(make_box(x, x));
      }
    compare_with_brute_force(d + " points", points, queries, 0.);

    // all boxes the same point: the cell size falls back to 1
    const std::vector<BoundingBox<dim>> same(10,
                                             make_box(Point<dim>(),
                                                      Point<dim>()));
    compare_with_brute_force(d + " one point", same, queries, 0.);

    // a single huge box among small ones
    boxes.resize(200);
    Point<dim> far;
    for (unsigned int k = 0; k < dim; ++k)
      far[k] = 1e6;
    boxes.push_back(make_box(-far, far));
    compare_with_brute_force(d + " with one box of size 2e6",
                             boxes,
                             queries,
                             0.);

    std::vector<unsigned int> candidates = {1, 2, 3};
    SpatialHash<dim>().query(queries[0], candidates);
    bfemp_tests::check(candidates.empty(), d + " empty hash: no candidates");

    // (set directly: the constructor of BoundingBox asserts the order)
    BoundingBox<dim> invalid;
    invalid.get_boundary_points().first[0] =
      std::numeric_limits<double>::quiet_NaN();
    bool thrown = false;
    try
      {
        SpatialHash<dim>(std::vector<BoundingBox<dim>>{invalid});
      }
    catch (const ExceptionBase &)
      {
        thrown = true;
      }
    bfemp_tests::check(thrown, d + " a box with a NaN corner throws");
  }

  template <int dim>
  bool
  inside(const BoundingBox<dim> &box, const Point<dim> &x)
  {
    for (unsigned int d = 0; d < dim; ++d)
      if (x[d] < box.lower_bound(d) || x[d] > box.upper_bound(d))
        return false;
    return true;
  }

  /** x + t dx lies in the swept boxes for sampled t, also with large
   *  coordinates and motions. */
  template <int dim>
  void
  check_swept_boxes()
  {
    unsigned int failures = 0;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double scale = std::pow(10., random_numbers.uniform(-3., 6.));
        std::array<Point<dim>, 3>     x;
        std::array<Tensor<1, dim>, 3> dx;
        for (unsigned int j = 0; j < 3; ++j)
          {
            x[j]  = Point<dim>(scale * random_numbers.vector<dim>(1.));
            dx[j] = scale * random_numbers.vector<dim>(1.);
          }
        const double margin = i % 2 == 0 ? 0. : 1e-3 * scale;
        const auto   point  = swept_point_box<dim>(x[0], dx[0], margin);
        const auto   segment =
          swept_segment_box<dim>(x[0], x[1], dx[0], dx[1], margin);
        const auto triangle = swept_triangle_box<dim>(x[0],
                                                      x[1],
                                                      x[2],
                                                      dx[0],
                                                      dx[1],
                                                      dx[2],
                                                      margin);
        for (unsigned int k = 0; k <= 64; ++k)
          {
            const double     t = k / 64.;
            const Point<dim> p = x[0] + t * dx[0];
            const Point<dim> a = x[1] + t * dx[1];
            const Point<dim> b = x[2] + t * dx[2];
            failures += !inside(point, p);
            failures += !inside(segment, p + 0.3 * (a - p));
            failures += !inside(triangle, p + 0.2 * (a - p) + 0.5 * (b - p));
          }
        // the margin pads every side
        failures += !(point.lower_bound(0) <=
                      std::min(x[0][0], x[0][0] + dx[0][0]) - margin);
      }
    bfemp_tests::check(failures == 0,
                       std::to_string(dim) +
                         "D swept boxes contain the moving primitives");
  }
} // namespace



int
main()
{
  bfemp_tests::initlog();

  check_dimension<2>();
  check_dimension<3>();
  check_swept_boxes<2>();
  check_swept_boxes<3>();
}
