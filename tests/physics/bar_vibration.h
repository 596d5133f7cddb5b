// Shared by bar_vibration_2d.cc and bar_vibration_3d.cc: the first axial
// mode of a free-free elastic bar.
//
// A linear elastic bar with nu = 0 (so lambda = 0 and the bar wave speed
// c = sqrt(E / rho) holds exactly, whatever the thickness), length L along
// x, one grid cell thick, no gravity, no walls. The initial velocity
// v_x = v0 cos(pi X / L) (X measured from the left end) is the first
// free-free mode; its period is T = 2 L / c. With nu = 0 and a velocity
// that depends on x only, the discrete MPM problem is one-dimensional, so
// the thickness does not enter.
//
// For a single mode E_kin = E cos^2(2 pi t / T) and E_el = E sin^2(...), so
// s(t) = E_kin - E_el = E cos(4 pi t / T) crosses zero every T / 4. The
// crossings (cubic interpolation of diagnostics.csv, one row per step) are
// fitted by a straight line; four times its slope is the measured period.
// A constant phase offset (e.g. the half step between the velocity and the
// deformation gradient of the explicit update) drops out of the slope.

#include <bfemp/scene/scene_parameters.h>
#include <bfemp/scene/simulation.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "diagnostics_csv.h"
#include "tests.h"

namespace bar_vibration
{
  using namespace dealii;

  constexpr double length       = 1.;
  constexpr double youngs       = 1e6;
  constexpr double density      = 1000.;
  constexpr double cfl_number   = 0.5;
  constexpr double margin_cells = 2.;  // grid cells between bar and grid edge
  constexpr double n_periods    = 2.3; // simulated time in periods

  inline double
  wave_speed()
  {
    return std::sqrt(youngs / density);
  }

  inline double
  exact_period()
  {
    return 2. * length / wave_speed();
  }

  /** "a, b(, c)" for a prm entry. */
  template <int dim>
  std::string
  prm_point(const double along, const double across)
  {
    std::ostringstream out;
    out << std::setprecision(17) << along;
    for (unsigned int d = 1; d < dim; ++d)
      out << ", " << across;
    return out.str();
  }

  using bfemp_tests::read_columns;

  /** Root of the cubic through (t[k], s[k]), k = i-1 .. i+2, bracketed by
   *  t[i], t[i+1] (Newton iterations from the linear estimate). */
  inline double
  cubic_root(const std::vector<double> &t,
             const std::vector<double> &s,
             const std::size_t          i)
  {
    const std::size_t first = (i == 0 ? 0 : i - 1);
    const std::size_t last  = std::min(first + 3, t.size() - 1);
    const auto        p     = [&](const double x, double &derivative) {
      double value = 0.;
      derivative   = 0.;
      for (std::size_t a = first; a <= last; ++a)
        {
          double l = 1., dl = 0.;
          for (std::size_t b = first; b <= last; ++b)
            if (b != a)
              {
                const double factor = (x - t[b]) / (t[a] - t[b]);
                dl                  = dl * factor + l / (t[a] - t[b]);
                l *= factor;
              }
          value += s[a] * l;
          derivative += s[a] * dl;
        }
      return value;
    };
    double x = t[i] - s[i] * (t[i + 1] - t[i]) / (s[i + 1] - s[i]);
    for (unsigned int iteration = 0; iteration < 20; ++iteration)
      {
        double       derivative;
        const double value = p(x, derivative);
        x -= value / derivative;
      }
    return x;
  }

  /**
   * The period of a single mode from its energy histories, and the number
   * of zero crossings of E_kin - E_el it used: the crossings (cubic
   * interpolation) lie T / 4 apart, so a least-squares line through
   * (j, crossing j) has the slope T / 4.
   */
  inline std::pair<double, unsigned int>
  measured_period(const std::vector<double> &t,
                  const std::vector<double> &kinetic,
                  const std::vector<double> &elastic)
  {
    std::vector<double> s(t.size());
    for (std::size_t i = 0; i < t.size(); ++i)
      s[i] = kinetic[i] - elastic[i];

    std::vector<double> crossings;
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      if ((s[i] > 0.) != (s[i + 1] > 0.))
        crossings.push_back(cubic_root(t, s, i));

    const double n  = crossings.size();
    double       sj = 0., st = 0., sjj = 0., sjt = 0.;
    for (unsigned int j = 0; j < crossings.size(); ++j)
      {
        sj += j;
        st += crossings[j];
        sjj += double(j) * j;
        sjt += j * crossings[j];
      }
    const double slope = (n * sjt - sj * st) / (n * sjj - sj * sj);
    return {4. * slope, static_cast<unsigned int>(crossings.size())};
  }

  struct Result
  {
    unsigned int n_cells;
    unsigned int n_particles;
    unsigned int n_steps;
    unsigned int n_crossings;
    double       period;
    double       error;
  };

