// Bodies and material regions from voxel images (primitive type 'image'):
// a point belongs to the primitive if the image's voxel there holds 'image
// value' (within 1/2). The images are written here with voxels the size of
// a grid cell and centred on cells, so that each cell's 2^dim particles lie
// in one voxel and every material's sampled volume is its voxel count times
// the voxel volume, to round-off.
//
// - 2D, legacy VTK ASCII, POINT_DATA int: a 20 x 12 image of labels 0
//   (empty), 1 (matrix) and 2 (inclusions: two disks); the body is the
//   image's label 1 united with its label 2, label 2 a material region
//   (rho 3000 against 1000).
// - 3D, legacy VTK BINARY (big-endian), CELL_DATA short, 10 x 8 x 6 cells
//   (DIMENSIONS 11 9 7): the body is a box with label 0 voxels subtracted
//   (a void), label 2 again a material region.
// - 2D, raw unsigned 8-bit with 'image size', 'image origin' and 'image
//   spacing' from the prm: the same labels as the first image.
// Checked: the volume and mass of each material against the voxel counts.

#include <bfemp/particles/particle_layout.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>

#include "tests.h"

using namespace dealii;

namespace
{
  constexpr double h = 0.02; // voxel = grid cell

  /** Label of the 2D image at voxel (i, j): disks of label 2 in a label 1
   *  box, 0 around. */
  int
  label_2d(const int i, const int j)
  {
    if (i < 2 || i >= 18 || j < 2 || j >= 10)
      return 0;
    const auto in_disk = [&](const double ci, const double cj) {
      return std::pow(i - ci, 2) + std::pow(j - cj, 2) <= 4.;
    };
    return in_disk(6, 6) || in_disk(13, 5) ? 2 : 1;
  }

  /** Label of the 3D image at cell (i, j, k): a void of label 0 in the
   *  middle, a slab of label 2 at the bottom, 1 elsewhere. */
  int
  label_3d(const int i, const int j, const int k)
  {
    if (i >= 4 && i < 6 && j >= 3 && j < 5 && k >= 2 && k < 4)
      return 0;
    return j < 2 ? 2 : 1;
  }

  std::string
  head(const unsigned int dim, const std::string &name)
  {
    std::ostringstream prm;
    prm << "set dimension = " << dim
        << "\nsubsection run\n  set name = " << name
        << "\n  set end time = 1e-5\n  set quiet = true\nend\n"
           "subsection grid\n  set upper corner = "
        << (dim == 2 ? "0.6, 0.4" : "0.4, 0.4, 0.4")
        << "\n  set cell size = " << h << "\nend\n";
    return prm.str();
  }

  std::string
  region(const std::string &image_entries)
  {
    return "  set number of material regions = 1\n"
           "  subsection material region 0\n    set type = image\n" +
           image_entries +
           "    set image value = 2\n"
           "    subsection material\n      set density = 3000\n    end\n"
           "  end\n"
           "  subsection material\n    set density = 1000\n  end\nend\n";
  }

  /** Runs nothing: builds the scene and returns volume per material. */
  template <int dim>
  std::map<unsigned int, std::pair<double, double>>
  sample(const std::string &name, const std::string &text)
  {
    using Layout = bfemp::ParticleLayout<dim>;
    {
      std::ofstream prm(name + ".prm");
      prm << text;
    }
    bfemp::SceneParameters<dim> parameters;
    parameters.read(name + ".prm");
    std::ostringstream     console;
    bfemp::Simulation<dim> simulation(parameters, name + ".prm", console);
    std::map<unsigned int, std::pair<double, double>> result;
    for (const auto &particle : simulation.particles().handler())
      {
        const auto p = particle.get_properties();
        auto &entry = result[static_cast<unsigned int>(p[Layout::material_id])];
        entry.first += p[Layout::rest_volume];
        entry.second += p[Layout::mass];
      }
    return result;
  }

  void
  report(const std::string                                       &name,
         const std::map<unsigned int, std::pair<double, double>> &sampled,
         const std::map<unsigned int, double>                    &expected)
  {
    bfemp_tests::check(sampled.size() == expected.size(),
                       name + ": materials " + std::to_string(sampled.size()) +
                         " (expected " + std::to_string(expected.size()) + ")");
    const double density[] = {1000., 3000.};
    for (const auto &[m, volume] : expected)
      {
        const auto entry =
          sampled.count(m) ? sampled.at(m) : std::pair<double, double>();
        const double error =
          std::max(std::abs(entry.first / volume - 1.),
                   std::abs(entry.second / (density[m] * volume) - 1.));
        char line[200];
        std::snprintf(line,
                      sizeof(line),
                      "%s material %u: volume %.6g m^dim, mass %.6g kg (voxel "
                      "count: %.6g, %.6g); largest relative error",
                      name.c_str(),
                      m,
                      entry.first,
                      entry.second,
                      volume,
                      density[m] * volume);
        bfemp_tests::check_below(error, 1e-12, line);
      }
  }

