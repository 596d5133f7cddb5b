// Two neo-Hookean blocks, offset sideways, move toward each other and
// collide through the grid, without gravity or walls, for 100 explicit steps
// (ExplicitMPM). The internal forces sum to zero and exert no net torque
// (symmetric Kirchhoff stress), so the total linear momentum is conserved to
// round-off by every scheme and, with APIC and the quadratic kernel, so is
// the angular momentum (StepDiagnostics' measure, with the affine part).
// PIC and FLIP, which do not conserve it, report its change.

#include <bfemp/boundary/grid_boundaries.h>
#include <bfemp/integrator/explicit_mpm.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "tests.h"
#include "transfer_scene.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  template <int dim>
  void
  test(const TransferParameters::Scheme scheme,
       const TimeParameters::Integrator variant)
  {
    using Layout = ParticleLayout<dim>;

    // A grid of [-1, 1]^dim, large enough for the blocks' whole path.
    GridParameters<dim> grid_parameters = bfemp_tests::grid_parameters<dim>(2);
    for (unsigned int d = 0; d < dim; ++d)
      {
        grid_parameters.lower_corner[d] = -1.;
        grid_parameters.upper_corner[d] = 1.;
      }
    const BackgroundGrid<dim>       grid(grid_parameters);
    ParticleSystem<dim>             particles(grid);
    const auto                      materials = bfemp_tests::neo_hookean<dim>();
    const ParticleGridTransfer<dim> transfer(grid,
                                             bfemp_tests::transfer_parameters(
                                               scheme),
                                             materials);

    ParameterHandler prm;
    GridBoundaries<dim>::declare_parameters(prm, 0);
    prm.enter_subsection("boundaries");
    prm.set("walls", "none");
    prm.leave_subsection();
    GridBoundaries<dim> boundaries;
    boundaries.parse_parameters(prm);

    // Blocks of 3 cells per side, 2 particles per cell and direction,
    // density 1000; block 1 is shifted by one cell in the other directions.
    const double dx = grid_parameters.cell_size, spacing = dx / 2.;
    for (unsigned int block = 0; block < 2; ++block)
      {
        Tensor<1, dim> v;
        v[0] = block == 0 ? 0.6 : -0.4;
        v[1] = block == 0 ? 0.3 : -0.2;
        std::array<unsigned int, dim> n;
        n.fill(6);
        const unsigned int n_total = dim == 2 ? 36 : 216;
        for (unsigned int q = 0; q < n_total; ++q)
          {
            Point<dim>   x;
            unsigned int rest = q;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double first = d == 0 ? (block == 0 ? -4. * dx : dx)
                                            : (block == 0 ? -2. * dx : -dx);
                x[d]               = first + (rest % n[d] + 0.5) * spacing;
                rest /= n[d];
              }
            std::vector<double> properties(Layout::n_properties, 0.);
            const auto          p  = make_array_view(properties);
            const double        V  = std::pow(spacing, dim);
            p[Layout::mass]        = 1000. * V;
            p[Layout::rest_volume] = V;
            p[Layout::body_id]     = block;
            Layout::set_vector(p, Layout::velocity, v);
            Layout::set_tensor(p,
                               Layout::deformation_gradient,
                               unit_symmetric_tensor<dim>());
            Layout::set_vector(p, Layout::initial_position, x);
            particles.insert(x, make_array_view(std::as_const(properties)));
          }
      }
    particles.finish_insertion();

    const auto measure = [&]() {
      return StepDiagnostics<dim>::measure(particles,
                                           materials,
                                           transfer,
                                           Tensor<1, dim>());
    };
    const StepDiagnostics<dim> start = measure();
    const double               lever =
      particles.template sum<double>([](const auto &particle) {
        const auto p = particle.get_properties();
        return p[Layout::mass] * particle.get_location().norm() *
               Layout::get_vector(p, Layout::velocity).norm();
      });

    ExplicitMPM<dim> integrator(grid,
                                particles,
                                transfer,
                                boundaries,
                                Tensor<1, dim>(),
                                variant);
    const double     c            = materials[0]->p_wave_speed(1000.);
    const double     dt           = 0.4 * dx / (c + 1.);
    double           max_momentum = 0., max_angular = 0., max_elastic = 0.;
    bool             finite = true;
    for (unsigned int n = 0; n < 100; ++n)
      {
        integrator.step({dt, n * dt});
        const StepDiagnostics<dim> now = measure();
        max_momentum =
          std::max(max_momentum,
                   (now.linear_momentum - start.linear_momentum).norm());
        max_angular =
          std::max(max_angular,
                   (now.angular_momentum - start.angular_momentum).norm());
        max_elastic = std::max(max_elastic, now.elastic_energy);
        finite      = finite && now.finite;
      }

    const std::string name =
      std::to_string(dim) + "D " + bfemp_tests::scheme_name(scheme) +
      (variant == TimeParameters::Integrator::explicit_usl ? " USL" : " USF") +
      ": ";
    bfemp_tests::check(finite && max_elastic > 1e-2 * start.kinetic_energy,
                       name + "the blocks collide (elastic energy builds up)");
    bfemp_tests::check(max_momentum < 1e-11 * start.mass * start.max_speed,
                       name + "linear momentum conserved");
    if (scheme == TransferParameters::Scheme::apic)
      bfemp_tests::check(start.angular_momentum.norm() > 0.01 * lever &&
                           max_angular < 1e-11 * lever,
                         name + "angular momentum conserved");
    else
      dealii::deallog << name << "angular momentum changes by up to "
                      << bfemp_tests::two_decimals(
                           max_angular / start.angular_momentum.norm())
                      << " (relative, not conserved)" << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  using Scheme     = TransferParameters::Scheme;
  using Integrator = TimeParameters::Integrator;
  test<2>(Scheme::apic, Integrator::explicit_usl);
  test<2>(Scheme::apic, Integrator::explicit_usf);
  test<2>(Scheme::pic, Integrator::explicit_usl);
  test<2>(Scheme::flip, Integrator::explicit_usl);
  test<3>(Scheme::apic, Integrator::explicit_usl);
}
