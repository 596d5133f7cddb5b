#ifndef bfemp_tests_implicit_scene_h
#define bfemp_tests_implicit_scene_h

// Shared by the tests of tests/implicit/: writing a scene's prm file,
// running it as a Simulation, and reading what the tests compare
// (particles by id, FEM nodes, diagnostics.csv).

#include <bfemp/base/input_error.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "diagnostics_csv.h"
#include "tests.h"

namespace implicit_scene
{
  using namespace dealii;

  /** The common head of a scene: dimension, body counts, run, output
   *  (into results/<name>, one diagnostics row per step, no VTU). */
  inline std::string
  head(const unsigned int dim,
       const unsigned int n_bodies,
       const unsigned int n_fem_bodies,
       const std::string &name,
       const double       end_time)
  {
    std::ostringstream prm;
    prm << std::setprecision(17) << "set dimension = " << dim
        << "\nset number of bodies = " << n_bodies
        << "\nset number of FEM bodies = " << n_fem_bodies
        << "\nsubsection run\n  set name = " << name
        << "\n  set end time = " << end_time
        << "\n  set quiet = true\nend\n"
           "subsection output\n  set directory = results\n"
           "  set interval = "
        << end_time
        << "\n  set diagnostics interval = 1\n"
           "  set write particles = false\n  set write grid = false\nend\n";
    return prm.str();
  }

  /** subsection time with a fixed step. */
  inline std::string
  fixed_step(const std::string &integrator, const double dt)
  {
    std::ostringstream prm;
    prm << std::setprecision(17)
        << "subsection time\n  set integrator = " << integrator
        << "\n  set time step mode = fixed\n  set time step = " << dt
        << "\nend\n";
    return prm.str();
  }

  /** subsection solver. */
  inline std::string
  solver(const double       newton_tolerance,
         const bool         check_invariants,
         const unsigned int max_iterations = 100)
  {
    std::ostringstream prm;
    prm << std::setprecision(17)
        << "subsection solver\n  set Newton tolerance = " << newton_tolerance
        << "\n  set maximum Newton iterations = " << max_iterations
        << "\n  set check invariants = "
        << (check_invariants ? "true" : "false") << "\nend\n";
    return prm.str();
  }

  /** subsection material (inside a body). */
  inline std::string
  material(const std::string &model,
           const double       youngs,
           const double       poisson,
           const double       density)
  {
    std::ostringstream prm;
    prm << std::setprecision(17)
        << "  subsection material\n    set model = " << model
        << "\n    set Young's modulus = " << youngs
        << "\n    set Poisson's ratio = " << poisson
        << "\n    set density = " << density << "\n  end\n";
    return prm.str();
  }

  /** An MPM body made of one box. */
  inline std::string
  mpm_box(const unsigned int index,
          const std::string &lower,
          const std::string &upper,
          const std::string &velocity,
          const std::string &material_text,
          const unsigned int particles_per_cell = 2)
  {
    std::ostringstream prm;
    prm << "subsection body " << index
        << "\n  set particles per cell = " << particles_per_cell
        << "\n  set initial velocity = " << velocity
        << "\n  subsection primitive 0\n    set type = box\n"
           "    set lower corner = "
        << lower << "\n    set upper corner = " << upper << "\n  end\n"
        << material_text << "end\n";
    return prm.str();
  }

  /** Writes @p text into @p file. */
  inline void
  write(const std::string &file, const std::string &text)
  {
    std::ofstream prm(file);
    prm << text;
  }

  /** What a run left behind. */
  template <int dim>
  struct Outcome
  {
    /** Empty if the run reached its end time. */
    std::string error;
    /** Particle location by particle id. */
    std::map<types::particle_index, Point<dim>> particles;
    /** Node positions and velocities of every FEM body. */
    std::vector<std::vector<Point<dim>>>     fem_positions;
    std::vector<std::vector<Tensor<1, dim>>> fem_velocities;
    std::vector<std::vector<double>>         fem_masses;
    /** Diagnostics of the state after the run (or the failure). */
    bfemp::StepDiagnostics<dim> diagnostics;
  };

