// Cost of the particle-mesh contact queries of the line search: continuous
// collision detection (CCD) queries per second for point-edge (2D) and
// point-triangle (3D) pairs in near-contact configurations, and the build
// and query time of the spatial hash (the broad phase) against the number
// of particles.
//
//   cmake --build build --target contact_queries
//   build/benchmarks/contact_queries            # full run, about a minute
//   build/benchmarks/contact_queries --quick    # smoke run, a few seconds
//
// Options:
//   --quick         fewer configurations, shorter timings, hash sizes up to
//                   1e4 particles
//   --output FILE   default benchmarks/results/contact_queries.json in the
//                   source tree (contact_queries_quick.json with --quick)
//   --seconds S     minimum wall time of one timed CCD block (1; 0.1 with
//                   --quick)
//   --repeats N     timed blocks / hash runs per measurement, the best is
//                   reported (3; 1 with --quick)
//
// CCD: a primitive of size about 1 (the segment from (0, 0) to (1, 0) in 2D,
// a random triangle with edges about 1 in 3D, both randomly rotated and
// translated), and a particle at a random point of it offset by a distance
// d0; displacements along a Newton direction are random. Regimes:
//   near_contact  d0 in [1e-4, 1e-2] (log-uniform), particle displacement
//                 of length in [1e-3, 1e-1], vertex displacements up to half
//                 that, all in random directions (the typical broad-phase
//                 survivor of a line search);
//   approaching   as near_contact, but the particle heads for the primitive
//                 with a displacement of 0.5 to 3 times d0 (about half of
//                 them reach it);
//   sliding       d0 = 1e-3, the particle slides parallel to the primitive
//                 by 1e-2 (ten times d0), the primitive at rest: the slow
//                 case of the additive CCD, about displacement / (0.9 d0)
//                 iterations.
// One block evaluates every configuration once, single-threaded, with the
// default CcdSettings; queries per second = configurations / best block.
//
// Spatial hash: N particles in a band of width 4 h around a boundary made
// of about N / 4 primitives of size h (2D: a polyline on the unit circle,
// 3D: the triangulated unit square z = 0); the particle boxes are the
// swept boxes of random displacements of up to h / 2, inflated by the
// contact distance 0.1 h, and the primitive boxes the swept boxes of
// displacements of up to h / 4. The hash is built over the primitive boxes
// (automatic cell size) and queried with every particle box, single-
// threaded, once in random order and once sorted by the grid cell of the
// particle (as particles stored by cell would be; the difference is the
// cost of cache misses); for N <= 1e4 the result is checked against brute
// force, whose time is reported too.

#include <bfemp/contact/collision_detection.h>
#include <bfemp/contact/spatial_hash.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "machine_info.h"

#ifndef BFEMP_SOURCE_DIR
#  define BFEMP_SOURCE_DIR "."
#endif

namespace
{
  using namespace dealii;
  using namespace bfemp;
  using namespace machine_info;
  using Clock = std::chrono::steady_clock;

  constexpr double pi = 3.14159265358979323846;

  struct Options
  {
    bool         quick   = false;
    double       seconds = 1.;
    unsigned int repeats = 3;
    std::string  output;
  };

  // ------------------------------------------------------------------------
  // Random numbers (seeded, so every run times the same configurations).

  class Random
  {
  public:
    explicit Random(const unsigned int seed)
      : engine(seed)
    {}

    double
    uniform(const double low, const double high)
    {
      return low + (high - low) * (engine() / 4294967295.);
    }

    double
    log_uniform(const double low, const double high)
    {
      return std::pow(10., uniform(std::log10(low), std::log10(high)));
    }

    template <int dim>
    Tensor<1, dim>
    direction()
    {
      while (true)
        {
          Tensor<1, dim> v;
          for (unsigned int d = 0; d < dim; ++d)
            v[d] = uniform(-1., 1.);
          const double norm = v.norm();
          if (norm > 0.1 && norm <= 1.)
            return v / norm;
        }
    }

  private:
    std::mt19937 engine;
  };

  // ------------------------------------------------------------------------
  // CCD.

