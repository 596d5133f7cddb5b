// Cost of the cMPM shape functions (seed 002 Sections 5 and 7.2): the
// coarse-boundary map Psi (built once), the boundary-interior map of one
// coarse element (rebuilt every step from its particles: assembly of K_i and
// K_ib Psi_b, Cholesky solve) and the evaluation of Phi_I and grad Phi_I at a
// particle, for both element types and node spans, n = 5, 7, 9, 2D and 3D,
// on a heterogeneous element (a 1000 times stiffer ball) with 2 particles per
// knot span and direction. With --phi-csv it also samples the four
// components of Phi_I of the element's upper right corner node on a
// heterogeneous 2D element (seed 002 Fig. 13) for
// doc/images/plot_cmpm_shape_function.py.
//
//   cmake --build build --target cmpm_shape_functions
//   build/benchmarks/cmpm_shape_functions            # full run, < 1 min
//   build/benchmarks/cmpm_shape_functions --quick    # smoke run
//   build/benchmarks/cmpm_shape_functions --phi-csv doc/images/cmpm_phi.csv
//
// Options:
//   --quick         n = 7 only, one repeat
//   --output FILE   default benchmarks/results/cmpm_shape_functions.json in
//                   the source tree (..._quick.json with --quick)
//   --phi-csv FILE  write the Fig. 13 samples instead of timing

#include <bfemp/cmpm/coarsened_shape_functions.h>
#include <bfemp/material/material.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

#include "machine_info.h"

using namespace dealii;
using namespace bfemp;
using namespace machine_info;

namespace
{
  using Clock = std::chrono::steady_clock;

  struct Result
  {
    int          dim;
    std::string  type;
    unsigned int nodes_per_span, n, r, interior, particles;
    double       psi_seconds, element_seconds, evaluate_seconds;
  };

