// Properties every material must have independently of its derivatives:
// a stress-free reference state, the common small-strain limit, frame
// invariance of the nonlinear models, a symmetric Cauchy stress, and the
// moduli helpers of the base class.

#include <bfemp/material/material.h>

#include <deal.II/base/tensor.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "tests.h"

using namespace dealii;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(7);

  template <int dim>
  Tensor<2, dim>
  random_deformation(const double amplitude)
  {
    while (true)
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F[i][j] += random_numbers.uniform(-amplitude, amplitude);
        if (determinant(F) > 0.2)
          return F;
      }
  }

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

  const std::vector<std::string> models = {"neo-Hookean",
                                           "linear elastic",
                                           "fixed corotated"};

  const bfemp::ElasticModuli moduli =
    bfemp::ElasticModuli::from_young_poisson(1e6, 0.3);

  template <int dim>
  std::string
  prefix(const bfemp::Material<dim> &material)
  {
    return std::to_string(dim) + "D " + material.name() + ": ";
  }

  template <int dim>
  void
  check_reference_state()
  {
    const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
    const auto linear = bfemp::create_material<dim>("linear elastic", moduli);
    const Tensor<4, dim> tangent = linear->first_piola_kirchhoff_derivative(I);

    for (const std::string &model : models)
      {
        const auto material = bfemp::create_material<dim>(model, moduli);
        bfemp_tests::check(material->name() == model,
                           prefix(*material) + "create_material by name");
        bfemp_tests::check(std::abs(material->energy_density(I)) <=
                               1e-12 * moduli.mu &&
                             material->first_piola_kirchhoff(I).norm() <=
                               1e-12 * moduli.mu,
                           prefix(*material) + "psi(I) = 0 and P(I) = 0");
        const Tensor<4, dim> difference =
          material->first_piola_kirchhoff_derivative(I) - tangent;
        bfemp_tests::check(difference.norm() <= 1e-10 * tangent.norm(),
                           prefix(*material) +
                             "dP/dF(I) equals the linear elastic tangent");
      }
  }

  template <int dim>
  double
  frame_invariance_error(const bfemp::Material<dim> &material,
                         const Tensor<2, dim>       &F,
                         const Tensor<2, dim>       &Q)
  {
    const double         psi = material.energy_density(F);
    const Tensor<2, dim> P   = material.first_piola_kirchhoff(F);
    const double         psi_error =
      std::abs(material.energy_density(Q * F) - psi) / std::abs(psi);
    const double P_error =
      (material.first_piola_kirchhoff(Q * F) - Q * P).norm() / P.norm();
    return std::max(psi_error, P_error);
  }

  template <int dim>
  void
  check_frame_invariance()
  {
    for (const std::string model : {"neo-Hookean", "fixed corotated"})
      {
        const auto material  = bfemp::create_material<dim>(model, moduli);
        double     max_error = 0.;
        double     max_rigid_energy = 0.;
        double     max_rigid_stress = 0.;
        double     max_cauchy_skew  = 0.;
        for (const double angle : {0.3, 2., M_PI - 1e-7, M_PI})
          {
            const Tensor<2, dim> Q = random_rotation<dim>(angle);
            for (const double amplitude : {0.05, 0.4})
              {
                const Tensor<2, dim> F = random_deformation<dim>(amplitude);
                max_error =
                  std::max(max_error, frame_invariance_error(*material, F, Q));

                const Tensor<2, dim> sigma = material->cauchy_stress(Q * F);
                max_cauchy_skew =
                  std::max(max_cauchy_skew,
                           (sigma - transpose(sigma)).norm() / sigma.norm());
              }
            max_rigid_energy =
              std::max(max_rigid_energy, std::abs(material->energy_density(Q)));
            max_rigid_stress =
              std::max(max_rigid_stress,
                       material->first_piola_kirchhoff(Q).norm());
          }
        bfemp_tests::check(max_error < 1e-10,
                           prefix(*material) +
                             "psi(QF) = psi(F) and P(QF) = Q P(F)");
        bfemp_tests::check(max_rigid_energy < 1e-9 * moduli.mu &&
                             max_rigid_stress < 1e-9 * moduli.mu,
                           prefix(*material) +
                             "a rigid rotation is stress free");
        bfemp_tests::check(max_cauchy_skew < 1e-12,
                           prefix(*material) + "Cauchy stress is symmetric");
      }
  }

  void
  check_moduli()
  {
    // Steel: E = 210 GPa, nu = 0.3 gives mu = E / 2.6, lambda = 0.3 E / 0.52
    // and bulk modulus K = lambda + 2 mu / 3 = E / 1.2.
    const bfemp::ElasticModuli steel =
      bfemp::ElasticModuli::from_young_poisson(210e9, 0.3);
    deallog << "steel: mu = " << steel.mu / 1e9
            << " GPa, lambda = " << steel.lambda / 1e9 << " GPa" << std::endl;
    bfemp_tests::check(std::abs(steel.mu - 80.76923076923077e9) < 1e-3 &&
                         std::abs(steel.lambda - 121.15384615384615e9) < 1e-3,
                       "from_young_poisson(210 GPa, 0.3)");
    bfemp_tests::check(std::abs(steel.lambda + 2. / 3. * steel.mu - 175e9) <
                         1e-3,
                       "bulk modulus E / (3 (1 - 2 nu))");

    const bfemp::ElasticModuli cork =
      bfemp::ElasticModuli::from_young_poisson(2e7, 0.);
    bfemp_tests::check(cork.lambda == 0. && cork.mu == 1e7,
                       "nu = 0 gives lambda = 0, mu = E / 2");

    const auto   material = bfemp::create_material<2>("neo-Hookean", moduli);
    const double density  = 1000.;
    const double c        = material->p_wave_speed(density);
    deallog << "p-wave speed (E = 1 MPa, nu = 0.3, rho = 1000) = " << c
            << " m/s" << std::endl;
    bfemp_tests::check(std::abs(c - std::sqrt((moduli.lambda + 2. * moduli.mu) /
                                              density)) <= 1e-14 * c,
                       "p_wave_speed = sqrt((lambda + 2 mu) / rho)");
    // The same from E and nu: c^2 = E (1 - nu) / ((1 + nu)(1 - 2 nu) rho).
    bfemp_tests::check(
      std::abs(c - std::sqrt(1e6 * 0.7 / (1.3 * 0.4 * 1000.))) <= 1e-12 * c,
      "p_wave_speed from E, nu");
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  check_reference_state<2>();
  check_reference_state<3>();
  check_frame_invariance<2>();
  check_frame_invariance<3>();
  check_moduli();
}
