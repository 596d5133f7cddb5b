// The kinetic energy APIC particles hand to the grid (BFEMP Table 1): P2G
// averages v_p + C_p (x_i - x_p) over each node, so the grid's kinetic
// energy is at most sum 1/2 m_p |v_p|^2 plus the affine part
// sum 1/2 m_p C_p : (C_p D_p) that StepDiagnostics reports as
// affine_kinetic_energy (Jensen). For a rigid rotation (v_p = w x x_p,
// C_p = skew(w)) every node gets exactly w x x_i and the two are equal, so
// the energy in C_p is real kinetic energy that kinetic_energy alone does
// not count. Quadratic and cubic kernels (D_p = dx^2/4 I, dx^2/3 I), 2D and
// 3D.

#include <string>

#include "tests.h"
#include "transfer_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::TransferScene;

namespace
{
  /** sum_i 1/2 |m_i v_i|^2 / m_i after P2G (momentum in velocity). */
  template <int dim>
  double
  grid_kinetic_energy(const GridState<dim> &state)
  {
    double energy = 0.;
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      if (state.mass[i] > 0.)
        energy += 0.5 * state.velocity[i].norm_square() / state.mass[i];
    return energy;
  }

  template <int dim>
  void
  test_random_particles(const unsigned int degree)
  {
    TransferScene<dim> scene(degree, TransferParameters::Scheme::apic);
    scene.insert_random(dim == 2 ? 300 : 150, true);
    const auto        d    = scene.measure();
    const double      grid = grid_kinetic_energy(scene.particles_to_grid());
    const std::string name =
      std::to_string(dim) + "D degree " + std::to_string(degree) + ": ";
    dealii::deallog << name << "random particles: grid / (kinetic + affine) "
                    << bfemp_tests::two_decimals(
                         grid / (d.kinetic_energy + d.affine_kinetic_energy))
                    << std::endl;
    bfemp_tests::check(d.affine_kinetic_energy > 0. &&
                         grid <= (d.kinetic_energy + d.affine_kinetic_energy) *
                                   (1. + 1e-12),
                       name + "P2G: grid kinetic energy <= particle kinetic "
                              "energy including the affine part");
  }

  template <int dim>
  void
  test_rigid_rotation(const unsigned int degree)
  {
    TransferScene<dim> scene(degree, TransferParameters::Scheme::apic);
    Tensor<1, 3>       omega;
    omega[2] = 2.;
    if (dim == 3)
      omega[0] = 0.7, omega[1] = -0.4;
    Tensor<2, dim> C; // C r = omega x r
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        {
          Tensor<1, 3> e;
          e[b]    = 1.;
          C[a][b] = cross_product_3d(omega, e)[a];
        }
    for (unsigned int q = 0; q < (dim == 2 ? 300u : 150u); ++q)
      {
        const Point<dim> x = scene.random_point();
        Tensor<1, dim>   v = C * x;
        scene.insert(x, 1e-3, v, unit_symmetric_tensor<dim>(), C);
      }
    scene.particles.finish_insertion();

    const auto        d     = scene.measure();
    const double      grid  = grid_kinetic_energy(scene.particles_to_grid());
    const double      total = d.kinetic_energy + d.affine_kinetic_energy;
    const std::string name =
      std::to_string(dim) + "D degree " + std::to_string(degree) + ": ";
    dealii::deallog << name << "rigid rotation: affine / kinetic "
                    << bfemp_tests::two_decimals(d.affine_kinetic_energy /
                                                 d.kinetic_energy)
                    << std::endl;
    bfemp_tests::check(std::abs(grid - total) < 1e-12 * total,
                       name + "rigid rotation: grid kinetic energy = particle "
                              "kinetic + affine energy");
    bfemp_tests::check(grid - d.kinetic_energy > 1e-3 * total,
                       name + "rigid rotation: kinetic energy alone misses "
                              "the affine part");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  for (unsigned int degree = 2; degree <= 3; ++degree)
    {
      test_random_particles<2>(degree);
      test_random_particles<3>(degree);
      test_rigid_rotation<2>(degree);
      test_rigid_rotation<3>(degree);
    }
}
