// Linear completeness of the cMPM shape functions and of the condensation
// (seed 002 eqs. 30-31), for both element types and node spans H, H/2 (and
// the boundary B-spline element with L = H/3), 2D and 3D:
// - homogeneous elements with particles at the regular sub-cell positions of
//   the fine knot spans (2 and 3 per span and direction), undeformed and
//   under a homogeneous stretch F: the condensation maps the boundary values
//   of an affine field to the affine field's interior control values, and
//   u_p = sum_I Phi_I(x_p) Q_I reproduces the affine field and its gradient
//   at every particle, to round-off (the particle sums of grad B_k of the
//   interior fine functions vanish exactly on such lattices);
// - jittered particles (each moved by up to 0.3 sub-cells): the error is
//   printed and stays below the stated band. It is the particle quadrature's
//   error of int grad B_k = 0 in the local equilibrium, O(jitter / s) in
//   the worst particle's gradient (doc/cmpm.md);
// - a heterogeneous element (stiff ball): an affine coarse field is not
//   reproduced inside, the shape functions follow the material (printed).

#include <bfemp/cmpm/coarsened_shape_functions.h>
#include <bfemp/material/material.h>

#include <algorithm>
#include <cmath>

#include "cmpm/cmpm_test_scene.h"
#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  template <int dim>
  struct AffineField
  {
    Tensor<2, dim> A;
    Tensor<1, dim> b;

    Tensor<1, dim>
    operator()(const Point<dim> &x) const
    {
      return A * x + b;
    }
  };

  /** Largest |u_p - (A x_p + b)| / (|A| H) and |grad u_p - A| / |A| over the
   *  particles, and the largest interior control error. */
  template <int dim>
  std::array<double, 3>
  errors(const bfemp_tests::CmpmTestScene<dim> &scene,
         const AffineField<dim>                &field)
  {
    const CoarseGrid<dim> &grid  = scene.grid;
    const double           scale = field.A.norm();
    std::array<double, 3>  e{};
    for (const Point<dim> &x : scene.particle_positions)
      {
        const auto [u, grad_u] =
          scene.interpolate(grid.element_of(x), x, field);
        e[0] =
          std::max(e[0], (u - field(x)).norm() / (scale * grid.element_size()));
        e[1] = std::max(e[1], (grad_u - field.A).norm() / scale);
      }
    // eq. 31: the interior control values p_i Q of every element
    const unsigned int r = grid.n_local_nodes();
    for (std::size_t element = 0; element < grid.n_elements_total(); ++element)
      {
        const auto  index   = grid.element_multi_index(element);
        const auto &control = scene.shape_functions.interior_control(element);
        for (unsigned int i = 0; i < grid.n_interior_fine(); ++i)
          {
            Tensor<1, dim> q;
            for (unsigned int I = 0; I < r; ++I)
              q += control[i * r + I] * field(grid.node_lattice().node_position(
                                          grid.global_node(index, I)));
            const Point<dim> x =
              grid.element_origin(index) +
              grid.fine_node_position(grid.interior_fine_node(i));
            e[2] =
              std::max(e[2],
                       (q - field(x)).norm() / (scale * grid.element_size()));
          }
      }
    return e;
  }

  template <int dim>
  void
  test(const CmpmParameters &prm)
  {
    const std::string name =
      std::to_string(dim) + "D " + bfemp_tests::variant_name(prm);
    const unsigned int n_1d = dim == 2 ? 3 : 2;
    const auto         soft =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3));
    const auto stiff =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e8, 0.3));

    AffineField<dim> field;
    for (unsigned int i = 0; i < dim; ++i)
      {
        field.b[i] = 0.01 * (i + 1);
        for (unsigned int j = 0; j < dim; ++j)
          field.A[i][j] = 0.02 * (1. + i) - 0.03 * j + 0.01 * i * j;
      }
    Tensor<2, dim> stretch = unit_symmetric_tensor<dim>();
    stretch[0][0]          = 1.2;
    stretch[1][1]          = 0.9;
    stretch[0][1]          = 0.1;

    const auto homogeneous = [&](const Point<dim> &) { return soft.get(); };
    for (const unsigned int ppc : {2u, 3u})
      for (const bool deformed : {false, true})
        {
          bfemp_tests::CmpmTestScene<dim> scene(prm, n_1d);
          scene.build(homogeneous,
                      ppc,
                      0.,
                      deformed ? stretch
                               : Tensor<2, dim>(unit_symmetric_tensor<dim>()));
          const auto e = errors(scene, field);
          bfemp_tests::check(
            e[0] < 1e-12 && e[1] < 1e-11 && e[2] < 1e-12,
            name + ", " + std::to_string(ppc) + " particles per span, " +
              (deformed ? "stretched F" : "F = I") +
              ": interior control values, u_p and grad u_p of an affine "
              "field exact (relative 1e-12, 1e-12, 1e-11)");
        }

    {
      bfemp_tests::CmpmTestScene<dim> scene(prm, n_1d);
      scene.build(homogeneous, 2, 0.3);
      const auto e = errors(scene, field);
      deallog << name << ", jittered particles: relative error of u_p "
              << std::setprecision(2) << e[0] << ", of grad u_p " << e[1]
              << std::setprecision(8) << std::endl;
      bfemp_tests::check(e[0] < 0.05 && e[1] < 0.4 && e[1] > 1e-8,
                         name + ", jittered particles: affine field "
                                "reproduced to < 0.05 (u) and < 0.4 "
                                "(grad u), not exactly");
    }

    {
      bfemp_tests::CmpmTestScene<dim> scene(prm, n_1d);
      Point<dim>                      centre;
      for (unsigned int d = 0; d < dim; ++d)
        centre[d] = 0.5 * n_1d * 0.5;
      scene.build(
        [&](const Point<dim> &x) {
          return (x - centre).norm() < 0.3 ? stiff.get() : soft.get();
        },
        2);
      const auto e = errors(scene, field);
      deallog << name << ", stiff ball: relative error of grad u_p "
              << std::setprecision(2) << e[1] << std::setprecision(8)
              << std::endl;
      bfemp_tests::check(e[1] > 0.01,
                         name + ", stiff ball: the shape functions follow the "
                                "material, not the affine field");
    }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  for (const CmpmParameters &prm : bfemp_tests::cmpm_variants())
    test<2>(prm);
  for (const CmpmParameters &prm : bfemp_tests::cmpm_variants())
    test<3>(prm);
}
