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
    bfemp_tests::check(std::abs(grid_mass - before.mass) < 1e-12 * before.mass,
                       name + "P2G conserves mass");
    bfemp_tests::check((grid_momentum - before.linear_momentum).norm() <
                         1e-12 * momentum_scale,
                       name + "P2G conserves linear momentum");
    bfemp_tests::check(force_scale > 0. &&
                         grid_force.norm() < 1e-12 * force_scale,
                       name + "internal forces sum to zero");
    bfemp_tests::check((after.linear_momentum - grid_momentum).norm() <
                         1e-12 * momentum_scale,
                       name + "G2P conserves linear momentum");
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
