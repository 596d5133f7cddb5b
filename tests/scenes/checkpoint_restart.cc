// Checkpoint and restart ('checkpoint' subsection, CheckpointFile): a run
// stopped at a checkpoint and continued with 'resume = true' must repeat the
// uninterrupted run bit for bit: every diagnostics.csv and bodies.csv value
// (the wall and phase times aside), every .pvd record and every VTU file
// (apart from its creation-date comment). Three scenes: particle-mesh
// contact with friction under backward Euler (the accumulated friction
// dissipation must continue, not restart at 0), the same with Newmark (its
// a^n is rebuilt from the state), and explicit USL with the grid series.
// Time steps and end times are binary fractions in the first scenes; then a
// decimal time step (2e-3), whose first part ends within round-off of its
// end time and must still take the full step. A diagnostics.csv of an older
// bfemp (without a column that this version writes) is continued with nan in
// the new column's earlier rows; one with a column this version no longer
// writes is refused. Then the refusals: no checkpoint, a checkpoint of another
// scene, a cut file, nothing left to run, and a new run that clears an old
// checkpoint.

#include <bfemp/base/input_error.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "diagnostics_csv.h"
#include "run_comparison.h"
#include "tests.h"

using namespace dealii;
using namespace run_comparison;

namespace
{
  /** What the last run() printed. */
  std::string last_console;

