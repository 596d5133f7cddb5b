#include <bfemp/material/fixed_corotated.h>
#include <bfemp/material/singular_value_decomposition.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace bfemp
{
  namespace
  {
    /** F = R S with R a proper rotation and S symmetric. */
    template <int dim>
    struct PolarDecomposition
    {
      Tensor<2, dim>          R;
      SymmetricTensor<2, dim> S;
    };



    /**
     * In 2D, R^T F is symmetric for two rotation angles, theta and
     * theta + pi; atan2 picks the one with tr(R^T F) >= 0, which is the
     * closest rotation. The formula is exact and has no special cases at
     * theta = pi or F = R. (Only a symmetric traceless F, which has
     * det F < 0, leaves theta undetermined; atan2(0, 0) then gives R = I.)
     */
    PolarDecomposition<2>
    polar_decomposition(const Tensor<2, 2> &F)
    {
      const double theta = std::atan2(F[1][0] - F[0][1], F[0][0] + F[1][1]);
      const double c     = std::cos(theta);
      const double s     = std::sin(theta);

      PolarDecomposition<2> polar;
      polar.R[0][0] = c;
      polar.R[0][1] = -s;
      polar.R[1][0] = s;
      polar.R[1][1] = c;
      polar.S       = symmetrize(transpose(polar.R) * F);
      return polar;
    }



    /**
     * In 3D, the scaled Newton iteration X <- (g X + X^-T / g) / 2 (Higham,
     * 1986) converges quadratically to the orthogonal polar factor Q for any
     * nonsingular F. Its iterates are Q times a function of F^T F, so the
     * rotation angle (near pi or not) does not affect it, and F close to a
     * rotation converges in one or two steps. It works on F itself; going
     * through sqrt(F^T F) would square the condition number.
     * For det F < 0, Q is a reflection; it is turned into the closest
     * rotation by flipping the direction of the smallest singular value.
     */
    PolarDecomposition<3>
    polar_decomposition(const Tensor<2, 3> &F)
    {
      const double J = determinant(F);
      Assert(J != 0., ExcMessage("polar decomposition needs det F != 0"));

      Tensor<2, 3> Q = F;
      for (unsigned int iteration = 0; iteration < 100; ++iteration)
        {
          const Tensor<2, 3> Q_inv_T = transpose(invert(Q));
          const double       g       = std::sqrt(Q_inv_T.norm() / Q.norm());
          const Tensor<2, 3> Q_next  = 0.5 * (g * Q + Q_inv_T / g);
          const double       change  = (Q_next - Q).norm();
          Q                          = Q_next;
          // The error after a step is about the square of the change, so
          // this leaves Q orthogonal to machine precision.
          if (change < 1e-9)
            break;
        }

      PolarDecomposition<3> polar;
      polar.R = Q;
      polar.S = symmetrize(transpose(Q) * F);
      if (J < 0.)
        {
          const Tensor<1, 3> v = eigenvectors(polar.S)[2].second;
          polar.R              = Q * (Tensor<2, 3>(unit_symmetric_tensor<3>()) -
                         2. * outer_product(v, v));
          polar.S              = symmetrize(transpose(polar.R) * F);
        }
      return polar;
    }



    /** The skew W with W S + S W = A (A skew), in 2D a scalar equation. */
    Tensor<2, 2>
    solve_spin(const SymmetricTensor<2, 2> &S, const Tensor<2, 2> &A)
    {
      const double w = A[1][0] / trace(S);
      Tensor<2, 2> W;
      W[0][1] = -w;
      W[1][0] = w;
      return W;
    }



    /**
     * In 3D, W S + S W for a skew W with axial vector w (W v = w x v) is the
     * skew tensor with axial vector (tr(S) I - S) w.
     */
    Tensor<2, 3>
    solve_spin(const SymmetricTensor<2, 3> &S, const Tensor<2, 3> &A)
    {
      const Tensor<1, 3> a({A[2][1], A[0][2], A[1][0]});
      const Tensor<2, 3> G =
        invert(Tensor<2, 3>(trace(S) * unit_symmetric_tensor<3>() - S));
      const Tensor<1, 3> w = G * a;
      Tensor<2, 3>       W;
      W[2][1] = w[0];
      W[1][2] = -w[0];
      W[0][2] = w[1];
      W[2][0] = -w[1];
      W[1][0] = w[2];
      W[0][1] = -w[2];
      return W;
    }
  } // namespace



  template <int dim>
  FixedCorotated<dim>::FixedCorotated(const ElasticModuli &moduli)
    : Material<dim>(moduli)
  {}



  template <int dim>
  double
  FixedCorotated<dim>::energy_density(const Tensor<2, dim> &F) const
  {
    const Tensor<2, dim> F_minus_R = F - polar_decomposition(F).R;
    const double         J         = determinant(F);
    return this->elastic_moduli.mu * scalar_product(F_minus_R, F_minus_R) +
           0.5 * this->elastic_moduli.lambda * (J - 1.) * (J - 1.);
  }



  template <int dim>
  Tensor<2, dim>
  FixedCorotated<dim>::first_piola_kirchhoff(const Tensor<2, dim> &F) const
  {
    const double J = determinant(F);
    return 2. * this->elastic_moduli.mu * (F - polar_decomposition(F).R) +
           this->elastic_moduli.lambda * (J - 1.) * cofactor(F);
  }



  template <int dim>
  Tensor<4, dim>
  FixedCorotated<dim>::first_piola_kirchhoff_derivative(
    const Tensor<2, dim> &F) const
  {
    const double                  mu     = this->elastic_moduli.mu;
    const double                  lambda = this->elastic_moduli.lambda;
    const double                  J      = determinant(F);
    const Tensor<2, dim>          C      = cofactor(F);
    const PolarDecomposition<dim> polar  = polar_decomposition(F);

    // d cof_ij / dF_kl = (cof_ij cof_kl - cof_il cof_kj) / J.
    Tensor<4, dim> dP_dF = lambda * (2. - 1. / J) * outer_product(C, C);
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = 0; l < dim; ++l)
        {
          Tensor<2, dim> dF;
          dF[k][l]               = 1.;
          const Tensor<2, dim> M = transpose(polar.R) * dF;
          const Tensor<2, dim> dR =
            polar.R * solve_spin(polar.S, M - transpose(M));
          const Tensor<2, dim> dP = 2. * mu * (dF - dR);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              dP_dF[i][j][k][l] +=
                dP[i][j] - lambda * (J - 1.) / J * C[i][l] * C[k][j];
        }
    return dP_dF;
  }



  template <int dim>
  Tensor<4, dim>
  FixedCorotated<dim>::filtered_first_piola_kirchhoff_derivative(
    const Tensor<2, dim>  &F,
    const EigenvalueFilter filter) const
  {
    const SingularValueDecomposition<dim> svd =
      signed_singular_value_decomposition(F);
    const Tensor<1, dim> &sigma = svd.sigma;

    const double mu     = this->elastic_moduli.mu;
    const double lambda = this->elastic_moduli.lambda;
    // J_i = prod_{k != i} sigma_k and J_ij = prod_{k != i, j} sigma_k,
    // formed without dividing by a possibly vanishing sigma_i.
    double J = 1.;
    double J_i[dim];
    for (unsigned int i = 0; i < dim; ++i)
      {
        J *= sigma[i];
        J_i[i] = 1.;
        for (unsigned int k = 0; k < dim; ++k)
          if (k != i)
            J_i[i] *= sigma[k];
      }

    SymmetricTensor<2, dim> hessian, twist, flip;
    for (unsigned int i = 0; i < dim; ++i)
      {
        hessian[i][i] = 2. * mu + lambda * J_i[i] * J_i[i];
        for (unsigned int j = i + 1; j < dim; ++j)
          {
            double J_ij = 1.;
            for (unsigned int k = 0; k < dim; ++k)
              if (k != i && k != j)
                J_ij *= sigma[k];
            const double c = lambda * (J - 1.) * J_ij;
            hessian[i][j]  = lambda * J_i[i] * J_i[j] + c;
            twist[i][j]    = 2. * mu + c - 4. * mu / (sigma[i] + sigma[j]);
            flip[i][j]     = 2. * mu - c;
          }
      }
    return project_isotropic_tangent(svd, hessian, twist, flip, filter);
  }



  template <int dim>
  std::string
  FixedCorotated<dim>::name() const
  {
    return "fixed corotated";
  }



  template class FixedCorotated<2>;
  template class FixedCorotated<3>;
} // namespace bfemp
