// cMPM's coarse-grid output (CoarseGridOutput, `output/write grid` with
// cMPM), 2D and 3D: a homogeneous block of particles at the regular
// sub-cell positions over 2^dim coarse elements (n = 5). The coarse nodes
// carry an affine displacement A X + b and a uniform velocity c.
//  - one patch per active element, subdivided into its n - 2 knot spans,
//    with the element's corners as vertices;
//  - at every patch point the velocity is c and the displacement A x + b
//    (partition of unity and affine reproduction of Phi, to round-off);
//  - write(): nothing before the first step; then coarse_grid_00001.vtu
//    with 2^dim (n - 2)^dim cells and (n - 1)^dim points per element,
//    listed in coarse_grid.pvd;
//  - a whole run of prm/cmpm/beam_2d.prm with `write grid = true` writes
//    the series (the refusal of `write grid` with cMPM is gone).

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/io/coarse_grid_output.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "cmpm/particle_block.h"
#include "format.h"
#include "run_scene.h"
#include "tests.h"

namespace
{
  using namespace dealii;
  using namespace bfemp;

  /** The number in attribute @p attribute of the first <Piece> in @p vtu. */
  unsigned int
  piece_attribute(const std::string &vtu, const std::string &attribute)
  {
    std::ifstream      in(vtu);
    std::ostringstream text;
    text << in.rdbuf();
    std::smatch       match;
    const std::string content = text.str();
    if (!std::regex_search(content,
                           match,
                           std::regex(attribute + "=\"([0-9]+)\"")))
      return 0;
    return std::stoul(match[1]);
  }

  unsigned int
  count_datasets(const std::string &pvd)
  {
    std::ifstream in(pvd);
    std::string   line;
    unsigned int  n = 0;
    while (std::getline(in, line))
      if (line.find("<DataSet") != std::string::npos)
        ++n;
    return n;
  }

