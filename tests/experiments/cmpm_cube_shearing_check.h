#ifndef bfemp_tests_experiments_cmpm_cube_shearing_check_h
#define bfemp_tests_experiments_cmpm_cube_shearing_check_h

// Seed 002 Section 8.1.1 (the sheared cube: the C1 continuity of cMPM
// against linear-kernel MPM), the runs and checks shared by the reduced
// test (tests/experiments/cmpm_cube_shearing, 2D) and the full one
// (tests/validation/cmpm_cube_shearing_full, 3D):
// prm/cmpm/cube_shearing_<dim>d{,_bsmpm,_linear}.prm on the same particles.
// doc/experiments/cmpm_stress_line.py takes the von Mises stress along the
// row of particles at mid-height and its roughness R (RMS second difference
// over the mean). Checked, as the seed's Fig. 19 shows: once particles have
// crossed cells (t = 0.15 and 0.21 s) the linear kernel's stress oscillates
// (R above 0.05) while BSMPM and cMPM stay smooth (R below 0.025).

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "../format.h"
#include "../run_scene.h"
#include "../tests.h"

namespace cmpm_cube_shearing_check
{
  template <int dim>
  void
  check()
  {
    using bfemp_tests::format;

    const std::string prefix = std::string(BFEMP_SOURCE_DIR) +
                               "/prm/cmpm/cube_shearing_" +
                               std::to_string(dim) + "d";
    std::string folders;
    for (const std::string variant : {"", "_bsmpm", "_linear"})
      {
        const std::string name = "cube" + (variant.empty() ? "_cmpm" : variant);
        std::ofstream(name + ".prm")
          << "include " << prefix << variant << ".prm\n"
          << "subsection run\n  set name = " << name
          << "\n  set quiet = true\nend\n"
          << "subsection output\n  set directory = results\nend\n";
        bfemp_tests::run_scene<dim>(name + ".prm");
        folders += " results/" + name;
      }
    const std::string command = std::string("/usr/bin/python3 ") +
                                BFEMP_SOURCE_DIR +
                                "/doc/experiments/cmpm_stress_line.py" +
                                folders + " > roughness.log 2>&1";
    bfemp_tests::check(std::system(command.c_str()) == 0,
                       "cmpm_stress_line.py reads the three runs");

    // roughness[run][time]
    std::map<std::string, std::map<double, double>> roughness;
    std::ifstream                                   log("roughness.log");
    for (std::string line; std::getline(log, line);)
      {
        std::istringstream words(line);
        std::string        run;
        double             time = 0., value = 0.;
        if (words >> run >> time >> value)
          roughness[run][time] = value;
      }
    for (const auto &[run, values] : roughness)
      for (const auto &[time, value] : values)
        dealii::deallog << run << " t = " << format("%.2f", time)
                        << ": roughness " << format("%.4f", value) << std::endl;
    bfemp_tests::check(roughness.size() == 3 &&
                         roughness["cube_linear"].size() == 3,
                       "three runs at three times");
    for (const double time : {0.15, 0.21})
      {
        const std::string at = " at t = " + format("%.2f", time);
        bfemp_tests::check(roughness["cube_linear"][time] > 0.05,
                           "the linear kernel's stress oscillates" + at);
        bfemp_tests::check(roughness["cube_bsmpm"][time] < 0.025 &&
                             roughness["cube_cmpm"][time] < 0.025,
                           "BSMPM's and cMPM's stresses are smooth" + at);
      }
  }
} // namespace cmpm_cube_shearing_check

#endif
