#ifndef bfemp_base_rotation_h
#define bfemp_base_rotation_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace bfemp
{
  /**
   * The rotation by @p angle [rad], counter-clockwise: in 2D in the plane
   * (@p axis ignored), in 3D about the unit vector along @p axis by the
   * right-hand rule (Rodrigues' formula R = I + sin a K + (1 - cos a) K^2 with
   * K the cross-product matrix of the axis). @p axis must be nonzero in 3D.
   */
  template <int dim>
  dealii::Tensor<2, dim>
  rotation_matrix(const double angle, const dealii::Tensor<1, dim> &axis)
  {
    dealii::Tensor<1, 3> n;
    n[2] = 1.;
    if constexpr (dim == 3)
      n = axis / axis.norm();
    dealii::Tensor<2, 3> K;
    K[0][1] = -n[2];
    K[0][2] = n[1];
    K[1][0] = n[2];
    K[1][2] = -n[0];
    K[2][0] = -n[1];
    K[2][1] = n[0];
    const dealii::Tensor<2, 3> R3 =
      dealii::Tensor<2, 3>(dealii::unit_symmetric_tensor<3>()) +
      std::sin(angle) * K + (1. - std::cos(angle)) * K * K;
    dealii::Tensor<2, dim> R;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        R[i][j] = R3[i][j];
    return R;
  }
} // namespace bfemp

#endif