  template <int dim>
  void
  test()
  {
    const std::string name = std::to_string(dim) + "D";

    BackgroundGrid<dim>     grid(bfemp_tests::unit_box_grid<dim>(0.25));
    ParticleSystem<dim>     particles(grid);
    CmpmDiscretization<dim> cmpm(grid, bfemp_tests::cmpm_with_fine_nodes(5));
    std::vector<std::unique_ptr<Material<dim>>> materials;
    materials.push_back(
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3)));

    // the block [0.25, 0.75]^dim, 2 particles per knot span (s = 0.25 / 3)
    Point<dim> lower;
    for (unsigned int d = 0; d < dim; ++d)
      lower[d] = 0.25;
    bfemp_tests::insert_particle_block<dim>(particles,
                                            lower,
                                            0.5 / 12,
                                            bfemp_tests::cube_counts<dim>(12),
                                            1000.,
                                            [](Point<dim> &,
                                               const ArrayView<double> &) {});
    particles.finish_insertion();
    cmpm.reinit(particles, materials);

    // a fresh folder: a rerun in the same build must not see the last run's
    const std::string folder = "output_" + name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    CoarseGridOutput<dim> output(folder, cmpm);
    GridState<dim>        state;
    output.write(state, 0., 0);
    bfemp_tests::check(!std::filesystem::exists(folder + "/coarse_grid.pvd"),
                       name + ": nothing written before the first step");

    const Lattice<dim> &nodes = cmpm.node_lattice();
    state.reinit(nodes.n_nodes);
    Tensor<2, dim> A;
    Tensor<1, dim> b, c;
    for (unsigned int i = 0; i < dim; ++i)
      {
        b[i] = 0.01 * (i + 1);
        c[i] = 0.5 - 0.3 * i;
        for (unsigned int j = 0; j < dim; ++j)
          A[i][j] = 0.02 * (1. + i) - 0.03 * j;
      }
    for (std::size_t i = 0; i < nodes.n_nodes; ++i)
      {
        state.displacement[i] = A * nodes.node_position(i) + b;
        state.new_velocity[i] = c;
      }

    const auto         patches = output.build_patches(state);
    const unsigned int spans   = cmpm.coarse_grid().n_fine_1d() - 2;
    const double       H       = cmpm.coarse_grid().element_size();
    double u_error = 0., v_error = 0., u_largest = 0., expected_largest = 0.;
    bool   geometry = patches.size() == (1u << dim);
    for (const auto &patch : patches)
      {
        geometry =
          geometry && patch.n_subdivisions == spans &&
          std::abs(patch.vertices[(1u << dim) - 1].distance(patch.vertices[0]) -
                   std::sqrt(dim) * H) < 1e-14;
        unsigned int n_points = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n_points *= spans + 1;
        for (unsigned int point = 0; point < n_points; ++point)
          {
            Point<dim>   x    = patch.vertices[0];
            unsigned int rest = point;
            for (unsigned int d = 0; d < dim; ++d, rest /= spans + 1)
              x[d] += H * (rest % (spans + 1)) / spans;
            const Tensor<1, dim> u = A * x + b;
            for (unsigned int d = 0; d < dim; ++d)
              {
                u_error =
                  std::max(u_error, std::abs(patch.data(d, point) - u[d]));
                u_largest =
                  std::max(u_largest, std::abs(double(patch.data(d, point))));
                expected_largest = std::max(expected_largest, std::abs(u[d]));
                v_error          = std::max(v_error,
                                   std::abs(patch.data(dim + d, point) - c[d]));
              }
          }
      }
    deallog << name << ": " << patches.size()
            << " patches, largest displacement component "
            << bfemp_tests::format("%.6f", u_largest) << " m (A x + b there: "
            << bfemp_tests::format("%.6f", expected_largest) << " m)"
            << std::endl;
    std::cout << name << ": displacement error " << u_error
              << " m, velocity error " << v_error << " m/s" << std::endl;
    bfemp_tests::check(geometry,
                       name + ": one patch per active element (2^dim), " +
                         std::to_string(spans) +
                         " knot spans per direction, element corners");
    // the data are stored as float: round-off 1e-7 relative
    bfemp_tests::check(u_error < 1e-8 && v_error < 1e-7,
                       name + ": displacement A x + b and velocity c at "
                              "every patch point (float round-off)");

    output.write(state, 0.1, 1);
    const std::string vtu      = folder + "/coarse_grid_00001.vtu";
    unsigned int      elements = 1, points = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        elements *= spans;
        points *= spans + 1;
      }
    const unsigned int cells = piece_attribute(vtu, "NumberOfCells");
    deallog << name << ": coarse_grid_00001.vtu has " << cells << " cells, "
            << piece_attribute(vtu, "NumberOfPoints") << " points" << std::endl;
    bfemp_tests::check(cells == (1u << dim) * elements &&
                         piece_attribute(vtu, "NumberOfPoints") ==
                           (1u << dim) * points &&
                         count_datasets(folder + "/coarse_grid.pvd") == 1,
                       name + ": the VTU holds 2^dim (n - 2)^dim cells and "
                              "(n - 1)^dim points per element; the pvd "
                              "lists it");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  test<2>();
  test<3>();

  {
    std::ofstream prm("beam.prm");
    prm << "include " << BFEMP_SOURCE_DIR << "/prm/cmpm/beam_2d.prm\n"
        << "subsection run\n  set name = beam\n  set quiet = true\n"
        << "  set end time = 0.05\nend\n"
        << "subsection output\n  set directory = results\n"
        << "  set interval = 0.025\n  set write grid = true\nend\n";
  }
  bfemp_tests::run_scene<2>("beam.prm");
  const unsigned int snapshots = count_datasets("results/beam/coarse_grid.pvd");
  const unsigned int first =
    piece_attribute("results/beam/coarse_grid_00001.vtu", "NumberOfCells");
  const unsigned int second =
    piece_attribute("results/beam/coarse_grid_00002.vtu", "NumberOfCells");
  deallog << "prm/cmpm/beam_2d.prm with write grid: " << snapshots
          << " coarse-grid snapshots, " << first << " and " << second
          << " cells" << std::endl;
  // the first step's elements are those the beam fills at rest, 24 x 4; the
  // sagging beam reaches into the row below in the second
  bfemp_tests::check(snapshots == 2 && first == 24 * 4 * 25 &&
                       second % 25 == 0 && second > first,
                     "the beam run writes the coarse grid after each of "
                     "its 2 steps: first 24 x 4 elements of 5 x 5 knot "
                     "spans, then more");
}