  /** Index 0: the particle; 1 ..: the primitive's vertices. */
  template <int dim>
  struct Configuration
  {
    std::array<Point<dim>, dim + 1>     x;
    std::array<Tensor<1, dim>, dim + 1> dx;
  };

  template <int dim>
  Tensor<1, dim>
  orthogonal_part(const Tensor<1, dim> &v, const Tensor<1, dim> &normal)
  {
    return v - (v * normal) * normal;
  }

  template <int dim>
  std::vector<Configuration<dim>>
  make_configurations(const std::string &regime,
                      const unsigned int n,
                      Random            &random)
  {
    std::vector<Configuration<dim>> configurations(n);
    for (Configuration<dim> &c : configurations)
      {
        // the primitive: a random frame around a unit segment / a random
        // triangle with edges about 1
        Point<dim> shift;
        for (unsigned int d = 0; d < dim; ++d)
          shift[d] = random.uniform(-10., 10.);
        if (dim == 2)
          {
            const Tensor<1, dim> e = random.template direction<dim>();
            c.x[1]                 = shift;
            c.x[2]                 = shift + e;
          }
        else
          {
            c.x[1] = shift;
            c.x[2] = shift + random.template direction<dim>();
            c.x[3] = shift + random.template direction<dim>();
          }
        Tensor<1, dim> normal;
        if constexpr (dim == 2)
          normal = cross_product_2d(c.x[2] - c.x[1]);
        else
          normal = cross_product_3d(c.x[2] - c.x[1], c.x[3] - c.x[1]);
        normal /= normal.norm();

        // a point of the primitive and the particle near it
        Point<dim> on     = c.x[1];
        double     weight = 1.;
        for (unsigned int j = 2; j <= dim; ++j)
          {
            const double w = random.uniform(0., weight);
            on += w * (c.x[j] - c.x[1]);
            weight -= w;
          }
        const double side = random.uniform(0., 1.) < 0.5 ? -1. : 1.;
        const double d0 =
          regime == "sliding" ? 1e-3 : random.log_uniform(1e-4, 1e-2);
        c.x[0] = on + side * d0 * normal;

        const double length = random.log_uniform(1e-3, 1e-1);
        if (regime == "sliding")
          {
            const Tensor<1, dim> t =
              orthogonal_part(random.template direction<dim>(), normal);
            c.dx[0] = 1e-2 * t / t.norm();
            for (unsigned int j = 1; j <= dim; ++j)
              c.dx[j] = Tensor<1, dim>();
          }
        else
          {
            c.dx[0] = length * random.template direction<dim>();
            if (regime == "approaching")
              c.dx[0] = -random.uniform(0.5, 3.) * side * d0 * normal +
                        0.2 * d0 * random.template direction<dim>();
            for (unsigned int j = 1; j <= dim; ++j)
              c.dx[j] = random.uniform(0., 0.5) * length *
                        random.template direction<dim>();
          }
      }
    return configurations;
  }