  /** Runs the bar with @p n_cells cells along its length. */
  template <int dim>
  Result
  run(const unsigned int n_cells, const double amplitude = 1e-3)
  {
    const double dx   = length / n_cells;
    const double low  = margin_cells * dx; // bar: [low, low + L] along x
    const double side = (2. * margin_cells + 1.) * dx; // grid extent across
    const std::string name =
      "bar_" + std::to_string(dim) + "d_" + std::to_string(n_cells);
    const std::string file = name + ".prm";
    {
      std::ofstream prm(file);
      prm << std::setprecision(17) << "set dimension = " << dim
          << "\nset number of bodies = 1\n"
          << "subsection run\n  set name = " << name
          << "\n  set end time = " << n_periods * exact_period()
          << "\n  set quiet = true\nend\n"
          << "subsection grid\n  set lower corner = " << prm_point<dim>(0., 0.)
          << "\n  set upper corner = "
          << prm_point<dim>(length + 2. * low, side)
          << "\n  set cell size = " << dx << "\n  set kernel = quadratic\nend\n"
          << "subsection time\n  set integrator = explicit USL\n"
             "  set time step mode = CFL\n  set CFL number = "
          << cfl_number << "\nend\n"
          << "subsection transfer\n  set scheme = APIC\nend\n"
          << "subsection gravity\n  set acceleration = "
          << prm_point<dim>(0., 0.) << "\nend\n"
          << "subsection boundaries\n  set walls = none\nend\n"
          << "subsection output\n  set directory = results"
             "\n  set interval = "
          << n_periods * exact_period()
          << "\n  set diagnostics interval = 1"
             "\n  set write particles = false\nend\n"
          << "subsection body 0\n  set particles per cell = 2\n"
             "  subsection primitive 0\n    set type = box\n"
             "    set lower corner = "
          << prm_point<dim>(low, low) << "\n    set upper corner = "
          << prm_point<dim>(low + length, low + dx) << "\n  end\n"
          << "  subsection material\n    set model = linear elastic\n"
             "    set Young's modulus = "
          << youngs
          << "\n    set Poisson's ratio = 0\n    set density = " << density
          << "\n  end\nend\n";
    }

    bfemp::SceneParameters<dim> parameters;
    parameters.read(file);
    std::ostringstream     console;
    bfemp::Simulation<dim> simulation(parameters, file, console);

    // v_x = v0 cos(pi X / L) and, for APIC, its gradient as the affine
    // velocity C_p (the exact local velocity field).
    using Layout    = bfemp::ParticleLayout<dim>;
    const double v0 = amplitude * wave_speed();
    const double k  = numbers::PI / length;
    for (auto &particle : simulation.particles().handler())
      {
        const ArrayView<double> p  = particle.get_properties();
        const double            X  = particle.get_location()[0] - low;
        p[Layout::velocity]        = v0 * std::cos(k * X);
        p[Layout::affine_velocity] = -v0 * k * std::sin(k * X); // C_xx
      }
    simulation.run();

    const auto columns =
      read_columns("results/" + name + "/diagnostics.csv",
                   {"time", "kinetic_energy", "elastic_energy"});
    const auto [period, n_crossings] =
      measured_period(columns[0], columns[1], columns[2]);

    Result result;
    result.n_cells     = n_cells;
    result.n_particles = simulation.particles().n_particles();
    result.n_steps     = columns[0].size() - 1;
    result.n_crossings = n_crossings;
    result.period      = period;
    result.error       = (result.period - exact_period()) / exact_period();
    return result;
  }

  /** Runs the resolutions, prints the errors and orders, and checks them. */
  template <int dim>
  void
  convergence_study(const std::vector<unsigned int> &resolutions)
  {
    std::filesystem::remove_all("results");
    deallog << dim << "D free-free bar, L = " << length
            << ", c = sqrt(E / rho) = " << wave_speed()
            << ", exact period T = 2 L / c = " << exact_period() << std::endl;

    std::vector<Result> results;
    for (const unsigned int n : resolutions)
      {
        const Result r = run<dim>(n);
        results.push_back(r);
        std::ostringstream line;
        line << "cells along L " << r.n_cells << ", particles " << r.n_particles
             << ", zero crossings " << r.n_crossings << ", period "
             << std::setprecision(6) << r.period << ", relative error "
             << std::setprecision(3) << r.error;
        deallog << line.str() << std::endl;
        // 2.3 periods: s = E_kin - E_el crosses zero 9 times.
        bfemp_tests::check(r.n_crossings == 9,
                           "the energy exchange has 9 zero crossings");
      }

    for (unsigned int i = 1; i < results.size(); ++i)
      {
        const double ratio =
          std::abs(results[i - 1].error) / std::abs(results[i].error);
        const double       order = std::log2(ratio);
        std::ostringstream line;
        line << "cells " << results[i - 1].n_cells << " -> "
             << results[i].n_cells << ": observed order " << std::fixed
             << std::setprecision(1) << order;
        deallog << line.str() << std::endl;
        bfemp_tests::check(std::abs(results[i].error) <
                             std::abs(results[i - 1].error),
                           "the period error decreases under refinement");
        bfemp_tests::check(order > 1.5,
                           "the period converges at (at least) second order");
      }
    // Theory for the leading error with k = pi / L: quadratic B-splines
    // with a lumped mass lengthen the period by (k dx)^2 / 8, the central
    // difference in time shortens it by (k c dt)^2 / 24, i.e. +0.115 (k dx)^2
    // in all at CFL 0.5.
    bfemp_tests::check(results.back().error > 0. && results.back().error < 2e-3,
                       "the finest period is longer than 2 L / c, by < 0.2 %");
  }
} // namespace bar_vibration
