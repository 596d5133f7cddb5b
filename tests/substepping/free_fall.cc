// Seed 003 through the whole macro step (Simulation, prm input): a
// stress-free block in uniform motion under gravity, where every transfer
// reproduces the uniform velocity field exactly, so the macro step has a
// closed form. Block 0.2 x 0.2 (x 0.2), neo-Hookean (F stays I, no
// stress), v_0 = (1, 0.5(, -0.25)) m/s, g = (0, -10(, 0)), no walls,
// dt = 1e-2 s, 10 macro steps of S = 8 substeps (delta t = dt / S).
//  - 'macro-step velocity = end of substeps' (default): after n macro
//    steps the particles have the velocity v_0 + g n dt and the position
//    of the explicit substeps, X + v_0 t + g delta t^2 nS (nS + 1) / 2
//    (the USL/USF update x += delta t v^{s+1}). Checked to 1e-12 (relative
//    to v_0 + g t and to the displacement) for USL and USF substeps with
//    APIC, PIC and FLIP transfers and the APIC, PIC and FLIP macro
//    transfers, in 2D and 3D.
//  - 'macro-step velocity = secant' (seed 003 read literally, v^{n+1} =
//    v*): every macro step adds g dt (S + 1) / (2 S) to the velocity, the
//    mean over the substeps, not g dt: checked v_0 + g n dt (S + 1) / (2 S)
//    to 1e-12, i.e. a gravity slowed by 9 / 16 at S = 8.

#include <bfemp/particles/particle_layout.h>

#include "implicit/implicit_scene.h"

using namespace dealii;

namespace
{
  constexpr double       dt       = 1e-2;
  constexpr unsigned int substeps = 8;
  constexpr unsigned int n_steps  = 10;

  template <int dim>
  std::string
  point(const double x, const double y, const double z)
  {
    std::ostringstream out;
    out << std::setprecision(17) << x << ", " << y;
    if (dim == 3)
      out << ", " << z;
    return out.str();
  }

  template <int dim>
  void
  check(const std::string &update,
        const std::string &substep_transfer,
        const std::string &macro_transfer,
        const std::string &velocity)
  {
    const std::string  name = "fall_" + std::to_string(dim) + "d";
    std::ostringstream prm;
    prm << implicit_scene::head(dim, 1, 0, name, n_steps * dt)
        << "subsection grid\n  set lower corner = " << point<dim>(-1, -1, -1)
        << "\n  set upper corner = " << point<dim>(1, 1, 1)
        << "\n  set cell size = 0.05\nend\n"
        << "subsection time\n  set integrator = substepped explicit\n"
           "  set time step mode = fixed\n  set time step = "
        << dt << "\n  subsection substepping\n    set substeps = " << substeps
        << "\n    set substep update = " << update
        << "\n    set macro-step transfer = " << macro_transfer
        << "\n    set macro-step velocity = " << velocity << "\n  end\nend\n"
        << "subsection transfer\n  set scheme = " << substep_transfer
        << "\nend\n"
        << "subsection gravity\n  set acceleration = " << point<dim>(0, -10, 0)
        << "\nend\nsubsection boundaries\n  set walls = none\nend\n"
        << implicit_scene::mpm_box(
             0,
             point<dim>(-0.1, -0.1, -0.1),
             point<dim>(0.1, 0.1, 0.1),
             point<dim>(1, 0.5, -0.25),
             implicit_scene::material("neo-Hookean", 1e5, 0.3, 1000.));
    implicit_scene::write(name + ".prm", prm.str());

    Tensor<1, dim> v0, g;
    v0[0] = 1.;
    v0[1] = 0.5;
    if (dim == 3)
      v0[2] = -0.25;
    g[1]             = -10.;
    const double   t = n_steps * dt;
    Tensor<1, dim> v_expected, displacement;
    if (velocity == "secant")
      v_expected = v0 + g * t * (substeps + 1.) / (2. * substeps);
    else
      {
        const double delta = dt / substeps;
        const double n     = n_steps * substeps;
        v_expected         = v0 + g * t;
        displacement       = v0 * t + g * delta * delta * n * (n + 1.) / 2.;
      }

    double     velocity_error = 0., position_error = 0.;
    const auto outcome = implicit_scene::run<dim>(
      name + ".prm",
      {},
      [&](bfemp::Simulation<dim> &simulation) {
        using Layout = bfemp::ParticleLayout<dim>;
        for (const auto &particle : simulation.particles().handler())
          {
            const auto p   = particle.get_properties();
            velocity_error = std::max(
              velocity_error,
              (Layout::get_vector(p, Layout::velocity) - v_expected).norm());
            const Tensor<1, dim> moved =
              particle.get_location() -
              Point<dim>(Layout::get_vector(p, Layout::initial_position));
            position_error =
              std::max(position_error, (moved - displacement).norm());
          }
      });
    bfemp_tests::check(outcome.error.empty(), "the run finishes");
    std::ostringstream line;
    line << dim << "D, " << update << " " << substep_transfer << " substeps, "
         << macro_transfer << " macro transfer, " << velocity
         << " velocity: v = "
         << (velocity == "secant" ? "v_0 + g t (S + 1) / (2 S)" : "v_0 + g t")
         << " to 1e-12 "
         << (velocity_error < 1e-12 * v_expected.norm() ? "yes" : "NO");
    if (velocity != "secant")
      line << ", x = the substeps' trajectory to 1e-12 "
           << (position_error < 1e-12 * displacement.norm() ? "yes" : "NO");
    deallog << line.str() << std::endl;
  }
} // namespace

int
main()
{
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");
  for (const std::string transfer : {"APIC", "PIC", "FLIP"})
    check<2>("USL", "APIC", transfer, "end of substeps");
  check<2>("USL", "FLIP", "as substeps", "end of substeps");
  check<2>("USF", "PIC", "as substeps", "end of substeps");
  check<2>("USL", "APIC", "as substeps", "secant");
  check<3>("USL", "APIC", "APIC", "end of substeps");
  check<3>("USF", "FLIP", "FLIP", "end of substeps");
  check<3>("USL", "APIC", "as substeps", "secant");
}
