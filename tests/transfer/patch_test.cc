// Patch test of the G2P of BFEMP Tables 1-3: the grid carries a homogeneous
// velocity field v~(x) = A x + b (end-of-step velocity and displacement
// u = dt v~ on every node) and an old velocity field w(x) = A0 x + b0. Every
// particle must then get exactly F = (I + dt A) F_old, x + dt (A x + b),
// the velocity A x + b (PIC, APIC) or v_p + v~(x_p) - w(x_p) (FLIP), and,
// for APIC, C_p = A. All kernels, 2D and 3D.

#include <map>
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
    using Layout = ParticleLayout<dim>;
    using Scheme = TransferParameters::Scheme;
    TransferScene<dim> scene(degree, scheme);
    scene.insert_random(dim == 2 ? 200 : 100, scheme == Scheme::apic);

    const double         dt = 1e-2;
    const Tensor<2, dim> A  = bfemp_tests::random_tensor<dim>(1.);
    const Tensor<2, dim> A0 = bfemp_tests::random_tensor<dim>(1.);
    const Tensor<1, dim> b  = bfemp_tests::random_vector<dim>(1.);
    const Tensor<1, dim> b0 = bfemp_tests::random_vector<dim>(1.);

    GridState<dim> state;
    state.reinit(scene.grid.lattice().n_nodes);
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      {
        const Point<dim> x    = scene.grid.lattice().node_position(i);
        state.velocity[i]     = A0 * x + b0;
        state.new_velocity[i] = A * x + b;
        state.displacement[i] = dt * state.new_velocity[i];
      }

    struct Old
    {
      Point<dim>     x;
      Tensor<1, dim> v;
      Tensor<2, dim> F;
    };
    std::map<types::particle_index, Old> old;
    for (const auto &particle : scene.particles.handler())
      old[particle.get_id()] = {
        particle.get_location(),
        Layout::get_vector(particle.get_properties(), Layout::velocity),
        Layout::get_tensor(particle.get_properties(),
                           Layout::deformation_gradient)};

    scene.transfer.grid_to_particles(scene.particles, state, true);

    const Tensor<2, dim> I     = unit_symmetric_tensor<dim>();
    double               max_F = 0., max_x = 0., max_v = 0., max_C = 0.;
    for (const auto &particle : scene.particles.handler())
      {
        const Old           &o = old.at(particle.get_id());
        const auto           p = particle.get_properties();
        const Tensor<1, dim> v = Layout::get_vector(p, Layout::velocity);
        const Tensor<1, dim> v_expected = scheme == Scheme::flip
                                            ? o.v + (A - A0) * o.x + (b - b0)
                                            : A * o.x + b;
        max_F                           = std::max(max_F,
                         (Layout::get_tensor(p, Layout::deformation_gradient) -
                          (I + dt * A) * o.F)
                           .norm());
        max_x =
          std::max(max_x,
                   (particle.get_location() - o.x - dt * (A * o.x + b)).norm());
        max_v = std::max(max_v, (v - v_expected).norm());
        max_C =
          std::max(max_C,
                   (Layout::get_tensor(p, Layout::affine_velocity) - A).norm());
      }

    const std::string name = std::to_string(dim) + "D degree " +
                             std::to_string(degree) + " " +
                             bfemp_tests::scheme_name(scheme) + ": ";
    bfemp_tests::check_below(max_F,
                             1e-13,
                             name + "F = (I + dt A) F_old: largest error");
    bfemp_tests::check_below(max_x,
                             1e-13,
                             name +
                               "x = x_old + dt (A x_old + b): largest error");
    bfemp_tests::check_below(max_v,
                             1e-13,
                             name +
                               (scheme == Scheme::flip
                                  ? "v = v_old + (A - A0) x_old + b - b0"
                                  : "v = A x_old + b") +
                               ": largest error");
    if (scheme == Scheme::apic)
      bfemp_tests::check_below(max_C, 1e-12, name + "C = A: largest error");
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
