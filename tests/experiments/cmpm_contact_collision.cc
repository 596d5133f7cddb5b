// Beyond seed 002 (its Section 9 leaves frictional contact open): a
// heterogeneous cMPM block (soft inclusions of E 1e3 in E 1e5) thrown
// obliquely at a free FEM block in zero gravity, with BFEMP's barrier
// frictional contact (mu 0.3), in 2D and 3D
// (prm/cmpm/contact_collision_{2d,3d}.prm; backward Euler, dt 4e-3 s,
// 0.2 s in 2D and 0.12 s in 3D). Nothing external acts. Checked at every
// step, as the BFEMP tests do:
// - no particle inside the FEM block, the smallest distance positive;
// - the total linear momentum of both bodies stays at its initial value to
//   1e-6 (the lumped 1e-8 floor of cMPM's inertia, doc/cmpm.md, moves it by
//   about 1e-8 of a step's momentum per step);
// - the total energy never rises above its initial value (backward Euler
//   and friction dissipate; the barrier's energy, not in the column, only
//   lowers it);
// - det F > 0 at every particle and FEM element;
// - the block hits the FEM block (more than 5 particles in contact) and
//   hands it momentum (its centre-of-mass velocity along x ends above 0.3
//   of the block's initial velocity times the mass ratio).
// About 35 s.

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "../diagnostics_csv.h"
#include "../format.h"
#include "../run_scene.h"
#include "../tests.h"

using namespace dealii;

namespace
{
  template <int dim>
  void
  check()
  {
    using bfemp_tests::format;
    const std::string name = "collision_" + std::to_string(dim) + "d";
    std::ofstream(name + ".prm")
      << "include " << BFEMP_SOURCE_DIR << "/prm/cmpm/contact_collision_" << dim
      << "d.prm\nsubsection run\n  set name = " << name
      << "\n  set quiet = true\nend\n"
      << "subsection output\n  set directory = results\n"
         "  set write particles = false\nend\n";
    bfemp_tests::run_scene<dim>(name + ".prm");

    std::vector<std::string> columns = {"total_energy",
                                        "particles_in_fem",
                                        "min_distance",
                                        "min_J",
                                        "contact_particles"};
    const std::string axes[3] = {"momentum_x", "momentum_y", "momentum_z"};
    for (unsigned int d = 0; d < dim; ++d)
      columns.push_back(axes[d]);
    const auto c =
      bfemp_tests::read_columns("results/" + name + "/diagnostics.csv",
                                columns);
    const std::size_t rows = c[0].size();

    double inside = 0., closest = 1e300, min_J = 1e300, in_contact = 0.;
    double energy_rise = -1e300, momentum_change = 0., p0 = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      p0 += c[5 + d][0] * c[5 + d][0];
    p0 = std::sqrt(p0);
    for (std::size_t i = 0; i < rows; ++i)
      {
        inside     = std::max(inside, c[1][i]);
        closest    = std::min(closest, c[2][i]);
        min_J      = std::min(min_J, c[3][i]);
        in_contact = std::max(in_contact, c[4][i]);
        energy_rise =
          std::max(energy_rise, (c[0][i] - c[0][0]) / std::abs(c[0][0]));
        double dp = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          dp += std::pow(c[5 + d][i] - c[5 + d][0], 2);
        momentum_change = std::max(momentum_change, std::sqrt(dp) / p0);
      }
    const auto b = bfemp_tests::read_columns(
      "results/" + name + "/bodies.csv",
      {"mpm0_mass", "mpm0_com_velocity_x", "fem0_mass", "fem0_com_velocity_x"});
    const double handed =
      b[3].back() / (b[1][0] * b[0][0] / (b[0][0] + b[2][0]));

    deallog << dim << "D: " << rows - 1 << " steps, particles inside "
            << format("%.0f", inside) << ", smallest distance "
            << format("%.2f", closest / 2e-3) << " dhat, smallest det F "
            << format("%.2f", min_J) << ", largest contact set "
            << format("%.0f", in_contact) << std::endl;
    deallog << dim << "D: energy at the end / initial "
            << format("%.3f", c[0].back() / c[0][0])
            << ", FEM block's velocity / shared velocity "
            << format("%.2f", handed) << std::endl;
    std::cout << dim << "D: largest relative momentum change "
              << momentum_change << ", largest energy rise " << energy_rise
              << std::endl;
    bfemp_tests::check(inside == 0. && closest > 0.,
                       "no particle inside the FEM block, distance positive");
    bfemp_tests::check(in_contact > 5., "the block hits the FEM block");
    bfemp_tests::check(momentum_change < 1e-6,
                       "total momentum kept to 1e-6 at every step");
    bfemp_tests::check(energy_rise <= 1e-9,
                       "total energy never above its initial value");
    bfemp_tests::check(min_J > 0., "det F > 0 everywhere");
    bfemp_tests::check(handed > 0.3, "the FEM block takes momentum");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  check<2>();
  check<3>();
}