  void
  check_2d_vtk_and_raw()
  {
    const int     nx = 20, ny = 12;
    std::ofstream vtk("labels_2d.vtk");
    std::ofstream raw("labels_2d.raw", std::ios::binary);
    vtk << "# vtk DataFile Version 3.0\nlabels\nASCII\n"
           "DATASET STRUCTURED_POINTS\nDIMENSIONS "
        << nx << ' ' << ny << " 1\nORIGIN 0.11 0.05 0\nSPACING " << h << ' '
        << h << ' ' << h << "\nPOINT_DATA " << nx * ny
        << "\nSCALARS label int 1\nLOOKUP_TABLE default\n";
    std::map<unsigned int, double> expected;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        {
          const int label = label_2d(i, j);
          vtk << label << (i + 1 == nx ? '\n' : ' ');
          raw.put(static_cast<char>(label));
          if (label > 0)
            expected[label - 1] += h * h;
        }
    vtk.close();
    raw.close();

    const std::string body =
      "subsection body 0\n  set number of primitives = 2\n"
      "  subsection primitive 0\n    set type = image\n"
      "    set image file = %FILE%\n    set image value = 1\n  end\n"
      "  subsection primitive 1\n    set type = image\n"
      "    set image file = %FILE%\n    set image value = 2\n  end\n";
    const auto with_file = [&](const std::string &file,
                               const std::string &extra) {
      std::string text = body;
      for (std::size_t at; (at = text.find("%FILE%")) != std::string::npos;)
        text.replace(at, 6, file + "\n" + extra);
      return text;
    };
    const std::string raw_entries = "    set image size = 20, 12\n"
                                    "    set image origin = 0.11, 0.05\n"
                                    "    set image spacing = 0.02, 0.02";
    report("2D VTK ASCII",
           sample<2>("image_2d_vtk",
                     head(2, "image_2d_vtk") + with_file("labels_2d.vtk", "") +
                       region("    set image file = labels_2d.vtk\n")),
           expected);
    report("2D raw",
           sample<2>("image_2d_raw",
                     head(2, "image_2d_raw") +
                       with_file("labels_2d.raw", raw_entries) +
                       region("    set image file = labels_2d.raw\n" +
                              raw_entries + "\n")),
           expected);
  }

  void
  check_3d_binary()
  {
    const int     nx = 10, ny = 8, nz = 6;
    std::ofstream vtk("labels_3d.vtk", std::ios::binary);
    vtk << "# vtk DataFile Version 3.0\nlabels\nBINARY\n"
           "DATASET STRUCTURED_POINTS\nDIMENSIONS "
        << nx + 1 << ' ' << ny + 1 << ' ' << nz + 1
        << "\nORIGIN 0.1 0.1 0.1\nSPACING " << h << ' ' << h << ' ' << h
        << "\nCELL_DATA " << nx * ny * nz
        << "\nSCALARS label short\nLOOKUP_TABLE default\n";
    std::map<unsigned int, double> expected;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          {
            const std::int16_t label = label_3d(i, j, k);
            // big-endian, as legacy VTK binary files are
            vtk.put(static_cast<char>((label >> 8) & 0xff));
            vtk.put(static_cast<char>(label & 0xff));
            if (label > 0)
              expected[label - 1] += h * h * h;
          }
    vtk.close();
    const std::string text =
      head(3, "image_3d") +
      "subsection body 0\n  set number of primitives = 2\n"
      "  subsection primitive 0\n    set type = box\n"
      "    set lower corner = 0.1, 0.1, 0.1\n"
      "    set upper corner = 0.3, 0.26, 0.22\n  end\n"
      "  subsection primitive 1\n    set type = image\n"
      "    set operation = subtract\n"
      "    set image file = labels_3d.vtk\n    set image value = 0\n  end\n" +
      region("    set image file = labels_3d.vtk\n");
    report("3D VTK binary", sample<3>("image_3d", text), expected);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  check_2d_vtk_and_raw();
  check_3d_binary();
}
