// A heterogeneous body: 'material region k' subsections give regions of one
// body their own material, applied in order ('subtract' gives the body's
// material back), with the ellipse / ellipsoid / elliptic cylinder
// primitives, tilted by 'rotation angle'.
//
// 2D: a box 0.6 x 0.4 (rho 1000) with a tilted ellipse region (semi-axes
// 0.2, 0.1, rotated by 0.3 rad; rho 3000) from which a disk of radius 0.05
// is given back. 3D: a box 0.6 x 0.4 x 0.4 with an elliptic-cylinder region
// (semi-axes 0.2, 0.1, half-length 0.15; rho 3000) and an ellipsoidal void
// (semi-axes 0.05, 0.05, 0.08) cut from the body by a subtracted primitive.
// Checked on the sampled particles (regular, 2 per cell and direction):
// - the volume of each material against the analytic one, within 2 % (2D)
//   and 3 % (3D) (sampling error on curved boundaries);
// - every particle's density m/V is its material's, and the material ids
//   are the body's own (0) and its region's (1);
// - the total mass is sum rho V of the analytic volumes within the same
//   bands.

#include <bfemp/particles/particle_layout.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "tests.h"

using namespace dealii;

namespace
{
  template <int dim>
  std::string
  scene()
  {
    std::ostringstream prm;
    prm << "set dimension = " << dim
        << "\nsubsection run\n  set name = regions_" << dim
        << "d\n  set end time = 1e-5\n  set quiet = true\nend\n"
           "subsection grid\n  set upper corner = "
        << (dim == 2 ? "1, 1" : "1, 1, 1")
        << "\n  set cell size = " << (dim == 2 ? "0.02" : "0.025")
        << "\nend\n"
           "subsection body 0\n";
    if (dim == 2)
      prm << "  set number of material regions = 2\n"
             "  subsection primitive 0\n    set type = box\n"
             "    set lower corner = 0.2, 0.3\n"
             "    set upper corner = 0.8, 0.7\n  end\n"
             "  subsection material region 0\n    set type = ellipse\n"
             "    set center = 0.5, 0.5\n    set semi-axes = 0.2, 0.1\n"
             "    set rotation angle = 0.3\n"
             "    subsection material\n      set Young's modulus = 1e7\n"
             "      set density = 3000\n    end\n  end\n"
             "  subsection material region 1\n    set type = disk\n"
             "    set operation = subtract\n"
             "    set center = 0.5, 0.5\n    set outer radius = 0.05\n"
             "  end\n";
    else
      prm << "  set number of primitives = 2\n"
             "  set number of material regions = 1\n"
             "  subsection primitive 0\n    set type = box\n"
             "    set lower corner = 0.2, 0.3, 0.3\n"
             "    set upper corner = 0.8, 0.7, 0.7\n  end\n"
             "  subsection primitive 1\n    set type = ellipsoid\n"
             "    set operation = subtract\n"
             "    set center = 0.5, 0.5, 0.5\n"
             "    set semi-axes = 0.05, 0.05, 0.08\n  end\n"
             "  subsection material region 0\n"
             "    set type = elliptic cylinder\n"
             "    set center = 0.5, 0.5, 0.5\n"
             "    set semi-axes = 0.2, 0.1, 0.15\n"
             "    subsection material\n      set Young's modulus = 1e7\n"
             "      set density = 3000\n    end\n  end\n";
    prm << "  subsection material\n    set density = 1000\n  end\nend\n";
    return prm.str();
  }

  template <int dim>
  void
  check()
  {
    using Layout           = bfemp::ParticleLayout<dim>;
    const std::string name = "regions_" + std::to_string(dim) + "d";
    {
      std::ofstream prm(name + ".prm");
      prm << scene<dim>();
    }
    bfemp::SceneParameters<dim> parameters;
    parameters.read(name + ".prm");
    std::ostringstream     console;
    bfemp::Simulation<dim> simulation(parameters, name + ".prm", console);

    const double pi = numbers::PI;
    // analytic volumes of the body's own material (id 0) and the region's
    const double region =
      dim == 2 ? pi * 0.2 * 0.1 - pi * 0.05 * 0.05
               : pi * 0.2 * 0.1 * 0.3 - 4. / 3. * pi * 0.05 * 0.05 * 0.08;
    const double box = dim == 2 ? 0.6 * 0.4 : 0.6 * 0.4 * 0.4;
    const double body =
      box - (dim == 2 ? pi * 0.2 * 0.1 - pi * 0.0025 : pi * 0.2 * 0.1 * 0.3);
    const double density[] = {1000., 3000.};
    const double exact[]   = {body, region};

    std::map<unsigned int, double> volume;
    double                         mass          = 0.;
    double                         density_error = 0.;
    for (const auto &particle : simulation.particles().handler())
      {
        const auto         p = particle.get_properties();
        const unsigned int m =
          static_cast<unsigned int>(p[Layout::material_id]);
        volume[m] += p[Layout::rest_volume];
        mass += p[Layout::mass];
        density_error =
          std::max(density_error,
                   m < 2 ? std::abs(p[Layout::mass] / p[Layout::rest_volume] /
                                      density[m] -
                                    1.)
                         : 1.);
      }
    const double band = dim == 2 ? 0.02 : 0.03;
    std::string  ids;
    for (const auto &entry : volume)
      ids += (ids.empty() ? "" : ", ") + std::to_string(entry.first);
    bfemp_tests::check(volume.size() == 2 && volume.count(0) && volume.count(1),
                       std::to_string(dim) +
                         "D: material ids 0 and 1: ids found " + ids);
    for (unsigned int m = 0; m < 2; ++m)
      {
        const double error = volume[m] / exact[m] - 1.;
        char         line[160];
        std::snprintf(line,
                      sizeof(line),
                      "%dD material %u: volume %.4f (analytic %.4f, error "
                      "%+.1f %%, bound %g %%)",
                      dim,
                      m,
                      volume[m],
                      exact[m],
                      100. * error,
                      100. * band);
        bfemp_tests::check(std::abs(error) < band, line);
      }
    bfemp_tests::check_below(density_error,
                             1e-12,
                             std::to_string(dim) +
                               "D: every particle has its material's "
                               "density: largest |m/(V rho) - 1|");
    const double expected = density[0] * exact[0] + density[1] * exact[1];
    char         line[160];
    std::snprintf(line,
                  sizeof(line),
                  "%dD total mass %.2f kg (analytic %.2f kg, error "
                  "%+.1f %%, bound %g %%)",
                  dim,
                  mass,
                  expected,
                  100. * (mass / expected - 1.),
                  100. * band);
    bfemp_tests::check(std::abs(mass / expected - 1.) < band, line);
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
