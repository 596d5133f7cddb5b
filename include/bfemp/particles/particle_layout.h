#ifndef bfemp_particles_particle_layout_h
#define bfemp_particles_particle_layout_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * The property layout of every MPM particle in the deal.II
   * Particles::ParticleHandler (all doubles, in this order):
   *
   * | offset | size  | quantity                                   | unit   |
   * |--------|-------|--------------------------------------------|--------|
   * | 0      | 1     | mass m_p                                   | kg     |
   * | 1      | 1     | rest volume V_p^0                          | m^dim  |
   * | 2      | dim   | velocity v_p                               | m/s    |
   * | ..     | dim^2 | deformation gradient F_p (row major)       | -      |
   * | ..     | dim^2 | affine velocity C_p = B_p D_p^-1 (APIC)    | 1/s    |
   * | ..     | dim   | initial position X_p                       | m      |
   * | ..     | 1     | material id (index into the material list) | -      |
   * | ..     | 1     | body id                                    | -      |
   *
   * The position itself is the particle's location in the handler. Storing
   * C instead of B keeps the P2G of BFEMP Table 1 a single matrix-vector
   * product per node; B is recovered as C D_p.
   */
  template <int dim>
  struct ParticleLayout
  {
    static constexpr unsigned int mass                 = 0;
    static constexpr unsigned int rest_volume          = 1;
    static constexpr unsigned int velocity             = 2;
    static constexpr unsigned int deformation_gradient = velocity + dim;
    static constexpr unsigned int affine_velocity =
      deformation_gradient + dim * dim;
    static constexpr unsigned int initial_position =
      affine_velocity + dim * dim;
    static constexpr unsigned int material_id  = initial_position + dim;
    static constexpr unsigned int body_id      = material_id + 1;
    static constexpr unsigned int n_properties = body_id + 1;

    static inline Tensor<1, dim>
    get_vector(const ArrayView<const double> &p, const unsigned int first)
    {
      Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = p[first + d];
      return v;
    }

    static inline void
    set_vector(const ArrayView<double> &p,
               const unsigned int       first,
               const Tensor<1, dim>    &v)
    {
      for (unsigned int d = 0; d < dim; ++d)
        p[first + d] = v[d];
    }

    static inline Tensor<2, dim>
    get_tensor(const ArrayView<const double> &p, const unsigned int first)
    {
      Tensor<2, dim> t;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          t[i][j] = p[first + i * dim + j];
      return t;
    }

    static inline void
    set_tensor(const ArrayView<double> &p,
               const unsigned int       first,
               const Tensor<2, dim>    &t)
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          p[first + i * dim + j] = t[i][j];
    }
  };
} // namespace bfemp

#endif