  /** One element with a stiff ball of a third of its size at its centre. */
  template <int dim>
  std::vector<LocalQuadraturePoint<dim>>
  heterogeneous_particles(const CoarseGrid<dim> &grid, const unsigned int ppc)
  {
    const auto soft =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3));
    const auto stiff =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e8, 0.3));
    const double       H      = grid.element_size();
    const unsigned int per_1d = (grid.n_fine_1d() - 2) * ppc;
    const double       h      = H / per_1d;
    unsigned int       total  = 1;
    for (unsigned int d = 0; d < dim; ++d)
      total *= per_1d;
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5 * H;
    std::vector<LocalQuadraturePoint<dim>> points(total);
    for (unsigned int flat = 0; flat < total; ++flat)
      {
        unsigned int rest = flat;
        for (unsigned int d = 0; d < dim; ++d)
          {
            points[flat].position[d] = (rest % per_1d + 0.5) * h;
            rest /= per_1d;
          }
        const Tensor<2, dim> F            = unit_symmetric_tensor<dim>();
        points[flat].weight               = std::pow(h, dim);
        points[flat].deformation_gradient = F;
        points[flat].tangent =
          ((points[flat].position - centre).norm() < H / 3. ? stiff : soft)
            ->tangent(F, true);
      }
    return points;
  }

  template <int dim>
  Result
  run(const CmpmParameters &prm, const unsigned int repeats)
  {
    std::array<unsigned int, dim> one;
    one.fill(1);
    const CoarseGrid<dim> grid(Point<dim>(), 1., one, prm);

    double psi_seconds = 1e300;
    for (unsigned int k = 0; k < repeats; ++k)
      {
        const auto                   start = Clock::now();
        const CoarseBoundaryMap<dim> psi(grid);
        psi_seconds = std::min(psi_seconds, seconds_since(start));
      }

    const auto                   points = heterogeneous_particles(grid, 2);
    CoarsenedShapeFunctions<dim> phi(grid);
    double element_seconds = 1e300, evaluate_seconds = 1e300;
    for (unsigned int k = 0; k < repeats; ++k)
      {
        const auto start = Clock::now();
        phi.reinit({0}, {points});
        element_seconds = std::min(element_seconds, seconds_since(start));
      }
    std::vector<CoarseShapeValue<dim>> values;
    const std::array<int, dim>         element{};
    for (unsigned int k = 0; k < repeats; ++k)
      {
        const auto start = Clock::now();
        for (const auto &point : points)
          phi.evaluate(element, point.position, values);
        evaluate_seconds =
          std::min(evaluate_seconds, seconds_since(start) / points.size());
      }
    const Result result{dim,
                        CmpmParameters::to_string(prm.element_type),
                        prm.nodes_per_span,
                        prm.n_fine,
                        grid.n_local_nodes(),
                        grid.n_interior_fine(),
                        static_cast<unsigned int>(points.size()),
                        psi_seconds,
                        element_seconds,
                        evaluate_seconds};
    std::cout << "  " << dim << "D " << result.type << ", L = H/"
              << prm.nodes_per_span << ", n = " << prm.n_fine
              << ": r = " << result.r << ", interior fine " << result.interior
              << ", Psi " << psi_seconds * 1e3 << " ms, element "
              << element_seconds * 1e3 << " ms (" << points.size()
              << " particles), Phi at a particle " << evaluate_seconds * 1e6
              << " us" << std::endl;
    return result;
  }

  /** Fig. 13: the four components of Phi_I at the upper right corner node
   *  of a 2D element with a circular hard filling. */
  void
  write_phi_samples(const std::string &file)
  {
    CmpmParameters prm;
    prm.element_type   = CmpmParameters::ElementType::boundary_bspline;
    prm.nodes_per_span = 1;
    prm.n_fine         = 7;
    const CoarseGrid<2>        grid(Point<2>(), 1., {{1, 1}}, prm);
    CoarsenedShapeFunctions<2> phi(grid);
    phi.reinit({0}, {heterogeneous_particles(grid, 4)});

    unsigned int corner = 0;
    for (unsigned int I = 0; I < grid.n_local_nodes(); ++I)
      if (grid.local_node_offset(I) == std::array<int, 2>{{1, 1}})
        corner = I;

    std::ofstream out(file + ".part");
    out << "x,y,phi_xx,phi_xy,phi_yx,phi_yy\n" << std::setprecision(8);
    std::vector<CoarseShapeValue<2>> values;
    const unsigned int               samples = 81;
    for (unsigned int j = 0; j < samples; ++j)
      for (unsigned int i = 0; i < samples; ++i)
        {
          const Point<2> x(i / (samples - 1.), j / (samples - 1.));
          phi.evaluate({{0, 0}}, x, values);
          const Tensor<2, 2> &v = values[corner].value;
          out << x[0] << ',' << x[1] << ',' << v[0][0] << ',' << v[0][1] << ','
              << v[1][0] << ',' << v[1][1] << '\n';
        }
    out.close();
    std::filesystem::rename(file + ".part", file);
    std::cout << "wrote " << file << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      bool        quick = false;
      std::string output, phi_csv;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--quick")
            quick = true;
          else if (arg == "--output" && i + 1 < argc)
            output = argv[++i];
          else if (arg == "--phi-csv" && i + 1 < argc)
            phi_csv = argv[++i];
          else
            {
              std::cerr << "usage: " << argv[0]
                        << " [--quick] [--output FILE] [--phi-csv FILE]\n";
              return 1;
            }
        }
      if (!phi_csv.empty())
        {
          write_phi_samples(phi_csv);
          return 0;
        }
      if (output.empty())
        output = std::string(BFEMP_SOURCE_DIR) +
                 "/benchmarks/results/cmpm_shape_functions" +
                 (quick ? "_quick" : "") + ".json";
      std::cout << "bfemp cmpm_shape_functions (" << cpu_model() << ", "
                << build_type() << " build, one element, one thread)"
                << std::endl;
      const GitState                  git     = read_git_state();
      const unsigned                  repeats = quick ? 1 : 3;
      std::vector<Result>             results;
      const std::vector<unsigned int> ns =
        quick ? std::vector<unsigned int>{7}
              : std::vector<unsigned int>{5, 7, 9};
      for (const int dim : {2, 3})
        for (const auto type : {CmpmParameters::ElementType::bspline,
                                CmpmParameters::ElementType::boundary_bspline})
          for (const unsigned int l : {1u, 2u})
            for (const unsigned int n : ns)
              {
                CmpmParameters prm;
                prm.element_type   = type;
                prm.nodes_per_span = l;
                prm.n_fine         = n;
                results.push_back(dim == 2 ? run<2>(prm, repeats)
                                           : run<3>(prm, repeats));
              }

      char              date[64];
      const std::time_t now = std::time(nullptr);
      std::strftime(date,
                    sizeof(date),
                    "%Y-%m-%dT%H:%M:%SZ",
                    std::gmtime(&now));
      const auto parent = std::filesystem::path(output).parent_path();
      if (!parent.empty())
        std::filesystem::create_directories(parent);
      std::ofstream out(output + ".part");
      out << std::setprecision(6) << "{\n"
          << "  \"benchmark\": \"cmpm_shape_functions\",\n"
          << "  \"mode\": " << json_string(quick ? "quick" : "full") << ",\n"
          << "  \"machine\": {\"cpu\": " << json_string(cpu_model())
          << ", \"nproc\": " << std::thread::hardware_concurrency()
          << ", \"memory_gib\": " << json_number(memory_gib()) << "},\n"
          << "  \"threads\": 1,\n"
          << "  \"date\": " << json_string(date) << ",\n"
          << "  \"git_commit\": " << json_string(git.commit) << ",\n"
          << "  \"library_files_modified_since_commit\": "
          << json_string(git.modified) << ",\n"
          << "  \"build\": " << json_string(build_type()) << ",\n"
          << "  \"notes\": \"one coarse element of span 1 with a stiff ball "
             "(E 1e8 vs 1e5) of radius 1/3, 2 particles per knot span and "
             "direction; psi_seconds: building Psi (once per run); "
             "element_seconds: the boundary-interior map of the element "
             "(every step); evaluate_seconds: Phi_I and grad Phi_I of all r "
             "nodes at one particle; best of the repeats\",\n"
          << "  \"results\": [\n";
      for (unsigned int i = 0; i < results.size(); ++i)
        {
          const Result &r = results[i];
          out << "    {\"dim\": " << r.dim
              << ", \"type\": " << json_string(r.type)
              << ", \"nodes_per_span\": " << r.nodes_per_span
              << ", \"n\": " << r.n << ", \"r\": " << r.r
              << ", \"interior_fine_nodes\": " << r.interior
              << ", \"particles\": " << r.particles
              << ", \"psi_seconds\": " << json_number(r.psi_seconds)
              << ", \"element_seconds\": " << json_number(r.element_seconds)
              << ", \"evaluate_seconds\": " << json_number(r.evaluate_seconds)
              << "}" << (i + 1 < results.size() ? "," : "") << "\n";
        }
      out << "  ]\n}\n";
      out.close();
      std::filesystem::rename(output + ".part", output);
      std::cout << "wrote " << output << std::endl;
    }
  catch (const std::exception &error)
    {
      std::cerr << "cmpm_shape_functions: " << error.what() << std::endl;
      return 1;
    }
}
