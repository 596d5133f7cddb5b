// doc/experiments/particle_error.py, the errors r_u and r_sigma of seed 002
// eq. (38) between two runs on the same particles, checked where the
// difference is known:
// 1. its self-test: synthetic snapshots with a known displacement offset and
//    stress factor, permuted particles and non-uniform volumes (exact to
//    1e-12), and the refusal of a run on other particles;
// 2. two bfemp runs of a linear elastic block that starts stretched,
//    u(X) = a x e_x, with a = 0.01 (the reference) and a = 0.015 (the run,
//    on a grid shifted by one particle spacing, so that its particles are
//    sampled in another order): at t = 0 the displacement of the run is 1.5
//    times the reference's at every particle, so r_u = 0.5 exactly, and the
//    stress is uniform, so r_sigma = |s(a = 0.015) / s(a = 0.01) - 1| with s
//    the von Mises stress of the material's Cauchy stress at F = I + a e_x e_x
//    (0.505, not 0.5: the Cauchy stress is P F^T / J);
// 3. the same block without stretch falling freely, the run with an extra
//    initial velocity of 0.5 m/s along x: the displacement differs by 0.5 t
//    at every particle, and the reference's is g t_n (t_n + dt) / 2 (backward
//    Euler's free fall), so r_u = t / (g t (t + dt)) = 1 / (g (t + dt)).

#include <bfemp/material/linear_elastic.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "diagnostics_csv.h"
#include "format.h"
#include "run_scene.h"
#include "tests.h"

using namespace dealii;

namespace
{
  const std::string tool = std::string("/usr/bin/python3 ") + BFEMP_SOURCE_DIR +
                           "/doc/experiments/particle_error.py";

  /** Runs the block scene with @p entries appended. */
  void
  run_block(const std::string &name, const std::string &entries)
  {
    {
      std::ofstream prm(name + ".prm");
      prm << "set dimension = 2\n"
             "subsection run\n  set name = "
          << name
          << "\n  set end time = 0.1\n  set quiet = true\nend\n"
             "subsection grid\n"
             "  set lower corner = 0, 0\n  set upper corner = 2, 2\n"
             "  set cell size = 0.05\n  set kernel = quadratic\nend\n"
             "subsection time\n  set integrator = implicit backward Euler\n"
             "  set time step mode = fixed\n  set time step = 0.02\nend\n"
             "subsection transfer\n  set scheme = PIC\nend\n"
             "subsection solver\n  set Newton tolerance = 1e-9\nend\n"
             "subsection gravity\n  set acceleration = 0, -10\nend\n"
             "subsection boundaries\n  set walls = none\nend\n"
             "subsection output\n  set directory = results\n"
             "  set interval = 0.02\nend\n"
             "subsection body 0\n"
             "  set particles per cell = 2\n"
             "  subsection primitive 0\n    set type = box\n"
             "    set lower corner = 0.5, 1.0\n"
             "    set upper corner = 1.1, 1.3\n  end\n"
             "  subsection material\n    set model = linear elastic\n"
             "    set Young's modulus = 1e5\n    set Poisson's ratio = 0.3\n"
             "    set density = 1000\n  end\nend\n"
          << entries;
    }
    bfemp_tests::run_scene<2>(name + ".prm");
  }

  /** Runs the tool on two run folders; returns its CSV's columns. */
  std::vector<std::vector<double>>
  errors(const std::string &reference, const std::string &run)
  {
    const std::string command = tool + " results/" + reference + " results/" +
                                run + " --quiet > " + run + ".log 2>&1";
    bfemp_tests::check(std::system(command.c_str()) == 0,
                       "the tool compares " + run + " with " + reference);
    return bfemp_tests::read_columns("results/" + run + "/particle_error.csv",
                                     {"time", "r_u", "r_sigma"});
  }

  const std::string shifted_grid =
    "subsection grid\n  set lower corner = 0.025, 0.025\n"
    "  set upper corner = 2.025, 2.025\nend\n";
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  using bfemp_tests::format;

  {
    const int status =
      std::system((tool + " --self-test > self_test.log 2>&1").c_str());
    std::ifstream log("self_test.log");
    for (std::string line; std::getline(log, line);)
      deallog << "self-test: " << line << std::endl;
    bfemp_tests::check(status == 0, "the tool's self-test passes");
  }

  // 2. stretched blocks at t = 0
  run_block("stretch_reference",
            "subsection body 0\n  set initial displacement = 0.01*x, 0\n"
            "end\nsubsection gravity\n  set acceleration = 0, 0\nend\n");
  run_block("stretch_run",
            shifted_grid +
              "subsection body 0\n  set initial displacement = 0.015*x, 0\n"
              "end\nsubsection gravity\n  set acceleration = 0, 0\nend\n");
  {
    const bfemp::LinearElastic<2> material(
      bfemp::ElasticModuli::from_young_poisson(1e5, 0.3));
    const auto von_mises = [&](const double a) {
      Tensor<2, 2> F = unit_symmetric_tensor<2>();
      F[0][0] += a;
      return bfemp::von_mises_stress(material.cauchy_stress(F));
    };
    const double exact = std::abs(von_mises(0.015) / von_mises(0.01) - 1.);
    const auto   c     = errors("stretch_reference", "stretch_run");
    deallog << "stretched by 1.5x at t = " << c[0][0] << ": r_u "
            << format("%.9f", c[1][0]) << " (exact 0.5), r_sigma "
            << format("%.9f", c[2][0]) << " (exact " << format("%.9f", exact)
            << ")" << std::endl;
    // the VTU files hold single-precision floats
    bfemp_tests::check(std::abs(c[1][0] - 0.5) < 1e-6 &&
                         std::abs(c[2][0] - exact) < 1e-6 * exact,
                       "r_u and r_sigma at t = 0 to 1e-6");
  }

  // 3. free fall with and without a horizontal velocity
  run_block("fall_reference", "");
  run_block("fall_run",
            shifted_grid + "subsection body 0\n"
                           "  set initial velocity = 0.5, 0\nend\n");
  {
    const auto c     = errors("fall_reference", "fall_run");
    double     worst = 0.;
    for (std::size_t i = 0; i < c[0].size(); ++i)
      {
        const double exact = 1. / (10. * (c[0][i] + 0.02));
        deallog << "free fall at t = " << format("%.2f", c[0][i]) << ": r_u "
                << format("%.7f", c[1][i]) << " (exact "
                << format("%.7f", exact) << ")" << std::endl;
        worst = std::max(worst, std::abs(c[1][i] - exact) / exact);
      }
    bfemp_tests::check(c[0].size() == 5 && worst < 1e-6,
                       "r_u = 1 / (g (t + dt)) at t = 0.02 ... 0.1 to 1e-6");
  }
}
