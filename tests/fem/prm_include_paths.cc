// A relative mesh 'file' is a path next to the prm file that names it, also
// when that file is included from a wrapper in another directory (the way
// every full experiment is run with other output settings). Checked:
//  - a scene in scenes/ naming 'box.msh', included by a wrapper in the
//    working directory, opens scenes/box.msh;
//  - the wrapper overriding 'file' with a relative name opens it next to the
//    wrapper;
//  - continued lines, comments and upper-case keywords are read as deal.II
//    reads them, and entries of other subsections do not interfere;
//  - a missing file is reported with the directory it was looked for in;
//  - an include is resolved next to the including file (a scene in scenes/
//    includes its sibling common.prm; a wrapper in another directory
//    includes ../scenes/nested.prm, and the scene runs from the test's
//    directory), before the working directory;
//  - a parse error in an included file names that file and its own line.

#include <bfemp/base/input_error.h>
#include <bfemp/base/prm_entry_origins.h>
#include <bfemp/scene/scene_parameters.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_scene.h"
#include "tests.h"

namespace
{
  void
  write(const std::string &path, const std::string &text)
  {
    std::ofstream(path) << text;
  }

  std::string
  opened_mesh(const std::string &prm)
  {
    bfemp::SceneParameters<2> parameters;
    parameters.read(prm);
    return std::filesystem::path(parameters.fem_bodies[0].mesh.file)
      .lexically_normal()
      .string();
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  std::filesystem::remove_all("scenes");
  std::filesystem::create_directories("scenes");
  std::filesystem::copy_file(BFEMP_SOURCE_DIR "/tests/fem/square.msh",
                             "scenes/box.msh");
  std::filesystem::copy_file(BFEMP_SOURCE_DIR "/tests/fem/square.msh",
                             "local.msh",
                             std::filesystem::copy_options::overwrite_existing);

  // Scanned only (the material subsection has no entry 'file').
  write("scenes/scan.prm",
        "subsection fem body 0\n"
        "  subsection mesh   # the FEM body's mesh\n"
        "    set file = box.msh\n"
        "  end\n"
        "  subsection material\n"
        "    set file = x # same name, other subsection\n"
        "  end\n"
        "end\n");
  write("scan.prm",
        "include scenes/scan.prm\n"
        "subsection fem body 0\n  subsection material\n"
        "    set file = y\n  end\nend\n");

  {
    const bfemp::PrmEntryOrigins origins("scan.prm");
    bfemp_tests::check(origins.directory_of({"fem body 0", "mesh"}, "file") ==
                         "scenes",
                       "the scan finds the included file that sets it");
    bfemp_tests::check(origins.directory_of({"fem body 0", "material"},
                                            "file") == ".",
                       "entries of other subsections are kept apart");
    bfemp_tests::check(origins.directory_of({"fem body 1", "mesh"}, "file") ==
                         ".",
                       "entries never set fall back to the top file");
  }

  write("scenes/scene.prm",
        "set dimension = 2\n"
        "set number of bodies = 0\n"
        "SET number of FEM bodies = 1\n"
        "subsection time\n"
        "  set integrator = implicit backward Euler\n"
        "end\n"
        "SUBSECTION fem body 0\n"
        "  subsection mesh   # the FEM body's mesh\n"
        "    set source = file\n"
        "    set file = \\\n"
        "               box.msh\n"
        "  end\n"
        "END\n");
  write("wrapper.prm",
        "include scenes/scene.prm\n"
        "subsection run\n  set quiet = true\nend\n");
  const std::string included = opened_mesh("wrapper.prm");
  dealii::deallog << "included scene opens " << included << std::endl;
  bfemp_tests::check(included == "scenes/box.msh",
                     "a relative file in an included prm is found next to it");

  write("override.prm",
        "include scenes/scene.prm\n"
        "subsection fem body 0\n"
        "  subsection mesh\n    set file = local.msh\n  end\n"
        "end\n");
  const std::string overridden = opened_mesh("override.prm");
  dealii::deallog << "override opens " << overridden << std::endl;
  bfemp_tests::check(overridden == "local.msh",
                     "a relative file set by the wrapper is found next to it");

  // includes relative to the including file
  write("scenes/common.prm", "subsection run\n  set end time = 0.25\nend\n");
  write("scenes/nested.prm",
        "include common.prm\n"
        "include scene.prm\n");
  std::filesystem::create_directories("elsewhere");
  write("elsewhere/wrapper.prm",
        "include ../scenes/nested.prm\n"
        "subsection run\n  set quiet = true\nend\n"
        "subsection output\n  set directory = results\nend\n");
  {
    bfemp::SceneParameters<2> parameters;
    parameters.read("elsewhere/wrapper.prm");
    const std::string mesh =
      std::filesystem::path(parameters.fem_bodies[0].mesh.file)
        .lexically_normal()
        .string();
    dealii::deallog << "nested includes from elsewhere/: end time "
                    << parameters.run.end_time << ", mesh " << mesh
                    << std::endl;
    bfemp_tests::check(parameters.run.end_time == 0.25 &&
                         mesh == "scenes/box.msh",
                       "includes are resolved next to the including file");
  }
  // and the scene runs so, from a directory that is neither the scene's
  // nor the wrapper's
  bfemp_tests::run_scene<2>("elsewhere/wrapper.prm");
  const bool ran = std::filesystem::exists("results/default/fem_body_0.pvd") &&
                   std::filesystem::exists("results/default/diagnostics.csv");
  dealii::deallog << "the wrapper's run wrote results/default: "
                  << (ran ? "yes" : "no") << std::endl;
  bfemp_tests::check(ran, "the scene runs through the nested includes");

  write("scenes/bad.prm",
        "# a scene fragment with a typo\n"
        "subsection grid\n"
        "  set cel size = 0.1\n"
        "end\n");
  write("bad_wrapper.prm",
        "set dimension = 2\n"
        "include scenes/bad.prm\n");
  std::string typo;
  try
    {
      opened_mesh("bad_wrapper.prm");
    }
  catch (const bfemp::InputError &error)
    {
      typo = error.what();
    }
  dealii::deallog << "error in an included file: "
                  << typo.substr(0, typo.find(';')) << std::endl;
  bfemp_tests::check(typo.rfind("scenes/bad.prm: line 3, subsection 'grid', "
                                "entry 'cel size'",
                                0) == 0,
                     "a parse error names the included file and its line");

  std::filesystem::remove("scenes/box.msh");
  std::string message;
  try
    {
      opened_mesh("wrapper.prm");
    }
  catch (const bfemp::InputError &error)
    {
      message = error.what();
    }
  dealii::deallog << "missing file: " << message << std::endl;
  bfemp_tests::check(message.find("scenes/box.msh") != std::string::npos &&
                       message.find("'scenes'") != std::string::npos,
                     "a missing file names the path and the directory");

  dealii::deallog << "OK" << std::endl;
}
