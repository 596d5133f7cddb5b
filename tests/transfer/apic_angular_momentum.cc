// APIC (BFEMP Table 1) conserves angular momentum: the particle angular
// momentum including the affine part m_p eps : (C_p D_p) (as measured by
// StepDiagnostics) equals sum_i x_i x m_i v_i after P2G, and a G2P of a
// force-free explicit step (v~_i = v_i, u_i = dt v_i) gives it back exactly.
// Because the B_p of Table 1 is built from the moved nodes x~_i and particle
// x_p^{n+1}, a G2P of an arbitrary grid motion (random v~_i and u_i, as
// after an implicit solve) gives the particles exactly sum_i x~_i x m_i v~_i.
// Quadratic and cubic kernels, 2D and 3D, random particles with random C_p;
// for the linear kernel, whose G2P takes C_p from the velocity gradient, the
// errors are only reported. PIC loses angular momentum of a rotating body.

#include <cmath>
#include <cstdio>
#include <string>

#include "tests.h"
#include "transfer_scene.h"

using namespace dealii;
using namespace bfemp;
using bfemp_tests::TransferScene;

namespace
{
  std::string
  one_digit(const double x)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.0e", x);
    return buffer;
  }

  /** sum_i |x~_i| |m_i v~_i|: the scale of the angular momenta. */
  template <int dim>
  double
  moment_scale(const TransferScene<dim> &scene, const GridState<dim> &state)
  {
    double scale = 0.;
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      scale +=
        (scene.grid.lattice().node_position(i) + state.displacement[i]).norm() *
        state.mass[i] * state.new_velocity[i].norm();
    return scale;
  }

  template <int dim>
  void
  test_apic(const unsigned int degree)
  {
    TransferScene<dim> scene(degree, TransferParameters::Scheme::apic);
    scene.insert_random(dim == 2 ? 300 : 150, true);
    const std::string name =
      std::to_string(dim) + "D degree " + std::to_string(degree) + ": ";
    // exact for degree 2 and 3, reported for degree 1
    const auto check_or_report = [&](const Tensor<1, 3> &L,
                                     const Tensor<1, 3> &L_expected,
                                     const double        scale,
                                     const std::string  &what) {
      if (degree > 1)
        bfemp_tests::check((L - L_expected).norm() < 1e-12 * scale,
                           name + what);
      else
        dealii::deallog << name << "not exact: " << what << " (relative error "
                        << one_digit((L - L_expected).norm() / scale) << ")"
                        << std::endl;
    };

    // P2G, then a force-free explicit step.
    const Tensor<1, 3> L_particles = scene.measure().angular_momentum;
    GridState<dim>     state       = scene.particles_to_grid();
    const Tensor<1, 3> L_grid      = scene.grid_moment(state.velocity);
    TransferScene<dim>::free_flight(state, 2e-2);
    const double scale = moment_scale(scene, state);
    bfemp_tests::check((L_grid - L_particles).norm() < 1e-12 * scale,
                       name + "P2G: sum_i x_i x m_i v_i = particle L");
    scene.transfer.grid_to_particles(scene.particles, state, true);
    check_or_report(scene.measure().angular_momentum,
                    L_particles,
                    scale,
                    "G2P of a force-free step: particle L unchanged");

    // An arbitrary grid motion (as after an implicit solve, u_i != dt v~_i):
    // Table 1 gives the particles exactly sum_i x~_i x m_i v~_i.
    scene.particles.update_cells();
    state = scene.particles_to_grid();
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      if (state.mass[i] > 0.)
        {
          state.new_velocity[i] = bfemp_tests::random_vector<dim>(1.);
          state.displacement[i] = bfemp_tests::random_vector<dim>(0.01);
        }
    Tensor<1, 3> L_moved;
    for (std::size_t i = 0; i < state.mass.size(); ++i)
      L_moved += bfemp_tests::cross(scene.grid.lattice().node_position(i) +
                                      state.displacement[i],
                                    state.mass[i] * state.new_velocity[i]);
    scene.transfer.grid_to_particles(scene.particles, state, true);
    check_or_report(scene.measure().angular_momentum,
                    L_moved,
                    moment_scale(scene, state),
                    "G2P of an arbitrary grid motion: particle L = sum_i x~_i "
                    "x m_i v~_i");
  }

  /** A body rotating about its center c with angular velocity omega. */
  template <int dim>
  void
  test_pic_rotation()
  {
    TransferScene<dim> scene(2, TransferParameters::Scheme::pic);
    Point<dim>         center;
    Tensor<1, 3>       omega;
    for (unsigned int d = 0; d < dim; ++d)
      center[d] = 0.03 - 0.02 * d;
    omega[2] = 1.;
    if (dim == 3)
      omega[0] = 0.3, omega[1] = -0.5;

    const double radius = 0.2, spacing = 1. / 32.; // two particles per cell
    const int    n = static_cast<int>(radius / spacing);
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = (dim == 3 ? -n : 0); k <= (dim == 3 ? n : 0); ++k)
          {
            Tensor<1, dim> r;
            r[0] = (i + 0.5) * spacing;
            r[1] = (j + 0.5) * spacing;
            if (dim == 3)
              r[dim - 1] = (k + 0.5) * spacing;
            if (r.norm() > radius)
              continue;
            Tensor<1, 3> r3;
            for (unsigned int d = 0; d < dim; ++d)
              r3[d] = r[d];
            const Tensor<1, 3> v3 = cross_product_3d(omega, r3);
            Tensor<1, dim>     v;
            for (unsigned int d = 0; d < dim; ++d)
              v[d] = v3[d];
            scene.insert(center + r, 1e-3, v);
          }
    scene.particles.finish_insertion();

    const Tensor<1, 3> L_before = scene.measure().angular_momentum;
    GridState<dim>     state    = scene.particles_to_grid();
    TransferScene<dim>::free_flight(state, 2e-2);
    scene.transfer.grid_to_particles(scene.particles, state, true);
    const Tensor<1, 3> L_after = scene.measure().angular_momentum;

    const double loss = (L_before - L_after).norm() / L_before.norm();
    dealii::deallog << dim << "D PIC, rotating body: relative change of L "
                    << bfemp_tests::two_decimals(loss) << std::endl;
    bfemp_tests::check(loss > 1e-6,
                       std::to_string(dim) +
                         "D PIC loses angular momentum of a rotating body");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  for (unsigned int degree = 1; degree <= 3; ++degree)
    {
      test_apic<2>(degree);
      test_apic<3>(degree);
    }
  test_pic_rotation<2>();
  test_pic_rotation<3>();
}
