// Analytic PSD projections of the material tangents (projected Newton, BFEMP
// Section 5) against the numerical (Jacobi) projection of the base class:
//  - the signed SVD reconstructs F with proper rotations, ordered singular
//    values and the sign of det F on the last one, also for repeated
//    singular values and rank-deficient F;
//  - for neo-Hookean and fixed corotated, in 2D and 3D, the analytic
//    projection equals project_to_positive_semidefinite(dP/dF) to 1e-8
//    relative, is symmetric and PSD, and returns dP/dF itself where that is
//    already PSD; deformations near identity, moderate, large stretch,
//    compression toward J -> 0, repeated singular values, exactly the
//    identity, rotations by pi and (fixed corotated only, neo-Hookean is
//    not defined there) inverted F;
//  - the same with negative eigenvalues replaced by their absolute values
//    (EigenvalueFilter::absolute, Chen et al. 2024): equal to the Jacobi
//    filter to 1e-8, with eigenvalues |eig(dP/dF)| to 1e-10;
//  - linear elastic returns its raw tangent for every admissible (E, nu),
//    including nu < 0 where lambda < 0 in 2D plane strain, and projects
//    inadmissible moduli like the numerical projection.

#include <bfemp/material/fixed_corotated.h>
#include <bfemp/material/linear_elastic.h>
#include <bfemp/material/material.h>
#include <bfemp/material/neo_hookean.h>
#include <bfemp/material/singular_value_decomposition.h>
#include <bfemp/material/tangent_projection.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(20240917);

  template <int dim>
  double
  norm(const Tensor<4, dim> &A)
  {
    return std::sqrt(scalar_product(A, A));
  }

  /** Ascending eigenvalues of A read as a dim^2 x dim^2 matrix (LAPACK). */
  template <int dim>
  std::vector<double>
  lapack_eigenvalues(const Tensor<4, dim> &A)
  {
    LAPACKFullMatrix<double> M(dim * dim, dim * dim);
    for (unsigned int r = 0; r < dim * dim; ++r)
      for (unsigned int c = 0; c < dim * dim; ++c)
        M(r, c) = A[r / dim][r % dim][c / dim][c % dim];
    Vector<double>     values;
    FullMatrix<double> vectors;
    M.compute_eigenvalues_symmetric(-1e300, 1e300, 0., values, vectors);
    return std::vector<double>(values.begin(), values.end());
  }

  template <int dim>
  Tensor<2, dim>
  random_rotation()
  {
    Tensor<1, dim> n;
    do
      n = random_numbers.vector<dim>(1.);
    while (n.norm() < 0.1);
    return bfemp_tests::rotation(random_numbers.uniform(-M_PI, M_PI),
                                 n / n.norm());
  }

  /**
   * R1 diag(s) R2^T with random rotations R1, R2 and the three values @p s
   * in 3D, s_0 and s_2 in 2D (the last one carries the sign of det F).
   */
  template <int dim>
  Tensor<2, dim>
  with_singular_values(const std::vector<double> &s)
  {
    Tensor<2, dim> D;
    for (unsigned int d = 0; d < dim; ++d)
      D[d][d] = (dim == 2 && d == 1 ? s[2] : s[d]);
    return random_rotation<dim>() * D * transpose(random_rotation<dim>());
  }

  template <int dim>
  Tensor<2, dim>
  random_deformation(const double amplitude, const double min_J)
  {
    while (true)
      {
        const Tensor<2, dim> F = Tensor<2, dim>(unit_symmetric_tensor<dim>()) +
                                 random_numbers.tensor<dim>(amplitude);
        if (determinant(F) > min_J)
          return F;
      }
  }

  /**
   * Test deformations. The inverted ones keep |sigma_i + sigma_j| away from
   * zero, where the fixed corotated R (and the tangent) is not
   * differentiable.
   */
  template <int dim>
  std::vector<std::pair<std::string, Tensor<2, dim>>>
  deformations()
  {
    std::vector<std::pair<std::string, Tensor<2, dim>>> Fs;
    const auto add = [&Fs](const std::string         &kind,
                           const std::vector<double> &s) {
      Fs.emplace_back(kind, with_singular_values<dim>(s));
    };

    Fs.emplace_back("identity", unit_symmetric_tensor<dim>());
    for (unsigned int n = 0; n < 4; ++n)
      Fs.emplace_back("near identity", random_deformation<dim>(1e-3, 0.));
    for (unsigned int n = 0; n < 8; ++n)
      Fs.emplace_back("moderate", random_deformation<dim>(0.4, 0.2));
    add("large stretch", {3., 0.4, 1.7});
    add("large stretch", {5., 2., 0.2});
    add("compression", {1.1, 0.9, 1e-1});
    add("compression", {0.8, 1.2, 1e-3});
    add("compression", {0.3, 0.2, 0.1});
    add("compression", {1e-2, 1e-2, 1e-2});
    add("repeated", {1.5, 0.5, 1.5});
    add("repeated", {2., 0.6, 0.6});
    add("repeated", {0.7, 0.7, 0.7});
    add("repeated", {1., 1., 1.});
    add("repeated", {1. + 1e-9, 1. + 2e-9, 1. - 1e-9});
    Tensor<1, dim> axis;
    axis[dim - 1] = 1.;
    Fs.emplace_back("rotation by pi",
                    bfemp_tests::rotation(M_PI, axis) *
                      random_deformation<dim>(0.05, 0.));

    add("inverted", {2., 1., -0.5});
    add("inverted", {1.3, 1.1, -0.2});
    add("inverted", {1.5, 1.5, -0.5});
    add("inverted", {1., 0.5, -0.4});
    for (unsigned int n = 0; n < 4; ++n)
      {
        Tensor<2, dim> reflection    = unit_symmetric_tensor<dim>();
        reflection[dim - 1][dim - 1] = -0.3;
        Fs.emplace_back("inverted",
                        random_deformation<dim>(0.2, 0.5) * reflection);
      }
    return Fs;
  }

  template <int dim>
  void
  check_singular_value_decomposition()
  {
    std::vector<Tensor<2, dim>> Fs;
    for (const auto &F : deformations<dim>())
      Fs.push_back(F.second);
    Fs.emplace_back(); // F = 0
    Tensor<1, dim> a = random_numbers.vector<dim>(1.),
                   b = random_numbers.vector<dim>(1.);
    Fs.push_back(outer_product(a, b)); // rank 1
    if (dim == 3)
      Fs.push_back(with_singular_values<dim>({2., 0.5, 0.})); // rank 2
    for (unsigned int n = 0; n < 50; ++n)
      Fs.push_back(random_numbers.tensor<dim>(2.));

    double worst_reconstruction = 0., worst_orthogonality = 0.;
    bool   rotations = true, ordered = true, signed_last = true;
    for (const auto &F : Fs)
      {
        const auto     svd = signed_singular_value_decomposition(F);
        Tensor<2, dim> Sigma;
        for (unsigned int d = 0; d < dim; ++d)
          Sigma[d][d] = svd.sigma[d];
        const double scale = std::max(F.norm(), 1e-300);
        worst_reconstruction =
          std::max(worst_reconstruction,
                   (svd.U * Sigma * transpose(svd.V) - F).norm() / scale);
        const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
        worst_orthogonality    = std::max({worst_orthogonality,
                                           (transpose(svd.U) * svd.U - I).norm(),
                                           (transpose(svd.V) * svd.V - I).norm()});
        rotations =
          rotations && determinant(svd.U) > 0. && determinant(svd.V) > 0.;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          ordered = ordered && svd.sigma[d] >= 0. &&
                    svd.sigma[d] >= std::abs(svd.sigma[d + 1]);
        const double J = determinant(F);
        if (std::abs(J) > 1e-12 * std::pow(scale, dim))
          signed_last = signed_last && (svd.sigma[dim - 1] > 0.) == (J > 0.);
      }
    const std::string name = std::to_string(dim) + "D signed SVD";
    bfemp_tests::check(worst_reconstruction < 1e-14,
                       name + ": U Sigma V^T = F");
    bfemp_tests::check(worst_orthogonality < 1e-14 && rotations,
                       name + ": U and V are proper rotations");
    bfemp_tests::check(ordered,
                       name + ": singular values ordered by magnitude, "
                              "only the last one negative");
    bfemp_tests::check(signed_last,
                       name + ": the last singular value has the sign "
                              "of det F");
  }

  template <int dim>
  void
  check_material(const Material<dim> &material, const std::string &moduli)
  {
    const std::string name =
      std::to_string(dim) + "D " + material.name() + " (" + moduli + ")";
    const bool   defined_inverted = (material.name() != "neo-Hookean");
    unsigned int n_checked = 0, n_psd = 0, n_indefinite = 0;
    double       worst_jacobi = 0., worst_symmetry = 0., worst_psd = 0.,
           worst_unchanged = 0., worst_absolute_jacobi = 0.,
           worst_absolute_values = 0.;
    for (const auto &[kind, F] : deformations<dim>())
      {
        if (determinant(F) <= 0. && !defined_inverted)
          continue;
        ++n_checked;
        const Tensor<4, dim> A = material.first_piola_kirchhoff_derivative(F);
        const TangentProjection<dim> jacobi(A);
        const Tensor<4, dim>         P_jacobi = jacobi.projected();
        const Tensor<4, dim>         P =
          material.projected_first_piola_kirchhoff_derivative(F);
        const double scale = norm(P_jacobi);

        const double error = norm(P - P_jacobi) / scale;
        if (error > 1e-8)
          deallog << "  " << kind << ": differs from Jacobi by " << error
                  << std::endl;
        worst_jacobi = std::max(worst_jacobi, error);

        // absolute eigenvalues (Chen et al. 2024): the same eigenvectors,
        // |lambda_m| for each eigenvalue
        const Tensor<4, dim> P_absolute =
          material.filtered_first_piola_kirchhoff_derivative(
            F,
            EigenvalueFilter::absolute);
        const double absolute_scale = norm(A);
        worst_absolute_jacobi =
          std::max(worst_absolute_jacobi,
                   norm(P_absolute -
                        jacobi.filtered(EigenvalueFilter::absolute)) /
                     absolute_scale);
        std::vector<double> expected = lapack_eigenvalues(A);
        for (double &lambda : expected)
          lambda = std::abs(lambda);
        std::sort(expected.begin(), expected.end());
        const std::vector<double> absolute_values =
          lapack_eigenvalues(P_absolute);
        for (unsigned int m = 0; m < expected.size(); ++m)
          worst_absolute_values =
            std::max(worst_absolute_values,
                     std::abs(absolute_values[m] - expected[m]) /
                       expected.back());

        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                worst_symmetry =
                  std::max(worst_symmetry,
                           std::abs(P[i][j][k][l] - P[k][l][i][j]) / scale);

        const auto values = lapack_eigenvalues(P);
        worst_psd = std::max(worst_psd, -values.front() / values.back());

        const auto &lambda = jacobi.eigenvalues();
        if (lambda.front() >= -1e-12 * lambda.back())
          {
            ++n_psd;
            worst_unchanged = std::max(worst_unchanged, norm(P - A) / norm(A));
          }
        else
          ++n_indefinite;
      }
    deallog << name << ": " << n_checked << " deformations, " << n_psd
            << " with a PSD tangent, " << n_indefinite << " indefinite"
            << std::endl;
    bfemp_tests::check(worst_jacobi < 1e-8,
                       name + ": equals the Jacobi projection");
    bfemp_tests::check(worst_symmetry < 1e-15, name + ": symmetric");
    bfemp_tests::check(worst_psd < 1e-12, name + ": PSD");
    bfemp_tests::check(worst_unchanged < 1e-8,
                       name + ": a PSD tangent is returned unchanged");
    bfemp_tests::check(n_psd > 0 && n_indefinite > 0,
                       name + ": both PSD and indefinite tangents occur");
    bfemp_tests::check_below(worst_absolute_jacobi,
                             1e-8,
                             name + ": absolute eigenvalues equal the Jacobi "
                                    "filter: largest difference / |dP/dF|");
    bfemp_tests::check_below(worst_absolute_values,
                             1e-10,
                             name + ": absolute eigenvalues are |eig(dP/dF)| "
                                    "(LAPACK): largest difference / "
                                    "|lambda|_max");
  }

  template <int dim>
  void
  check_linear_elastic()
  {
    const std::string name      = std::to_string(dim) + "D linear elastic";
    bool              unchanged = true;
    double            worst_psd = 0.;
    for (const double nu : {-0.99, -0.5, -0.1, 0., 0.3, 0.45, 0.499})
      {
        const LinearElastic<dim> material(
          ElasticModuli::from_young_poisson(1e5, nu));
        const Tensor<2, dim> F = random_deformation<dim>(0.3, 0.2);
        const Tensor<4, dim> A = material.first_piola_kirchhoff_derivative(F);
        unchanged              = unchanged &&
                    material.projected_first_piola_kirchhoff_derivative(F) == A;
        const auto values = lapack_eigenvalues(A);
        worst_psd = std::max(worst_psd, -values.front() / values.back());
      }
    bfemp_tests::check(worst_psd < 1e-14,
                       name + ": PSD for every admissible (E, nu)");
    bfemp_tests::check(unchanged,
                       name + ": the raw tangent is returned for every "
                              "admissible (E, nu)");

    // Moduli outside the admissible range, set directly.
    double worst_jacobi = 0.;
    for (const auto &[lambda, mu] :
         std::vector<std::pair<double, double>>{{-2., 1.},
                                                {1., -1.},
                                                {-3., -1.}})
      {
        ElasticModuli moduli;
        moduli.lambda = lambda;
        moduli.mu     = mu;
        const LinearElastic<dim> material(moduli);
        const Tensor<2, dim>     F        = unit_symmetric_tensor<dim>();
        const Tensor<4, dim>     P_jacobi = project_to_positive_semidefinite(
          material.first_piola_kirchhoff_derivative(F));
        worst_jacobi =
          std::max(worst_jacobi,
                   norm(material.projected_first_piola_kirchhoff_derivative(F) -
                        P_jacobi) /
                     norm(material.first_piola_kirchhoff_derivative(F)));
      }
    bfemp_tests::check(worst_jacobi < 1e-12,
                       name + ": inadmissible moduli are projected like "
                              "the Jacobi projection");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  check_singular_value_decomposition<2>();
  check_singular_value_decomposition<3>();

  for (const auto &[label, nu] :
       std::vector<std::pair<std::string, double>>{{"nu = 0.3", 0.3},
                                                   {"nu = 0.45", 0.45},
                                                   {"nu = -0.5", -0.5}})
    {
      const ElasticModuli moduli = ElasticModuli::from_young_poisson(1e5, nu);
      check_material(NeoHookean<2>(moduli), label);
      check_material(NeoHookean<3>(moduli), label);
      check_material(FixedCorotated<2>(moduli), label);
      check_material(FixedCorotated<3>(moduli), label);
    }

  check_linear_elastic<2>();
  check_linear_elastic<3>();
}
