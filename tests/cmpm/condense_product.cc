// CoarsenedShapeFunctions::condense against the product it stands for,
// K_alpha = p^T K p (seed 002's condensed stiffness), formed densely from p's
// columns (fine_values() of unit coarse vectors) and a random symmetric K:
// - for both element types and both node spans (and the boundary B-spline
//   element with L = H/3), in 2D and 3D, on an element
//   that holds a stiff ball (so that its interior rows of p are not those of
//   a homogeneous element);
// - K's blocks are given only between a random subset of the fine nodes (the
//   nodes that particles touch) and only for a random subset of the pairs
//   within two nodes of each other (those that a particle's stencil
//   couples); every other block of the caller's buffer is NaN, so a read of
//   an uncoupled block would show in the result;
// - the result must agree to round-off and be symmetric to the last bit.

#include <bfemp/cmpm/coarsened_shape_functions.h>
#include <bfemp/material/neo_hookean.h>

#include <cmath>
#include <limits>

#include "cmpm/cmpm_test_scene.h"
#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  template <int dim>
  void
  test(const CmpmParameters &parameters)
  {
    const std::string name =
      std::to_string(dim) + "D " + bfemp_tests::variant_name(parameters);
    bfemp_tests::CmpmTestScene<dim> scene(parameters, 2);
    const NeoHookean<dim> soft(ElasticModuli::from_young_poisson(1e5, 0.3));
    const NeoHookean<dim> stiff(ElasticModuli::from_young_poisson(1e8, 0.3));
    Point<dim>            center;
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = 0.3;
    scene.build(
      [&](const Point<dim> &x) -> const Material<dim> * {
        return x.distance(center) < 0.15 ? &stiff : &soft;
      },
      2);
    const CoarseGrid<dim>              &grid = scene.grid;
    const CoarsenedShapeFunctions<dim> &phi  = scene.shape_functions;
    const std::size_t                   element =
      grid.element_index(bfemp_tests::CmpmTestScene<dim>::uniform(0));
    bfemp_tests::check(phi.is_active(element), name + ": element active");

    // p's columns: p_kJ e_b = fine_values of the unit coarse vector (J, b)
    const unsigned int  r = grid.n_local_nodes(), n = grid.n_fine();
    const unsigned int  cols = dim * r, rows = dim * n;
    std::vector<double> P(rows * cols);
    {
      std::vector<Tensor<1, dim>> coarse(r), fine;
      for (unsigned int J = 0; J < r; ++J)
        for (unsigned int b = 0; b < dim; ++b)
          {
            coarse.assign(r, Tensor<1, dim>());
            coarse[J][b] = 1.;
            phi.fine_values(element, coarse, fine);
            for (unsigned int k = 0; k < n; ++k)
              for (unsigned int a = 0; a < dim; ++a)
                P[(dim * k + a) * cols + dim * J + b] = fine[k][a];
          }
    }

    // the fine nodes particles touch, and the coupled pairs between them
    bfemp_tests::RandomNumbers random(11 + dim);
    std::vector<unsigned int>  nodes;
    for (unsigned int k = 0; k < n; ++k)
      if (random.uniform(0., 1.) < 0.85)
        nodes.push_back(k);
    const std::size_t           m   = nodes.size();
    const double                nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<Tensor<2, dim>> upper(m * m);
    std::vector<char>           coupled(m * m, 0);
    std::vector<double>         K(rows * rows, 0.);
    unsigned int                n_near = 0, n_coupled = 0;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = i; j < m; ++j)
        {
          const auto a_index = grid.fine_multi_index(nodes[i]);
          const auto b_index = grid.fine_multi_index(nodes[j]);
          bool       near    = true;
          for (unsigned int d = 0; d < dim; ++d)
            near = near && std::abs(static_cast<int>(a_index[d]) -
                                    static_cast<int>(b_index[d])) <= 2;
          Tensor<2, dim> &block = upper[i * m + j];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              block[a][b] = nan;
          if (!near)
            continue;
          ++n_near;
          if (i != j && random.uniform(0., 1.) < 0.2)
            continue;
          ++n_coupled;
          coupled[i * m + j] = 1;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              block[a][b] = random.uniform(-1., 1.);
          if (i == j)
            block = symmetrize(block);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              {
                K[(dim * nodes[i] + a) * rows + dim * nodes[j] + b] =
                  block[a][b];
                K[(dim * nodes[j] + b) * rows + dim * nodes[i] + a] =
                  block[a][b];
              }
        }

    std::vector<Tensor<2, dim>> coarse;
    phi.condense(element, nodes, upper, coupled, coarse);

    // p^T K p, densely
    std::vector<double> KP(rows * cols, 0.);
    for (unsigned int i = 0; i < rows; ++i)
      for (unsigned int k = 0; k < rows; ++k)
        if (K[i * rows + k] != 0.)
          for (unsigned int c = 0; c < cols; ++c)
            KP[i * cols + c] += K[i * rows + k] * P[k * cols + c];
    double error = 0., scale = 0.;
    bool   symmetric = true;
    for (unsigned int I = 0; I < r; ++I)
      for (unsigned int J = 0; J < r; ++J)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            {
              double reference = 0.;
              for (unsigned int k = 0; k < rows; ++k)
                reference +=
                  P[k * cols + dim * I + a] * KP[k * cols + dim * J + b];
              scale              = std::max(scale, std::abs(reference));
              const double value = coarse[I * r + J][a][b];
              error              = std::isfinite(value)
                                     ? std::max(error, std::abs(value - reference))
                                     : std::numeric_limits<double>::infinity();
              symmetric = symmetric && value == coarse[J * r + I][b][a];
            }
    deallog << name << ": " << m << " of " << n << " fine nodes, " << n_coupled
            << " of " << n_near << " near pairs coupled" << std::endl;
    bfemp_tests::check(scale > 0.1 && error <= 1e-13 * scale,
                       name + ": condense = p^T K p to 1e-13 relative, no "
                              "uncoupled block read");
    bfemp_tests::check(symmetric, name + ": symmetric to the last bit");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  for (const CmpmParameters &p : bfemp_tests::cmpm_variants(7))
    test<2>(p);
  for (const CmpmParameters &p : bfemp_tests::cmpm_variants(7))
    test<3>(p);
}
