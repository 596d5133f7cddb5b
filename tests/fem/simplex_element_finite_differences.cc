// Checks SimplexElement (a linear triangle / tetrahedron, BFEMP eq. 24) in 2D
// and 3D for every material: the gradient against central finite differences
// of the energy and the Hessian against central finite differences of the
// gradient, on random well-shaped rest elements and random deformed
// positions. Also checks that F is the identity at rest, that the gradient
// sums to zero over the nodes, that a rigid motion has zero energy and zero
// gradient for the rotation-invariant models, and that a degenerate or
// inverted rest element is rejected.

#include <bfemp/fem/simplex_element.h>
#include <bfemp/material/material.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
#include <random>
#include <string>

#include "tests.h"

using namespace dealii;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(20240612);

  template <int dim>
  using Nodes = typename bfemp::SimplexElement<dim>::NodePositions;

  using bfemp_tests::rotation;

  template <int dim>
  Tensor<2, dim>
  random_rotation()
  {
    const Tensor<1, dim> n = random_numbers.vector<dim>(1.);
    return rotation(random_numbers.uniform(0., 2. * M_PI), n / n.norm());
  }

  template <int dim>
  Tensor<2, dim>
  edge_basis(const Nodes<dim> &p)
  {
    Tensor<2, dim> B;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int r = 0; r < dim; ++r)
        B[r][c] = p[c + 1][r] - p[0][r];
    return B;
  }

  // A perturbed corner simplex of edge length @p size, rotated and moved;
  // "well-shaped" means det B_e > 0.3 size^dim.
  template <int dim>
  Nodes<dim>
  random_rest_element(const double size)
  {
    while (true)
      {
        const Tensor<2, dim> Q  = random_rotation<dim>();
        const Point<dim> origin = Point<dim>(random_numbers.vector<dim>(2.));
        Nodes<dim>       X;
        for (unsigned int a = 0; a < dim + 1; ++a)
          {
            Tensor<1, dim> corner = random_numbers.vector<dim>(0.2 * size);
            if (a > 0)
              corner[a - 1] += size;
            X[a] = origin + Q * corner;
          }
        if (determinant(edge_basis<dim>(X)) > 0.3 * std::pow(size, dim))
          return X;
      }
  }

  // x_a = A X_a + t + noise with det F > 0.2.
  template <int dim>
  Nodes<dim>
  random_deformed_positions(const Nodes<dim>                 &X,
                            const bfemp::SimplexElement<dim> &element,
                            const double                      amplitude)
  {
    const double size = std::pow(element.rest_volume(), 1. / dim);
    while (true)
      {
        Tensor<2, dim> A = unit_symmetric_tensor<dim>();
        for (unsigned int i = 0; i < dim; ++i)
          A[i] += random_numbers.vector<dim>(amplitude);
        const Tensor<1, dim> t = random_numbers.vector<dim>(1.);
        Nodes<dim>           x;
        for (unsigned int a = 0; a < dim + 1; ++a)
          x[a] = Point<dim>(A * X[a] + t +
                            random_numbers.vector<dim>(0.5 * amplitude * size));
        if (determinant(element.deformation_gradient(x)) > 0.2)
          return x;
      }
  }

  template <int dim>
  Nodes<dim>
  perturbed(Nodes<dim> x, const unsigned int dof, const double h)
  {
    x[dof / dim][dof % dim] += h;
    return x;
  }

  template <int dim>
  double
  gradient_error(const bfemp::SimplexElement<dim> &element,
                 const Nodes<dim>                 &x,
                 const bfemp::Material<dim>       &material,
                 const double                      h)
  {
    const Vector<double> g = element.gradient(x, material);
    Vector<double>       g_fd(g.size());
    for (unsigned int n = 0; n < g.size(); ++n)
      g_fd[n] = (element.energy(perturbed<dim>(x, n, h), material) -
                 element.energy(perturbed<dim>(x, n, -h), material)) /
                (2. * h);
    g_fd -= g;
    return g_fd.l2_norm() / g.l2_norm();
  }

  template <int dim>
  double
  hessian_error(const bfemp::SimplexElement<dim> &element,
                const Nodes<dim>                 &x,
                const bfemp::Material<dim>       &material,
                const double                      h)
  {
    const FullMatrix<double> H = element.hessian(x, material);
    FullMatrix<double>       H_fd(H.m(), H.n());
    for (unsigned int n = 0; n < H.n(); ++n)
      {
        Vector<double> dg = element.gradient(perturbed<dim>(x, n, h), material);
        dg -= element.gradient(perturbed<dim>(x, n, -h), material);
        for (unsigned int m = 0; m < H.m(); ++m)
          H_fd(m, n) = dg[m] / (2. * h);
      }
    H_fd.add(-1., H);
    return H_fd.frobenius_norm() / H.frobenius_norm();
  }

  template <int dim>
  double
  node_sum_error(const Vector<double> &g)
  {
    Tensor<1, dim> sum;
    for (unsigned int n = 0; n < g.size(); ++n)
      sum[n % dim] += g[n];
    return sum.norm() / g.l2_norm();
  }

  // Energy and gradient of a rigid motion, relative to mu V_e and
  // mu V_e / size.
  template <int dim>
  std::pair<double, double>
  rigid_motion_residual(const bfemp::SimplexElement<dim> &element,
                        const Nodes<dim>                 &X,
                        const bfemp::Material<dim>       &material)
  {
    const Tensor<2, dim> Q = random_rotation<dim>();
    const Tensor<1, dim> t = random_numbers.vector<dim>(3.);
    Nodes<dim>           x;
    for (unsigned int a = 0; a < dim + 1; ++a)
      x[a] = Point<dim>(Q * X[a] + t);

    const double mu_V = material.moduli().mu * element.rest_volume();
    const double size = std::pow(element.rest_volume(), 1. / dim);
    return {std::abs(element.energy(x, material)) / mu_V,
            element.gradient(x, material).l2_norm() * size / mu_V};
  }

  template <int dim>
  void
  check_material(const std::string &model)
  {
    const auto material = bfemp::create_material<dim>(
      model,
      bfemp::ElasticModuli::from_young_poisson(1e5, 0.3));
    const bool rotation_invariant = (model != "linear elastic");

    double max_gradient_error = 0., max_hessian_error = 0.;
    double max_node_sum = 0., max_identity_error = 0.;
    double max_rigid_energy = 0., max_rigid_gradient = 0.;
    for (unsigned int sample = 0; sample < 10; ++sample)
      {
        const double     size = std::pow(10., random_numbers.uniform(-2., 1.));
        const Nodes<dim> X    = random_rest_element<dim>(size);
        const bfemp::SimplexElement<dim> element(X);

        max_identity_error =
          std::max(max_identity_error,
                   (element.deformation_gradient(X) -
                    Tensor<2, dim>(unit_symmetric_tensor<dim>()))
                     .norm());

        const Nodes<dim> x =
          random_deformed_positions<dim>(X, element, sample < 3 ? 0.05 : 0.4);
        const double h   = 1e-6 * size;
        const double e_g = gradient_error(element, x, *material, h);
        const double e_H = hessian_error(element, x, *material, h);
        const double e_sum =
          node_sum_error<dim>(element.gradient(x, *material));
        std::cout << dim << "D " << model << " sample " << sample
                  << ": gradient " << e_g << ", Hessian " << e_H
                  << ", node sum " << e_sum << std::endl;
        max_gradient_error = std::max(max_gradient_error, e_g);
        max_hessian_error  = std::max(max_hessian_error, e_H);
        max_node_sum       = std::max(max_node_sum, e_sum);

        if (rotation_invariant)
          {
            const auto [e_E, e_dE] =
              rigid_motion_residual(element, X, *material);
            max_rigid_energy   = std::max(max_rigid_energy, e_E);
            max_rigid_gradient = std::max(max_rigid_gradient, e_dE);
          }
      }
    std::cout << dim << "D " << model << " max: gradient " << max_gradient_error
              << ", Hessian " << max_hessian_error << ", node sum "
              << max_node_sum << ", rigid E " << max_rigid_energy
              << ", rigid dE " << max_rigid_gradient << std::endl;

    const std::string what =
      std::to_string(dim) + "D " + material->name() + ": ";
    bfemp_tests::check_below(max_identity_error,
                             1e-12,
                             what + "F = I at rest: largest |F - I|");
    bfemp_tests::check_below(max_gradient_error,
                             1e-6,
                             what + "gradient matches FD of energy: largest "
                                    "relative error");
    bfemp_tests::check_below(max_hessian_error,
                             1e-6,
                             what + "Hessian matches FD of gradient: largest "
                                    "relative error");
    bfemp_tests::check_below(max_node_sum,
                             1e-12,
                             what + "gradient sums to zero over nodes: "
                                    "largest |sum| / |gradient|");
    if (rotation_invariant)
      {
        bfemp_tests::check_below(max_rigid_energy,
                                 1e-10,
                                 what + "rigid motion has zero energy: "
                                        "largest |E| / (mu V_e)");
        bfemp_tests::check_below(max_rigid_gradient,
                                 1e-10,
                                 what + "rigid motion has zero gradient: "
                                        "largest |dE| size / (mu V_e)");
      }
  }

  template <int dim>
  bool
  is_rejected(const Nodes<dim> &X)
  {
    try
      {
        const bfemp::SimplexElement<dim> element(X);
      }
    catch (const std::exception &error)
      {
        const std::string message = error.what();
        return message.find("element has non-positive rest volume") !=
               std::string::npos;
      }
    return false;
  }

  /** det B_e / dim!, the signed rest volume the constructor refuses when it
   *  is not positive. */
  template <int dim>
  double
  signed_volume(const Nodes<dim> &X)
  {
    return determinant(edge_basis<dim>(X)) / (dim == 2 ? 2. : 6.);
  }

  template <int dim>
  void
  check_rejection()
  {
    // All nodes on the line x = y = z: zero volume.
    Nodes<dim> degenerate;
    for (unsigned int a = 0; a < dim + 1; ++a)
      for (unsigned int d = 0; d < dim; ++d)
        degenerate[a][d] = a;
    bfemp_tests::check(is_rejected<dim>(degenerate),
                       std::to_string(dim) +
                         "D degenerate element rejected: signed rest volume " +
                         bfemp_tests::format("%.1e",
                                             signed_volume<dim>(degenerate)));

    Nodes<dim> inverted;
    for (unsigned int a = 1; a < dim + 1; ++a)
      inverted[a][a - 1] = 1.;
    std::swap(inverted[1], inverted[2]);
    bfemp_tests::check(is_rejected<dim>(inverted),
                       std::to_string(dim) +
                         "D inverted element rejected: signed rest volume " +
                         bfemp_tests::format("%.1e",
                                             signed_volume<dim>(inverted)));
  }

  template <int dim>
  void
  check_all()
  {
    for (const std::string model :
         {"neo-Hookean", "linear elastic", "fixed corotated"})
      check_material<dim>(model);
    check_rejection<dim>();
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  check_all<2>();
  check_all<3>();
}
