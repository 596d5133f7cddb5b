#include <bfemp/base/input_error.h>
#include <bfemp/io/output_parameters.h>

#include <filesystem>
#include <fstream>

namespace bfemp
{
  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("output");
    prm.declare_entry("directory",
                      "output",
                      Patterns::Anything(),
                      "[-] Folder that receives <run name>/ with the PVD/VTU "
                      "series and diagnostics.csv (relative to the working "
                      "directory).");
    prm.declare_entry("interval",
                      "0.01",
                      Patterns::Double(),
                      "[s] Simulated time between VTU snapshots; 0 writes "
                      "every step.");
    prm.declare_entry("write particles",
                      "true",
                      Patterns::Bool(),
                      "[-] Write the particle VTU series.");
    prm.declare_entry("write grid",
                      "false",
                      Patterns::Bool(),
                      "[-] Also write the active grid (cells touching a node "
                      "with mass) with nodal mass and velocity; with cMPM, "
                      "the active coarse elements subdivided into their "
                      "fine knot spans, with the last step's displacement "
                      "and velocity through the shape functions "
                      "(coarse_grid.pvd).");
    prm.declare_entry("diagnostics interval",
                      "1",
                      Patterns::Integer(1),
                      "[steps] Steps between rows of diagnostics.csv (and the "
                      "NaN / inversion checks, which also run at every "
                      "snapshot).");
    prm.leave_subsection();
  }



  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("output");
    directory            = prm.get("directory");
    interval             = prm.get_double("interval");
    write_particles      = prm.get_bool("write particles");
    write_grid           = prm.get_bool("write grid");
    diagnostics_interval = prm.get_integer("diagnostics interval");
    prm.leave_subsection();
    require_input(!directory.empty(),
                  "output",
                  "directory",
                  "''",
                  "must name a folder");
    require_input(interval >= 0.,
                  "output",
                  "interval",
                  to_input_string(interval),
                  "must be >= 0 [s]");
  }


  void
  OutputParameters::create_folder(const std::string &folder) const
  {
    const std::string where = "subsection 'output', entry 'directory' = '" +
                              directory + "': cannot write the folder '" +
                              folder + "'";
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
      throw InputError(where + ": " + error.message() +
                       "; allowed: a folder bfemp may create and write");
    // a probe file: permissions alone do not tell (root, read-only mounts)
    const std::string probe = folder + "/.bfemp_write_probe";
    bool              written;
    {
      std::ofstream out(probe);
      written = static_cast<bool>(out << "probe\n");
    }
    std::filesystem::remove(probe, error);
    if (!written)
      throw InputError(where +
                       ": files cannot be created in it; allowed: a folder "
                       "bfemp may create and write");
  }
} // namespace bfemp
