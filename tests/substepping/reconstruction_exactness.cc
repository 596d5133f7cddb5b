// Seed 003: the macro-step grid velocity reconstructed from particles that
// carry an affine velocity field v(x) = a + B x (translation, rotation and
// uniform strain rate: B has a skew and a symmetric part) is that field on
// the grid, to round-off, for both forms:
//  - APIC, eq. 5: m_k v_k = sum_p m_p w_kp (v_p + B (x_k - x_p)) = m_k (a +
//    B x_k) on every node with mass, because sum_p m_p w_kp = m_k;
//  - least squares, eq. 4 (consistent mass + lambda stiffness, CHOLMOD),
//    for lambda / D = 0.25, 1, 4: the B-spline basis reproduces affine
//    functions (sum_j w_jp x_j = x_p, sum_j x_j grad w_jp^T = I), so
//    v_j = a + B x_j zeroes both residuals of eq. 2.
// Particles: a jittered block of 3 per cell and direction (2D) or 2 (3D),
// masses 0.5 .. 1.5 g, on the grid of transfer_scene.h (dx = 1/16); every
// kernel degree (1, 2, 3), 2D and 3D. Printed, relative to max |v|: the
// largest nodal error for eq. 5 (< 1e-12, measured <= 2e-15); for eq. 4
// the largest error of the interpolated particle velocity sum_k w_kp v_k
// (< 1e-12, measured <= 7e-15), the mass-weighted nodal error (< 1e-10,
// measured <= 2e-12) and the largest nodal error (< 1e-8, measured <=
// 6e-10). Nodes that particles reach only at the edge of their kernel
// support (w ~ 1e-6) make the system ill-conditioned, so the round-off in
// those nodes' velocities grows to 1e-10 in 3D; they carry as little mass
// and weight, which the mass-weighted and particle errors show.

#include <bfemp/grid/kernel_stencil.h>
#include <bfemp/integrator/macro_velocity_reconstruction.h>

#include "transfer/transfer_scene.h"

using namespace bfemp;
using namespace bfemp_tests;

namespace
{
  template <int dim>
  void
  fill_block(TransferScene<dim> &scene, const unsigned int per_cell)
  {
    const double       dx      = scene.grid.lattice().dx;
    const unsigned int n_cells = 6; // per direction, centred in the grid
    const unsigned int n       = n_cells * per_cell;
    const double       h       = dx / per_cell;
    for (unsigned int q = 0; q < std::pow(n, dim); ++q)
      {
        Point<dim>   x;
        unsigned int rest = q;
        for (unsigned int d = 0; d < dim; ++d, rest /= n)
          x[d] =
            -0.5 * n_cells * dx + (rest % n + 0.5) * h + uniform(-0.3, 0.3) * h;
        scene.insert(x, uniform(0.5e-3, 1.5e-3), Tensor<1, dim>());
      }
    scene.particles.finish_insertion();
  }

  struct Errors
  {
    /** max_k |v_k - v(x_k)| / max |v|, nodes with mass. */
    double nodal = 0.;
    /** (sum m_k |v_k - v(x_k)|^2 / sum m_k |v(x_k)|^2)^1/2. */
    double mass_weighted = 0.;
    /** max_p |sum_k w_kp v_k - v*_p| / max |v|. */
    double particle = 0.;
  };

  template <int dim>
  Errors
  relative_error(const unsigned int                                degree,
                 const TimeParameters::Substepping::Reconstruction form,
                 const double                                      weight)
  {
    TransferScene<dim> scene(degree, TransferParameters::Scheme::apic);
    fill_block(scene, dim == 2 ? 3 : 2);

    Tensor<1, dim> a = random_vector<dim>(1.);
    Tensor<2, dim> B = random_tensor<dim>(2.);
    B[0][1] += 3.; // a rotation on top of the random strain rate
    B[1][0] -= 3.;

    std::vector<SecantTarget<dim>> targets(scene.particles.n_particles());
    for (const auto &particle : scene.particles.handler())
      {
        targets[particle.get_id()].velocity =
          a + B * Tensor<1, dim>(particle.get_location());
        targets[particle.get_id()].velocity_gradient = B;
      }
    const GridState<dim> masses = scene.particles_to_grid();

    TimeParameters::Substepping parameters;
    parameters.reconstruction       = form;
    parameters.least_squares_weight = weight;
    MacroVelocityReconstruction<dim> reconstruction(scene.grid, parameters);
    std::vector<Tensor<1, dim>>      velocity;
    reconstruction.reconstruct(scene.particles, targets, masses.mass, velocity);

    Errors errors;
    double largest = 0., error2 = 0., norm2 = 0.;
    for (std::size_t k = 0; k < velocity.size(); ++k)
      if (masses.mass[k] > 0.)
        {
          const Tensor<1, dim> exact =
            a + B * Tensor<1, dim>(scene.grid.lattice().node_position(k));
          errors.nodal = std::max(errors.nodal, (velocity[k] - exact).norm());
          largest      = std::max(largest, exact.norm());
          error2 += masses.mass[k] * (velocity[k] - exact).norm_square();
          norm2 += masses.mass[k] * exact.norm_square();
        }
    errors.nodal /= largest;
    errors.mass_weighted = std::sqrt(error2 / norm2);
    // The fit of eq. 2 at the particles: sum_k w_kp v_k against v*_p.
    for (const auto &particle : scene.particles.handler())
      {
        Tensor<1, dim> v;
        dispatch_kernel_degree(degree, [&](auto p) {
          KernelStencil<dim, decltype(p)::value> stencil;
          stencil.reinit(scene.grid.lattice(), particle.get_location());
          for (unsigned int k = 0; k < stencil.n_nodes; ++k)
            v += stencil.weight[k] * velocity[stencil.node[k]];
        });
        errors.particle =
          std::max(errors.particle,
                   (v - targets[particle.get_id()].velocity).norm() / largest);
      }
    return errors;
  }

  template <int dim>
  void
  check(const unsigned int degree)
  {
    using Form        = TimeParameters::Substepping::Reconstruction;
    const Errors apic = relative_error<dim>(degree, Form::apic, 1.);
    deallog << dim << "D degree " << degree
            << " APIC (eq. 5): nodal error < 1e-12 "
            << (apic.nodal < 1e-12 ? "yes" : "NO") << std::endl;
    for (const double weight : {0.25, 1., 4.})
      {
        const Errors ls =
          relative_error<dim>(degree, Form::least_squares, weight);
        deallog << dim << "D degree " << degree
                << " least squares (eq. 4), lambda / D = " << weight
                << ": mass-weighted error < 1e-10 "
                << (ls.mass_weighted < 1e-10 ? "yes" : "NO")
                << ", particle error < 1e-12 "
                << (ls.particle < 1e-12 ? "yes" : "NO")
                << ", nodal error < 1e-8 " << (ls.nodal < 1e-8 ? "yes" : "NO")
                << std::endl;
      }
  }
} // namespace

int
main()
{
  initlog();
  for (const unsigned int degree : {1u, 2u, 3u})
    check<2>(degree);
  for (const unsigned int degree : {1u, 2u, 3u})
    check<3>(degree);
}
