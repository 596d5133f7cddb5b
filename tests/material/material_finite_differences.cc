// Checks the analytic derivatives of every material against central finite
// differences: P against dpsi/dF and dP/dF against dP/dF of P, in 2D and 3D,
// for moderately and nearly incompressible moduli and for deformations that
// stress different code paths (near identity, large stretch, rotations near
// pi, and for fixed corotated an inverted F).

#include <bfemp/material/material.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tests.h"

using namespace dealii;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(20240611);

  using bfemp_tests::rotation;

  template <int dim>
  Tensor<2, dim>
  random_rotation(const double angle)
  {
    Tensor<1, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = random_numbers.uniform(-1., 1.);
    return rotation(angle, n / n.norm());
  }

  template <int dim>
  Tensor<2, dim>
  random_deformation(const double amplitude)
  {
    while (true)
      {
        const Tensor<2, dim> F = Tensor<2, dim>(unit_symmetric_tensor<dim>()) +
                                 random_numbers.tensor<dim>(amplitude);
        if (determinant(F) > 0.2)
          return F;
      }
  }

  template <int dim>
  std::vector<std::pair<std::string, Tensor<2, dim>>>
  deformations(const bool include_inverted)
  {
    std::vector<std::pair<std::string, Tensor<2, dim>>> Fs;
    Fs.emplace_back("near identity", random_deformation<dim>(1e-3));
    Fs.emplace_back("moderate", random_deformation<dim>(0.3));
    Fs.emplace_back("moderate", random_deformation<dim>(0.3));

    Tensor<2, dim> stretch;
    const double   stretches[3] = {2.5, 0.4, 1.3};
    for (unsigned int d = 0; d < dim; ++d)
      stretch[d][d] = stretches[d];
    Fs.emplace_back(
      "large stretch",
      random_rotation<dim>(random_numbers.uniform(0., 3.)) * stretch *
        transpose(random_rotation<dim>(random_numbers.uniform(0., 3.))));

    Fs.emplace_back("large rotation",
                    random_rotation<dim>(M_PI - 1e-3) *
                      random_deformation<dim>(0.1));
    Fs.emplace_back("rotation by pi",
                    random_rotation<dim>(M_PI) * random_deformation<dim>(1e-3));

    if (include_inverted)
      {
        Tensor<2, dim> reflection    = unit_symmetric_tensor<dim>();
        reflection[dim - 1][dim - 1] = -0.5;
        Fs.emplace_back("inverted",
                        random_rotation<dim>(1.) * reflection *
                          random_deformation<dim>(0.1));
      }
    return Fs;
  }

  template <int dim>
  double
  step_size(const Tensor<2, dim> &F)
  {
    return 1e-6 * F.norm() / std::sqrt(double(dim));
  }

  template <int dim>
  double
  stress_error(const bfemp::Material<dim> &material, const Tensor<2, dim> &F)
  {
    const double   h = step_size(F);
    Tensor<2, dim> P_fd;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = 0; l < dim; ++l)
        {
          Tensor<2, dim> dF;
          dF[k][l]   = h;
          P_fd[k][l] = (material.energy_density(F + dF) -
                        material.energy_density(F - dF)) /
                       (2. * h);
        }
    const Tensor<2, dim> P = material.first_piola_kirchhoff(F);
    return (P_fd - P).norm() / P.norm();
  }

  template <int dim>
  double
  tangent_error(const bfemp::Material<dim> &material, const Tensor<2, dim> &F)
  {
    const double   h = step_size(F);
    Tensor<4, dim> dP_dF_fd;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = 0; l < dim; ++l)
        {
          Tensor<2, dim> dF;
          dF[k][l]                = h;
          const Tensor<2, dim> dP = (material.first_piola_kirchhoff(F + dF) -
                                     material.first_piola_kirchhoff(F - dF)) /
                                    (2. * h);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              dP_dF_fd[i][j][k][l] = dP[i][j];
        }
    const Tensor<4, dim> dP_dF = material.first_piola_kirchhoff_derivative(F);
    return (dP_dF_fd - dP_dF).norm() / dP_dF.norm();
  }

  template <int dim>
  void
  check_material(const std::string &model, const double poisson_ratio)
  {
    const auto material = bfemp::create_material<dim>(
      model,
      bfemp::ElasticModuli::from_young_poisson(1e6, poisson_ratio));

    double max_stress_error  = 0.;
    double max_tangent_error = 0.;
    for (const auto &[label, F] : deformations<dim>(model == "fixed corotated"))
      {
        const double e_P  = stress_error(*material, F);
        const double e_dP = tangent_error(*material, F);
        // The errors of the single deformations go to the console only; the
        // output file records the largest at two significant digits (below
        // 1e-6, so numdiff's absolute tolerance absorbs their rounding).
        std::cout << dim << "D " << model << " nu=" << poisson_ratio << " "
                  << label << ": P " << e_P << ", dP/dF " << e_dP << std::endl;
        max_stress_error  = std::max(max_stress_error, e_P);
        max_tangent_error = std::max(max_tangent_error, e_dP);
      }

    const std::string what =
      std::to_string(dim) + "D " + material->name() +
      ", nu = " + (poisson_ratio == 0.3 ? "0.3" : "0.49") + ": ";
    bfemp_tests::check_below(max_stress_error,
                             1e-6,
                             what + "P matches FD of psi: max relative error");
    bfemp_tests::check_below(max_tangent_error,
                             1e-6,
                             what +
                               "dP/dF matches FD of P: max relative error");
  }

  template <int dim>
  void
  check_all()
  {
    for (const std::string model :
         {"neo-Hookean", "linear elastic", "fixed corotated"})
      for (const double poisson_ratio : {0.3, 0.49})
        check_material<dim>(model, poisson_ratio);
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