  /**
   * Reads the scene @p file, lets @p set_up change the initial state (may
   * be empty), runs it, lets @p inspect read the end state (may be empty)
   * and returns the end state. A SimulationError is
   * caught and returned as Outcome::error; anything else fails the test.
   */
  template <int dim>
  Outcome<dim>
  run(const std::string                                   &file,
      const std::function<void(bfemp::Simulation<dim> &)> &set_up  = {},
      const std::function<void(bfemp::Simulation<dim> &)> &inspect = {})
  {
    bfemp::SceneParameters<dim> parameters;
    parameters.read(file);
    std::ostringstream     console;
    bfemp::Simulation<dim> simulation(parameters, file, console);
    if (set_up)
      set_up(simulation);
    Outcome<dim> outcome;
    try
      {
        simulation.run();
      }
    catch (const bfemp::SimulationError &error)
      {
        outcome.error = error.what();
      }
    for (const auto &particle : simulation.particles().handler())
      outcome.particles[particle.get_id()] = particle.get_location();
    for (const auto &body : simulation.fem_bodies())
      {
        outcome.fem_positions.push_back(body->positions());
        outcome.fem_velocities.push_back(body->velocities());
        outcome.fem_masses.push_back(body->masses());
      }
    outcome.diagnostics = simulation.diagnostics();
    if (inspect)
      inspect(simulation);
    return outcome;
  }

  /** Largest distance between the particles of two runs' end states, each
   *  particle compared with the one of the same id. */
  template <int dim>
  double
  particle_distance(const Outcome<dim> &a, const Outcome<dim> &b)
  {
    double distance = 0.;
    for (const auto &[id, x] : a.particles)
      distance = std::max(distance, x.distance(b.particles.at(id)));
    return distance;
  }

  /** Largest distance between the FEM nodes of two runs' end states. */
  template <int dim>
  double
  fem_node_distance(const Outcome<dim> &a, const Outcome<dim> &b)
  {
    double distance = 0.;
    for (unsigned int k = 0; k < a.fem_positions.size(); ++k)
      for (unsigned int i = 0; i < a.fem_positions[k].size(); ++i)
        distance =
          std::max(distance,
                   a.fem_positions[k][i].distance(b.fem_positions[k][i]));
    return distance;
  }

  /** Columns of results/<name>/diagnostics.csv. */
  inline std::vector<std::vector<double>>
  columns(const std::string &name, const std::vector<std::string> &which)
  {
    return bfemp_tests::read_columns("results/" + name + "/diagnostics.csv",
                                     which);
  }

  inline double
  max_of(const std::vector<double> &v)
  {
    return *std::max_element(v.begin(), v.end());
  }

  inline double
  min_of(const std::vector<double> &v)
  {
    return *std::min_element(v.begin(), v.end());
  }

  /** @p value with @p digits significant digits, for deallog. */
  inline std::string
  rounded(const double value, const int digits = 3)
  {
    std::ostringstream out;
    out << std::setprecision(digits) << value;
    return out.str();
  }

  /** Least-squares slope of y(t) over t > t0. */
  inline double
  fitted_slope(const std::vector<double> &t,
               const std::vector<double> &y,
               const double               t0)
  {
    double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
    for (unsigned int i = 0; i < t.size(); ++i)
      if (t[i] > t0)
        {
          const double s = t[i] - t0;
          n += 1;
          st += s;
          sy += y[i];
          stt += s * s;
          sty += s * y[i];
        }
    return (n * sty - st * sy) / (n * stt - st * st);
  }

  /** Whether every value of @p columns is finite (no NaN, no inf). */
  inline bool
  finite(const std::vector<std::vector<double>> &columns)
  {
    for (const auto &column : columns)
      for (const double v : column)
        if (!std::isfinite(v))
          return false;
    return true;
  }
} // namespace implicit_scene

#endif