  /**
   * Writes @p name.prm (the scene @p scene plus @p entries) and runs it;
   * returns the InputError message, or "" if the run finished.
   */
  std::string
  run(const std::string &name,
      const std::string &scene,
      const std::string &entries)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << "include " << BFEMP_SOURCE_DIR << "/prm/" << scene << "\n"
          << "subsection run\n"
             "  set name    = "
          << name
          << "\n"
             "  set quiet   = true\n"
             "  set threads = 1\n"
             "end\n"
          << entries;
    }
    try
      {
        bfemp::SceneParameters<2> parameters;
        parameters.read(name + ".prm");
        std::ostringstream   console;
        bfemp::Simulation<2> simulation(parameters, name + ".prm", console);
        simulation.run();
        last_console = console.str();
        return "";
      }
    catch (const bfemp::InputError &error)
      {
        return error.what();
      }
  }

  /**
   * Rewrites the CSV file @p path as an older bfemp might have written it:
   * without the column @p removed (if not empty) and with an extra last
   * column @p added holding 0 (if not empty).
   */
  void
  rewrite_as_older_version(const std::string &path,
                           const std::string &removed,
                           const std::string &added)
  {
    const std::vector<std::string> lines   = lines_of(path);
    const std::vector<std::string> columns = fields_of(lines[0]);
    std::ofstream                  out(path);
    for (unsigned int l = 0; l < lines.size(); ++l)
      {
        const std::vector<std::string> fields = fields_of(lines[l]);
        std::string                    line;
        for (unsigned int c = 0; c < fields.size(); ++c)
          if (columns[c] != removed)
            line += (line.empty() ? "" : ",") + fields[c];
        if (!added.empty())
          line += "," + (l == 0 ? added : std::string("0"));
        out << line << '\n';
      }
  }

  /** The first run stops at half the end time, the second continues it. */
  void
  check_continuation(const std::string &label,
                     const std::string &scene,
                     const std::string &entries,
                     const double       end_time,
                     const double       checkpoint_interval)
  {
    deallog << "--- " << label << std::endl;
    const std::string end =
      "subsection run\n  set end time = " + std::to_string(end_time) +
      "\nend\n";
    const std::string half =
      "subsection run\n  set end time = " + std::to_string(end_time / 2) +
      "\nend\n";
    const std::string checkpoint = "subsection checkpoint\n  set interval = " +
                                   std::to_string(checkpoint_interval) +
                                   "\nend\n";
    const std::string resume = "subsection checkpoint\n  set interval = " +
                               std::to_string(checkpoint_interval) +
                               "\n  set resume = true\nend\n";
    bfemp_tests::check(run(label, scene, entries + end).empty(),
                       "the uninterrupted run finishes");
    bfemp_tests::check(
      run(label + "_parts", scene, entries + half + checkpoint).empty(),
      "the first part finishes");
    bfemp_tests::check(std::filesystem::exists("results/" + label +
                                               "_parts/checkpoint.h5"),
                       "the first part left a checkpoint");
    // The continuation runs under the same name, from its own prm file.
    std::filesystem::copy_file(
      label + "_parts.prm",
      label + "_parts_first.prm",
      std::filesystem::copy_options::overwrite_existing);
    bfemp_tests::check(
      run(label + "_parts", scene, entries + end + resume).empty(),
      "the continued run finishes");
    compare_outputs("results/" + label, "results/" + label + "_parts");
  }

  /**
   * Continues the first part of "contact_newmark" after removing the
   * column affine_kinetic_energy from its diagnostics.csv, as if an older
   * bfemp had written it: the rows must be those of the uninterrupted run,
   * with nan in that column up to the checkpoint, and the console must say
   * so. A file with a column this bfemp does not write is refused.
   */
  void
  check_older_diagnostics(const std::string &entries)
  {
    deallog << "--- diagnostics.csv of an older bfemp" << std::endl;
    const std::string name   = "older_version";
    const std::string folder = "results/" + name;
    const std::string part_1 = entries +
                               "subsection run\n  set end time = 0.0625\n"
                               "end\n"
                               "subsection checkpoint\n  set interval = "
                               "0.03125\nend\n";
    const std::string part_2 = entries +
                               "subsection run\n  set end time = 0.125\n"
                               "end\n"
                               "subsection checkpoint\n  set interval = "
                               "0.03125\n  set resume = true\nend\n";
    bfemp_tests::check(run(name, "demo_contact.prm", part_1).empty(),
                       "the first part finishes");
    const std::vector<std::string> first_part =
      lines_of(folder + "/diagnostics.csv");
    const std::string column = "affine_kinetic_energy";
    rewrite_as_older_version(folder + "/diagnostics.csv", column, "");
    bfemp_tests::check(run(name, "demo_contact.prm", part_2).empty(),
                       "the run continues a file without " + column);
    const std::size_t note = last_console.find("bfemp: diagnostics");
    deallog << last_console.substr(note, last_console.find('\n', note) - note)
            << std::endl;
    bfemp_tests::check(last_console.find("diagnostics.csv was written by an "
                                         "older bfemp") != std::string::npos &&
                         last_console.find(column) != std::string::npos,
                       "the console names the new column");

    auto       continued = csv_without_timings(folder + "/diagnostics.csv");
    const auto uninterrupted =
      csv_without_timings("results/contact_newmark/diagnostics.csv");
    const auto  header = continued[0];
    const auto  where  = std::find(header.begin(), header.end(), column);
    std::size_t n_nan  = 0;
    for (unsigned int r = 1; r < continued.size(); ++r)
      if (continued[r][where - header.begin()] == "nan")
        {
          ++n_nan;
          continued[r][where - header.begin()] =
            uninterrupted[r][where - header.begin()];
        }
    deallog << "rows " << continued.size() - 1 << ", nan in " << column << ": "
            << n_nan << std::endl;
    bfemp_tests::check(n_nan == first_part.size() - 1 &&
                         continued == uninterrupted,
                       "the continued file is the uninterrupted one with nan "
                       "in the new column before the checkpoint");

    bfemp_tests::check(run(name, "demo_contact.prm", part_1).empty(),
                       "the first part finishes again");
    rewrite_as_older_version(folder + "/diagnostics.csv", "", "retired_column");
    const std::string refused = run(name, "demo_contact.prm", part_2);
    deallog << refused << std::endl;
    bfemp_tests::check(refused.find("retired_column") != std::string::npos &&
                         refused.find(folder + "/diagnostics.csv") !=
                           std::string::npos,
                       "a file with a column this bfemp does not write is "
                       "refused, naming the column and the file");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  std::filesystem::remove_all("results");

  const std::string output        = "subsection output\n"
                                    "  set directory = results\n"
                                    "  set interval  = 0.03125\n"
                                    "end\n";
  const std::string implicit_step = "subsection time\n"
                                    "  set time step = 0.00390625\n"
                                    "end\n";
  check_continuation("contact_backward_euler",
                     "demo_contact.prm",
                     output + implicit_step,
                     0.25,
                     0.0625);
  {
    const auto columns = bfemp_tests::read_columns(
      "results/contact_backward_euler_parts/diagnostics.csv",
      {"friction_dissipation"});
    deallog << "friction dissipation at the end > 0: "
            << (columns[0].back() > 0.) << std::endl;
    bfemp_tests::check(columns[0].back() > 0.,
                       "friction dissipated energy in the contact scene");
  }
  check_continuation("contact_newmark",
                     "demo_contact.prm",
                     output + implicit_step +
                       "subsection time\n"
                       "  set integrator = implicit Newmark\n"
                       "end\n",
                     0.125,
                     0.03125);
  // A time step that is no binary fraction: after 9 steps of 2e-3 the time
  // is 0.018000000000000002, so the first part's last step to 0.02 is
  // within round-off of dt, and must take the full dt (not end - t) for the
  // continuation to repeat the uninterrupted run.
  check_continuation("decimal_time_step",
                     "demo_contact.prm",
                     output + "subsection time\n"
                              "  set time step = 2e-3\n"
                              "end\n"
                              "subsection output\n"
                              "  set interval = 0.01\n"
                              "end\n",
                     0.04,
                     0.01);
  {
    const std::size_t line = last_console.find("bfemp: finished");
    const std::string finished =
      last_console.substr(line, last_console.find(')', line) + 1 - line);
    deallog << finished << std::endl;
    bfemp_tests::check(finished ==
                         "bfemp: finished 10 steps (continued from step 10, "
                         "20 in all)",
                       "the continued run reports its own steps and the "
                       "total");
  }
  check_older_diagnostics(output + implicit_step +
                          "subsection time\n"
                          "  set integrator = implicit Newmark\n"
                          "end\n");
  check_continuation("explicit_usl",
                     "default.prm",
                     output +
                       "subsection output\n  set write grid = true\nend\n"
                       "subsection time\n"
                       "  set time step mode = fixed\n"
                       "  set time step      = 0.000244140625\n"
                       "end\n",
                     0.125,
                     0.0625);

  deallog << "--- refusals" << std::endl;
  const std::string resume = "subsection checkpoint\n"
                             "  set resume = true\n"
                             "end\n";
  const std::string no_checkpoint =
    run("fresh", "demo_contact.prm", output + resume);
  deallog << no_checkpoint << std::endl;
  bfemp_tests::check(no_checkpoint.find("there is no checkpoint") !=
                         std::string::npos &&
                       !std::filesystem::exists("results/fresh"),
                     "resume = true without a checkpoint is refused before "
                     "any output");

  // A finer grid samples more particles: another scene.
  const std::string other_scene =
    run("contact_backward_euler_parts",
        "demo_contact.prm",
        output + resume + "subsection grid\n  set cell size = 0.02\nend\n");
  deallog << other_scene << std::endl;
  bfemp_tests::check(other_scene.find("belongs to another scene") !=
                       std::string::npos,
                     "a checkpoint of another scene is refused");

  const std::string folder      = "results/contact_backward_euler_parts";
  const std::string rows_before = lines_of(folder + "/diagnostics.csv").back();
  const std::string finished =
    run("contact_backward_euler_parts",
        "demo_contact.prm",
        output + resume + "subsection run\n  set end time = 0.25\nend\n");
  bfemp_tests::check(finished.empty() &&
                       lines_of(folder + "/diagnostics.csv").back() ==
                         rows_before,
                     "a checkpoint at the end time runs nothing and keeps "
                     "the output");

  {
    std::filesystem::copy_file(
      folder + "/checkpoint.h5",
      "whole.h5",
      std::filesystem::copy_options::overwrite_existing);
    std::vector<char> bytes(std::filesystem::file_size("whole.h5") / 2);
    std::ifstream("whole.h5", std::ios::binary)
      .read(bytes.data(), bytes.size());
    std::ofstream(folder + "/checkpoint.h5", std::ios::binary)
      .write(bytes.data(), bytes.size());
  }
  const std::string cut =
    run("contact_backward_euler_parts", "demo_contact.prm", output + resume);
  deallog << cut << std::endl;
  bfemp_tests::check(cut.find(folder + "/checkpoint.h5") != std::string::npos,
                     "a cut checkpoint file is refused, naming it");

  const std::string restarted = run("contact_backward_euler_parts",
                                    "demo_contact.prm",
                                    output + "subsection run\n"
                                             "  set end time = 0.0078125\n"
                                             "end\n");
  bfemp_tests::check(restarted.empty() &&
                       !std::filesystem::exists(folder + "/checkpoint.h5") &&
                       lines_of(folder + "/diagnostics.csv").size() == 4,
                     "a new run in the folder clears the old checkpoint and "
                     "rows");
  deallog << "OK" << std::endl;
}