  template <int dim>
  double
  time_of_impact(const Configuration<dim> &c, CcdStatistics *statistics)
  {
    if constexpr (dim == 2)
      return point_edge_time_of_impact<2>(c.x[0],
                                          c.x[1],
                                          c.x[2],
                                          c.dx[0],
                                          c.dx[1],
                                          c.dx[2],
                                          1.,
                                          CcdSettings(),
                                          statistics);
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
                                           statistics);
  }

  struct CcdResult
  {
    std::string   primitive, regime;
    unsigned int  configurations  = 0;
    unsigned long blocks          = 0;
    double        best_seconds    = 0.; // one pass over the configurations
    double        mean_iterations = 0., finite_fraction = 0.;
    unsigned long capped   = 0;
    double        min_time = 0.; // keeps the work observable

    double
    queries_per_second() const
    {
      return configurations / best_seconds;
    }
  };

  template <int dim>
  CcdResult
  run_ccd(const std::string &regime, const Options &options)
  {
    Random             random(dim == 2 ? 1234 : 5678);
    const unsigned int n      = options.quick ? 20000 : 200000;
    const auto configurations = make_configurations<dim>(regime, n, random);

    CcdResult result;
    result.primitive      = dim == 2 ? "point-edge 2D" : "point-triangle 3D";
    result.regime         = regime;
    result.configurations = n;

    // statistics from one untimed pass
    CcdStatistics statistics;
    unsigned int  finite = 0;
    double        sink   = std::numeric_limits<double>::infinity();
    for (const auto &c : configurations)
      {
        const double t = time_of_impact<dim>(c, &statistics);
        finite += std::isfinite(t);
        sink = std::min(sink, t);
      }
    result.mean_iterations =
      static_cast<double>(statistics.iterations) / statistics.queries;
    result.finite_fraction = static_cast<double>(finite) / n;
    result.capped          = statistics.capped;

    // timed blocks: passes over all configurations for at least
    // options.seconds, the best pass per block
    result.best_seconds = std::numeric_limits<double>::infinity();
    for (unsigned int r = 0; r < options.repeats; ++r)
      {
        const auto block_start = Clock::now();
        do
          {
            const auto start = Clock::now();
            for (const auto &c : configurations)
              sink = std::min(sink, time_of_impact<dim>(c, nullptr));
            result.best_seconds =
              std::min(result.best_seconds, seconds_since(start));
            ++result.blocks;
        } while (seconds_since(block_start) < options.seconds);
      }
    result.min_time = sink;
    std::cout << "  " << std::left << std::setw(18) << result.primitive
              << std::setw(14) << regime << std::right << std::setw(12)
              << std::setprecision(4) << result.queries_per_second()
              << " queries/s  " << std::setw(8) << 1e9 * result.best_seconds / n
              << " ns/query  " << std::setw(8) << result.mean_iterations
              << " iterations  " << std::setw(6)
              << 100. * result.finite_fraction << " % finite  " << result.capped
              << " capped" << std::endl;
    return result;
  }

  // ------------------------------------------------------------------------
  // Spatial hash.

  struct HashResult
  {
    unsigned int dim = 0, points = 0, primitives = 0;
    double       cell_size = 0., build_seconds = 0., query_seconds = 0.;
    double       sorted_query_seconds = 0.;
    double       brute_force_seconds = std::numeric_limits<double>::quiet_NaN();
    unsigned long candidates         = 0;
    std::size_t   cell_entries       = 0;
    unsigned int  large_boxes        = 0;
    bool          checked            = false;
  };

  template <int dim>
  HashResult
  run_hash(const unsigned int n_points, const Options &options)
  {
    Random random(42 + n_points);
    // primitives: about n_points / 4
    std::vector<BoundingBox<dim>> primitive_boxes;
    double                        h = 0.;
    if constexpr (dim == 2)
      {
        const unsigned int m = std::max(4u, n_points / 4);
        h                    = 2. * pi / m;
        for (unsigned int i = 0; i < m; ++i)
          {
            const Point<2> a(std::cos(h * i), std::sin(h * i));
            const Point<2> b(std::cos(h * (i + 1)), std::sin(h * (i + 1)));
            primitive_boxes.push_back(
              swept_segment_box<2>(a,
                                   b,
                                   0.25 * h * random.direction<2>(),
                                   0.25 * h * random.direction<2>(),
                                   0.));
          }
      }
    else
      {
        const unsigned int k =
          std::max(2u, static_cast<unsigned int>(std::sqrt(n_points / 8.)));
        h = 1. / k;
        for (unsigned int i = 0; i < k; ++i)
          for (unsigned int j = 0; j < k; ++j)
            {
              const Point<3> a(h * i, h * j, 0.), b(h * (i + 1), h * j, 0.),
                c(h * i, h * (j + 1), 0.), d(h * (i + 1), h * (j + 1), 0.);
              const auto motion = [&]() {
                return 0.25 * h * random.direction<3>();
              };
              primitive_boxes.push_back(swept_triangle_box<3>(a,
                                                              b,
                                                              c,
                                                              motion(),
                                                              motion(),
                                                              motion(),
                                                              0.));
              primitive_boxes.push_back(swept_triangle_box<3>(b,
                                                              d,
                                                              c,
                                                              motion(),
                                                              motion(),
                                                              motion(),
                                                              0.));
            }
      }

    // particles in a band of width 4 h around the boundary
    std::vector<BoundingBox<dim>> point_boxes;
    for (unsigned int q = 0; q < n_points; ++q)
      {
        Point<dim> x;
        if constexpr (dim == 2)
          {
            const double angle  = random.uniform(0., 2. * pi);
            const double radius = 1. + random.uniform(-2. * h, 2. * h);
            x = Point<2>(radius * std::cos(angle), radius * std::sin(angle));
          }
        else
          x = Point<3>(random.uniform(0., 1.),
                       random.uniform(0., 1.),
                       random.uniform(-2. * h, 2. * h));
        point_boxes.push_back(
          swept_point_box<dim>(x,
                               random.uniform(0., 0.5) * h *
                                 random.template direction<dim>(),
                               0.1 * h));
      }

    HashResult result;
    result.dim           = dim;
    result.points        = n_points;
    result.primitives    = primitive_boxes.size();
    result.build_seconds = result.query_seconds =
      std::numeric_limits<double>::infinity();
    std::vector<unsigned int> candidates;
    for (unsigned int r = 0; r < options.repeats; ++r)
      {
        auto             start = Clock::now();
        SpatialHash<dim> hash(primitive_boxes);
        result.build_seconds =
          std::min(result.build_seconds, seconds_since(start));
        start               = Clock::now();
        unsigned long found = 0;
        for (const auto &box : point_boxes)
          {
            hash.query(box, candidates);
            found += candidates.size();
          }
        result.query_seconds =
          std::min(result.query_seconds, seconds_since(start));
        result.candidates   = found;
        result.cell_size    = hash.get_cell_size();
        result.cell_entries = hash.n_cell_entries();
        result.large_boxes  = hash.n_large_boxes();
      }

    // The same queries in the order of the grid cells of their lower
    // corners (as particles sorted by cell would be): the difference to the
    // random order above is the cost of cache misses.
    {
      const double h       = result.cell_size;
      const auto   cell_of = [h](const BoundingBox<dim> &box) {
        std::array<double, dim> cell;
        for (unsigned int d = 0; d < dim; ++d)
          cell[dim - 1 - d] = std::floor(box.lower_bound(d) / h);
        return cell;
      };
      std::vector<BoundingBox<dim>> sorted = point_boxes;
      std::sort(sorted.begin(),
                sorted.end(),
                [&](const BoundingBox<dim> &a, const BoundingBox<dim> &b) {
                  return cell_of(a) < cell_of(b);
                });
      const SpatialHash<dim> hash(primitive_boxes);
      result.sorted_query_seconds = std::numeric_limits<double>::infinity();
      for (unsigned int r = 0; r < options.repeats; ++r)
        {
          const auto    start = Clock::now();
          unsigned long found = 0;
          for (const auto &box : sorted)
            {
              hash.query(box, candidates);
              found += candidates.size();
            }
          result.sorted_query_seconds =
            std::min(result.sorted_query_seconds, seconds_since(start));
          if (found != result.candidates)
            throw std::runtime_error("sorted queries found other boxes");
        }
    }

    if (n_points <= 10000)
      {
        const auto    start = Clock::now();
        unsigned long found = 0;
        for (const auto &box : point_boxes)
          for (const auto &primitive : primitive_boxes)
            {
              bool overlap = true;
              for (unsigned int d = 0; d < dim; ++d)
                overlap = overlap &&
                          box.lower_bound(d) <= primitive.upper_bound(d) &&
                          primitive.lower_bound(d) <= box.upper_bound(d);
              found += overlap;
            }
        result.brute_force_seconds = seconds_since(start);
        if (found != result.candidates)
          throw std::runtime_error("spatial hash and brute force disagree");
        result.checked = true;
      }

    std::cout << "  " << dim << "D " << std::setw(8) << n_points << " points "
              << std::setw(8) << result.primitives << " primitives: build "
              << std::setprecision(3) << std::setw(9)
              << 1e3 * result.build_seconds << " ms, query " << std::setw(9)
              << 1e3 * result.query_seconds << " ms (" << std::setw(6)
              << 1e9 * result.query_seconds / n_points << " ns/point; sorted "
              << std::setw(6) << 1e9 * result.sorted_query_seconds / n_points
              << " ns/point), " << std::setw(5)
              << static_cast<double>(result.candidates) / n_points
              << " candidates/point";
    if (result.checked)
      std::cout << ", brute force " << 1e3 * result.brute_force_seconds
                << " ms";
    std::cout << std::endl;
    return result;
  }

  // ------------------------------------------------------------------------

  void
  write_json(const std::string             &file,
             const Options                 &options,
             const GitState                &git,
             const std::vector<CcdResult>  &ccd,
             const std::vector<HashResult> &hash,
             const double                   total_seconds,
             const double                   load_before)
  {
    char              date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));

    const auto parent = std::filesystem::path(file).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);
    std::ofstream out(file);
    out << std::setprecision(6);
    const CcdSettings settings;
    out << "{\n"
        << "  \"benchmark\": \"contact_queries\",\n"
        << "  \"mode\": " << json_string(options.quick ? "quick" : "full")
        << ",\n"
        << "  \"machine\": {\"cpu\": " << json_string(cpu_model())
        << ", \"nproc\": " << std::thread::hardware_concurrency()
        << ", \"memory_gib\": " << json_number(memory_gib()) << "},\n"
        << "  \"threads\": 1,\n"
        << "  \"date\": " << json_string(date) << ",\n"
        << "  \"git_commit\": " << json_string(git.commit) << ",\n"
        << "  \"library_files_modified_since_commit\": "
        << json_string(git.modified) << ",\n"
        << "  \"build\": " << json_string(build_type()) << ",\n"
        << "  \"total_seconds\": " << json_number(total_seconds) << ",\n"
        << "  \"load_average_before\": " << json_number(load_before)
        << ", \"load_average_after\": " << json_number(load_average()) << ",\n"
        << "  \"ccd_settings\": {\"gap_fraction\": " << settings.gap_fraction
        << ", \"step_fraction\": " << settings.step_fraction
        << ", \"max_iterations\": " << settings.max_iterations << "},\n"
        << "  \"notes\": \"ccd: additive CCD (Li et al. 2021) of a particle "
           "against a primitive of size 1, single-threaded; "
           "queries_per_second = configurations / best_seconds, the best "
           "of all passes over the configurations (blocks); "
           "mean_iterations = distance evaluations after the first per "
           "query; finite_fraction = share of queries that report a time "
           "of impact in [0, 1]. Regimes: near_contact (distance 1e-4..1e-2, "
           "random displacements 1e-3..1e-1), approaching (heading for the "
           "primitive with 0.5..3 times the distance), sliding (distance "
           "1e-3, parallel displacement 1e-2). spatial_hash: hash over the "
           "swept boxes of about points/4 boundary primitives of size h "
           "(automatic cell size), queried with the swept boxes (margin "
           "0.1 h) of all particles in a band of width 4 h; best of the "
           "repeats; sorted_query_seconds = the same queries sorted by the "
           "grid cell of their lower corner (as for particles stored by "
           "cell); brute_force_seconds = all pairs tested, for the "
           "smaller sizes only (its candidate count is checked equal).\",\n"
        << "  \"ccd\": [\n";
    for (unsigned int i = 0; i < ccd.size(); ++i)
      {
        const CcdResult &r = ccd[i];
        out << "    {\"primitive\": " << json_string(r.primitive)
            << ", \"regime\": " << json_string(r.regime)
            << ", \"configurations\": " << r.configurations
            << ", \"blocks\": " << r.blocks
            << ", \"best_seconds\": " << json_number(r.best_seconds)
            << ", \"queries_per_second\": "
            << json_number(r.queries_per_second()) << ", \"ns_per_query\": "
            << json_number(1e9 * r.best_seconds / r.configurations)
            << ", \"mean_iterations\": " << json_number(r.mean_iterations)
            << ", \"finite_fraction\": " << json_number(r.finite_fraction)
            << ", \"capped\": " << r.capped << "}"
            << (i + 1 < ccd.size() ? "," : "") << "\n";
      }
    out << "  ],\n  \"spatial_hash\": [\n";
    for (unsigned int i = 0; i < hash.size(); ++i)
      {
        const HashResult &r = hash[i];
        out << "    {\"dim\": " << r.dim << ", \"points\": " << r.points
            << ", \"primitives\": " << r.primitives
            << ", \"cell_size\": " << json_number(r.cell_size)
            << ", \"cell_entries\": " << r.cell_entries
            << ", \"large_boxes\": " << r.large_boxes
            << ", \"build_seconds\": " << json_number(r.build_seconds)
            << ", \"query_seconds\": " << json_number(r.query_seconds)
            << ", \"ns_per_point\": "
            << json_number(1e9 * r.query_seconds / r.points)
            << ", \"sorted_query_seconds\": "
            << json_number(r.sorted_query_seconds)
            << ", \"sorted_ns_per_point\": "
            << json_number(1e9 * r.sorted_query_seconds / r.points)
            << ", \"candidates\": " << r.candidates
            << ", \"candidates_per_point\": "
            << json_number(static_cast<double>(r.candidates) / r.points)
            << ", \"brute_force_seconds\": "
            << json_number(r.brute_force_seconds) << "}"
            << (i + 1 < hash.size() ? "," : "") << "\n";
      }
    out << "  ]\n}\n";
    if (!out)
      throw std::runtime_error("could not write " + file);
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      Options options;
      bool    seconds_given = false, repeats_given = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--quick")
            options.quick = true;
          else if (arg == "--output" && i + 1 < argc)
            options.output = argv[++i];
          else if (arg == "--seconds" && i + 1 < argc)
            options.seconds = std::atof(argv[++i]), seconds_given = true;
          else if (arg == "--repeats" && i + 1 < argc)
            options.repeats = std::max(1, std::atoi(argv[++i])),
            repeats_given   = true;
          else
            {
              std::cerr << "usage: " << argv[0]
                        << " [--quick] [--output FILE] [--seconds S] "
                           "[--repeats N]\n";
              return 1;
            }
        }
      if (options.quick && !seconds_given)
        options.seconds = 0.1;
      if (options.quick && !repeats_given)
        options.repeats = 1;
      if (options.output.empty())
        options.output = std::string(BFEMP_SOURCE_DIR) +
                         "/benchmarks/results/contact_queries" +
                         (options.quick ? "_quick" : "") + ".json";

      std::cout << "bfemp contact_queries (" << cpu_model() << ", "
                << std::thread::hardware_concurrency() << " cores, "
                << build_type() << " build, single-threaded)" << std::endl;
      if (build_type() != "release")
        std::cout << "WARNING: not a Release build; configure with "
                     "-DCMAKE_BUILD_TYPE=Release for meaningful numbers"
                  << std::endl;

      const GitState git         = read_git_state();
      const double   load_before = load_average();
      const auto     start       = Clock::now();

      std::cout << "CCD:" << std::endl;
      std::vector<CcdResult> ccd;
      for (const std::string regime :
           {"near_contact", "approaching", "sliding"})
        {
          ccd.push_back(run_ccd<2>(regime, options));
          ccd.push_back(run_ccd<3>(regime, options));
        }

      std::cout << "spatial hash:" << std::endl;
      std::vector<HashResult>   hash;
      std::vector<unsigned int> sizes = {1000, 10000};
      if (!options.quick)
        sizes.insert(sizes.end(), {100000, 1000000});
      for (const unsigned int n : sizes)
        hash.push_back(run_hash<2>(n, options));
      for (const unsigned int n : sizes)
        hash.push_back(run_hash<3>(n, options));

      const double total = seconds_since(start);
      write_json(options.output, options, git, ccd, hash, total, load_before);
      std::cout << "\nwrote " << options.output << " (total " << total << " s)"
                << std::endl;
    }
  catch (const std::exception &error)
    {
      std::cerr << "contact_queries: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
