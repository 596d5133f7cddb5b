// PSD projection of material tangents (projected Newton, BFEMP Section 5):
// the Jacobi eigenvalues agree with LAPACK's, the projection of an indefinite
// tangent is PSD, what it removes is negative semi-definite, it is
// idempotent, and it leaves a PSD tangent unchanged.

#include <bfemp/material/material.h>
#include <bfemp/material/tangent_projection.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <random>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  template <int dim>
  LAPACKFullMatrix<double>
  as_matrix(const Tensor<4, dim> &A)
  {
    LAPACKFullMatrix<double> M(dim * dim, dim * dim);
    for (unsigned int r = 0; r < dim * dim; ++r)
      for (unsigned int c = 0; c < dim * dim; ++c)
        M(r, c) = A[r / dim][r % dim][c / dim][c % dim];
    return M;
  }

  /** Ascending eigenvalues from LAPACK (dsyevx), the reference. */
  template <int dim>
  std::vector<double>
  lapack_eigenvalues(const Tensor<4, dim> &A)
  {
    LAPACKFullMatrix<double> M = as_matrix(A);
    Vector<double>           values;
    FullMatrix<double>       vectors;
    M.compute_eigenvalues_symmetric(-1e300, 1e300, 0., values, vectors);
    return std::vector<double>(values.begin(), values.end());
  }

  template <int dim>
  double
  norm(const Tensor<4, dim> &A)
  {
    return std::sqrt(scalar_product(A, A));
  }

  template <int dim>
  std::vector<Tensor<2, dim>>
  deformations()
  {
    std::mt19937                           rng(7);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    std::vector<Tensor<2, dim>>            Fs;
    Fs.push_back(unit_symmetric_tensor<dim>()); // PSD reference case
    for (const double stretch : {0.2, 0.5, 1.6, 3.0})
      {
        Tensor<2, dim> F = unit_symmetric_tensor<dim>();
        F[0][0]          = stretch;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F[i][j] += (i != j) * u(rng);
        Fs.push_back(F);
      }
    return Fs;
  }

  template <int dim>
  void
  check_material(const std::string &model)
  {
    const auto material =
      create_material<dim>(model, ElasticModuli::from_young_poisson(1e5, 0.3));
    unsigned int n_indefinite = 0, n_deformations = 0;
    double       worst_lapack = 0., worst_psd = 0., worst_removed = 0.,
           worst_idempotent = 0., worst_unchanged = 0.;
    for (const auto &F : deformations<dim>())
      {
        if (determinant(F) <= 0.)
          continue;
        ++n_deformations;
        const Tensor<4, dim> A = material->first_piola_kirchhoff_derivative(F);
        const TangentProjection<dim> projection(A);
        const auto                  &lambda = projection.eigenvalues();
        const double                 scale =
          std::max(std::abs(lambda.front()), std::abs(lambda.back()));

        const auto reference = lapack_eigenvalues(A);
        for (unsigned int m = 0; m < dim * dim; ++m)
          worst_lapack =
            std::max(worst_lapack, std::abs(lambda[m] - reference[m]) / scale);

        const Tensor<4, dim> P                = projection.projected();
        const auto           projected_values = lapack_eigenvalues(P);
        worst_psd = std::max(worst_psd, -projected_values.front() / scale);
        const auto removed_values = lapack_eigenvalues(A - P);
        worst_removed = std::max(worst_removed, removed_values.back() / scale);
        worst_idempotent =
          std::max(worst_idempotent,
                   norm(project_to_positive_semidefinite(P) - P) / norm(P));
        if (lambda.front() >= 0.)
          worst_unchanged = std::max(worst_unchanged, norm(P - A) / norm(A));
        else
          ++n_indefinite;
      }
    const std::string name = std::to_string(dim) + "D " + model;
    bfemp_tests::check_below(worst_lapack,
                             1e-12,
                             name + ": eigenvalues agree with LAPACK: largest "
                                    "difference / |lambda|_max");
    bfemp_tests::check_below(worst_psd,
                             1e-12,
                             name + ": projection is PSD: largest -lambda_min "
                                    "/ |lambda|_max");
    bfemp_tests::check_below(worst_removed,
                             1e-12,
                             name + ": the removed part is negative "
                                    "semi-definite: largest lambda_max / "
                                    "|lambda|_max");
    bfemp_tests::check_below(worst_idempotent,
                             1e-12,
                             name + ": projecting twice changes nothing: "
                                    "largest relative change");
    bfemp_tests::check_below(worst_unchanged,
                             1e-12,
                             name + ": a PSD tangent is left unchanged: "
                                    "largest relative change");
    if (model != "linear elastic")
      bfemp_tests::check(n_indefinite > 0,
                         name +
                           ": some deformation has an indefinite "
                           "tangent: " +
                           std::to_string(n_indefinite) + " of " +
                           std::to_string(n_deformations));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  for (const std::string model :
       {"neo-Hookean", "linear elastic", "fixed corotated"})
    {
      check_material<2>(model);
      check_material<3>(model);
    }
}
