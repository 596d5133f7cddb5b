// The coarse-boundary map Psi of cMPM (seed 002 Section 5.1, eqs. 22-27):
// - the connectivity sizes r of the seed (2D 16 / 25 and 12 / 16, 3D 64 / 125
//   and 56 / 98 for the B-spline and boundary B-spline elements with
//   L = H / H/2), and with L = H/3 (the seed's Section 8.2.1) 36 / 20 in 2D,
//   216 / 152 in 3D: the (l + 3)^dim offsets around the element, of which
//   the boundary B-spline element keeps those on a face line or plane;
// - partition of unity of every row (eq. 33) and reproduction of an affine
//   coarse field at the boundary fine nodes;
// - Lemma 2 (eq. 27): a boundary fine node shared by neighbouring elements
//   gets the same weights on the same global coarse nodes from each, which
//   the element-local multilinear interpolation does not (its difference is
//   printed).

#include <bfemp/cmpm/coarse_boundary_map.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  /** Global coarse node -> weight of fine node k of an element. */
  template <int dim>
  std::map<std::size_t, double>
  global_row(const CoarseGrid<dim>        &grid,
             const CoarseBoundaryMap<dim> &psi,
             const std::array<int, dim>   &element,
             const unsigned int            k)
  {
    std::map<std::size_t, double> row;
    for (const auto &[I, w] : psi.row(k))
      row[grid.global_node(element, I)] += w;
    return row;
  }

  template <int dim>
  void
  test(const CmpmParameters &prm, const unsigned int expected_r)
  {
    const std::string name =
      std::to_string(dim) + "D " + CmpmParameters::to_string(prm.element_type) +
      ", L = " + CmpmParameters::node_span_to_string(prm.nodes_per_span);
    std::array<unsigned int, dim> n_elements;
    n_elements.fill(2);
    const double                 H = 0.4;
    const CoarseGrid<dim>        grid(Point<dim>(), H, n_elements, prm);
    const CoarseBoundaryMap<dim> psi(grid);

    deallog << name << ": r = " << grid.n_local_nodes()
            << ", boundary fine nodes = "
            << grid.n_fine() - grid.n_interior_fine()
            << ", interior = " << grid.n_interior_fine() << std::endl;
    bfemp_tests::check(
      grid.n_local_nodes() == expected_r,
      name + ": r = " + std::to_string(expected_r) +
        (prm.element_type == CmpmParameters::ElementType::multilinear
           ? " (the element's corners)"
         : prm.nodes_per_span == 3
           ? " (the offsets [-1, 4]^dim, on a face for boundary B-spline)"
           : " as in the seed (Lemma 1, Figs. 7-8, Sec. 7.1)"));

    // every local node is used by some row
    std::vector<bool> used(grid.n_local_nodes(), false);
    double            max_unity = 0., max_affine = 0.;
    Tensor<2, dim>    A;
    Tensor<1, dim>    b;
    for (unsigned int i = 0; i < dim; ++i)
      {
        b[i] = 0.3 - 0.1 * i;
        for (unsigned int j = 0; j < dim; ++j)
          A[i][j] = 0.5 * (i + 1) - 0.7 * j + 0.2 * i * j;
      }
    const std::array<int, dim> element{};
    bool                       interior_rows_empty = true;
    for (unsigned int k = 0; k < grid.n_fine(); ++k)
      {
        if (!grid.is_boundary_fine_node(k))
          {
            interior_rows_empty = interior_rows_empty && psi.row(k).empty();
            continue;
          }
        double         sum = 0.;
        Tensor<1, dim> u;
        for (const auto &[I, w] : psi.row(k))
          {
            used[I] = true;
            sum += w;
            const Point<dim> X =
              grid.node_lattice().node_position(grid.global_node(element, I));
            u += w * (A * X + b);
          }
        max_unity          = std::max(max_unity, std::abs(sum - 1.));
        const Point<dim> x = grid.fine_node_position(k);
        max_affine         = std::max(max_affine, (u - (A * x + b)).norm());
      }
    bfemp_tests::check(interior_rows_empty,
                       name + ": Psi has no rows for interior fine nodes");
    bfemp_tests::check(std::all_of(used.begin(),
                                   used.end(),
                                   [](bool u) { return u; }),
                       name + ": every coarse node of the connectivity is "
                              "used");
    bfemp_tests::check(max_unity < 1e-14,
                       name + ": sum_I psi_kI = 1 (eq. 33), to 1e-14");
    bfemp_tests::check(max_affine < 1e-13,
                       name + ": an affine coarse field is reproduced at the "
                              "boundary fine nodes, to 1e-13");

    // Lemma 2: the neighbour in every direction d
    double       max_shared = 0.;
    unsigned int n_shared   = 0;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::array<int, dim> neighbour{};
        neighbour[d]   = 1;
        const double s = grid.knot_span();
        for (unsigned int k = 0; k < grid.n_fine(); ++k)
          {
            const auto index = grid.fine_multi_index(k);
            if (index[d] + 2 < grid.n_fine_1d())
              continue; // not in the two rows shared with the neighbour
            // the same physical node in the neighbour: index - (n - 2)
            unsigned int k_neighbour = 0, stride = 1;
            for (unsigned int e = 0; e < dim; ++e)
              {
                const unsigned int i =
                  e == d ? index[e] - (grid.n_fine_1d() - 2) : index[e];
                k_neighbour += i * stride;
                stride *= grid.n_fine_1d();
              }
            const Point<dim> x_here  = grid.fine_node_position(k);
            Point<dim>       x_there = grid.fine_node_position(k_neighbour);
            x_there[d] += H;
            AssertThrow((x_here - x_there).norm() < 1e-12 * s,
                        ExcInternalError());
            auto here  = global_row<dim>(grid, psi, element, k);
            auto there = global_row<dim>(grid, psi, neighbour, k_neighbour);
            for (const auto &[node, w] : there)
              here[node] -= w;
            for (const auto &[node, w] : here)
              max_shared = std::max(max_shared, std::abs(w));
            ++n_shared;
          }
      }
    if (prm.element_type == CmpmParameters::ElementType::multilinear)
      {
        deallog << name << ": largest weight difference at shared fine nodes "
                << std::setprecision(3) << max_shared << std::setprecision(8)
                << std::endl;
        bfemp_tests::check(max_shared > 0.01,
                           name + ": the element-local interpolation differs "
                                  "between neighbours at shared fine nodes");
      }
    else
      bfemp_tests::check(max_shared < 1e-14,
                         name + ": " + std::to_string(n_shared) +
                           " shared boundary fine nodes get the same weights "
                           "from both elements (Lemma 2), to 1e-14");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  using Type      = CmpmParameters::ElementType;
  const auto make = [](const Type type, const unsigned int l) {
    CmpmParameters p;
    p.element_type   = type;
    p.nodes_per_span = l;
    p.n_fine         = 7;
    return p;
  };
  test<2>(make(Type::bspline, 1), 16);
  test<2>(make(Type::bspline, 2), 25);
  test<2>(make(Type::boundary_bspline, 1), 12);
  test<2>(make(Type::boundary_bspline, 2), 16);
  test<2>(make(Type::bspline, 3), 36);
  test<2>(make(Type::boundary_bspline, 3), 20);
  test<2>(make(Type::multilinear, 1), 4);
  test<3>(make(Type::bspline, 1), 64);
  test<3>(make(Type::bspline, 2), 125);
  test<3>(make(Type::boundary_bspline, 1), 56);
  test<3>(make(Type::boundary_bspline, 2), 98);
  test<3>(make(Type::bspline, 3), 216);
  test<3>(make(Type::boundary_bspline, 3), 152);
  test<3>(make(Type::multilinear, 1), 8);
}
