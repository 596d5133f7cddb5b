// P2G of BFEMP Tables 1-3 conserves mass and linear momentum (APIC's affine
// term C_p (x_i - x_p) adds none, since sum_i w_ip (x_i - x_p) = 0), the
// internal forces of random deformation gradients sum to zero, and a G2P
// without forces gives the particles back the grid momentum: PIC, FLIP and
// APIC, linear, quadratic and cubic kernels, 2D and 3D, random particles.

#include <cmath>
#include <string>

#include "tests.h"
#include "transfer_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::TransferScene;

namespace
{
  template <int dim>
  void
  test(const unsigned int degree, const TransferParameters::Scheme scheme)
  {
    const bool         apic = scheme == TransferParameters::Scheme::apic;
    TransferScene<dim> scene(degree, scheme);
    scene.insert_random(dim == 2 ? 300 : 150, apic);

    const StepDiagnostics<dim> before         = scene.measure();
    const double               momentum_scale = before.mass * before.max_speed;
    GridState<dim>             state          = scene.particles_to_grid(true);

    double         grid_mass = 0., force_scale = 0.;
    Tensor<1, dim> grid_momentum, grid_force;
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      {
        grid_mass += state.mass[i];
        grid_momentum += state.velocity[i];
        grid_force += state.force[i];
        force_scale += state.force[i].norm();
      }

    TransferScene<dim>::free_flight(state, 1e-3);
    scene.transfer.grid_to_particles(scene.particles, state, true);
    const StepDiagnostics<dim> after = scene.measure();

    const std::string name = std::to_string(dim) + "D degree " +
                             std::to_string(degree) + " " +
                             bfemp_tests::scheme_name(scheme) + ": ";
    // Each relative to its scale: the mass, sum_p m_p max |v_p| and
    // sum_i |f_i|.
    bfemp_tests::check_below(std::abs(grid_mass - before.mass) / before.mass,
                             1e-12,
                             name + "P2G conserves mass: relative error");
    bfemp_tests::check_below((grid_momentum - before.linear_momentum).norm() /
                               momentum_scale,
                             1e-12,
                             name +
                               "P2G conserves linear momentum: relative error");
    bfemp_tests::check(force_scale > 0. &&
                         grid_force.norm() <= 1e-12 * force_scale,
                       name +
                         "internal forces sum to zero: |sum_i f_i| / "
                         "sum_i |f_i| " +
                         bfemp_tests::measured(grid_force.norm() / force_scale,
                                               1e-12));
    bfemp_tests::check_below((after.linear_momentum - grid_momentum).norm() /
                               momentum_scale,
                             1e-12,
                             name +
                               "G2P conserves linear momentum: relative error");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  for (const auto scheme : {TransferParameters::Scheme::pic,
                            TransferParameters::Scheme::flip,
                            TransferParameters::Scheme::apic})
    for (unsigned int degree = 1; degree <= 3; ++degree)
      {
        test<2>(degree, scheme);
        test<3>(degree, scheme);
      }
}
