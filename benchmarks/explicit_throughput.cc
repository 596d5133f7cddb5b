// Explicit-step throughput of bfemp in particle-steps per second, compared
// with a hand-written fixed-grid loop of the same algorithm.
//
//   cmake --build build --target explicit_throughput
//   build/benchmarks/explicit_throughput            # full run, a few minutes
//   build/benchmarks/explicit_throughput --quick    # smoke run, seconds
//
// Options:
//   --quick            2D 25,600 and 3D 32,768 particles, short blocks
//   --output FILE      default benchmarks/results/explicit_throughput.json
//                      (explicit_throughput_quick.json with --quick) in the
//                      source tree
//   --repeats N        timed blocks per configuration, best is reported (3)
//   --seconds S        target wall time of one 1-thread bfemp block (2.5;
//                      0.25 with --quick); at least 15 steps per block
//   --case I           run only case I (0-3, or 0-1 with --quick)
//   --profile-steps N  run N bfemp steps on 1 thread after the warm-up and
//                      stop (no loop, no JSON): for perf record / callgrind
//
// Each case is one neo-Hookean block (APIC, quadratic B-splines, explicit
// USL, 2 particles per cell and direction) filling most of a grid with
// walls, started with a Taylor-Green vortex velocity field, so that it
// shears and particles keep crossing cells. bfemp's scene is built from a prm
// text read by SceneParameters<dim>::read, assembled like Simulation does,
// and only ExplicitMPM::step(dt, t) is timed, at a fixed stable dt (no
// output, no diagnostics, no time-step control). The hand-written loop runs
// the same algorithm on the same particles, grid and dt with plain arrays,
// single-threaded; after the warm-up both states are compared particle by
// particle to show that it is the same algorithm. See doc/performance.md.

#include <bfemp/grid/background_grid.h>
#include <bfemp/integrator/explicit_mpm.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/body_sampler.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "machine_info.h"

#ifndef BFEMP_SOURCE_DIR
#  define BFEMP_SOURCE_DIR "."
#endif

namespace
{
  using namespace dealii;
  using Clock = std::chrono::steady_clock;
  using namespace machine_info;

  // ------------------------------------------------------------------------
  // Scene constants, shared by bfemp and the hand-written loop.

  constexpr unsigned int particles_per_direction = 2;
  constexpr unsigned int wall_layers             = 2; // prm default
  constexpr double       cell_size               = 0.01;
  constexpr double       youngs_modulus          = 1e6;
  constexpr double       poisson_ratio           = 0.3;
  constexpr double       density                 = 1000.;
  // Peak speed of the initial vortex as a fraction of the P-wave speed.
  constexpr double vortex_mach = 0.1;
  // dt = cfl_number dx / (c_p + peak speed).
  constexpr double       cfl_number          = 0.4;
  constexpr double       pi                  = 3.14159265358979323846;
  constexpr unsigned int min_steps_per_block = 15;

  struct CaseSpec
  {
    unsigned int dim;
    unsigned int block_cells; // per direction
    unsigned int margin;      // cells between block and grid boundary
  };

  struct Options
  {
    bool         quick   = false;
    unsigned int repeats = 3;
    double       seconds = 2.5; // target length of one 1-thread timed block
    std::string  output;
    int          only_case = -1; // --case I: run only case I (for profiling)
    // --profile-steps N: after set-up and warm-up run N bfemp steps on one
    // thread and stop (no loop, no JSON), for perf / callgrind.
    unsigned int profile_steps = 0;
  };

  // ------------------------------------------------------------------------
  // Initial velocity: a Taylor-Green vortex on the block [lo, lo + L]^dim.
  // Divergence free, tangential on the block's faces, so the block shears
  // in place instead of flying into a wall.

  template <int dim>
  struct Vortex
  {
    double lo, length, amplitude;

    Tensor<1, dim>
    velocity(const Point<dim> &x) const
    {
      double s[dim], c[dim];
      for (unsigned int d = 0; d < dim; ++d)
        {
          s[d] = std::sin(pi * (x[d] - lo) / length);
          c[d] = std::cos(pi * (x[d] - lo) / length);
        }
      const double   z = dim == 3 ? c[dim - 1] : 1.;
      Tensor<1, dim> v;
      v[0] = amplitude * s[0] * c[1] * z;
      v[1] = -amplitude * c[0] * s[1] * z;
      return v;
    }

    /** grad v (the APIC affine velocity C of a smooth field). */
    Tensor<2, dim>
    gradient(const Point<dim> &x) const
    {
      double s[dim], c[dim];
      for (unsigned int d = 0; d < dim; ++d)
        {
          s[d] = std::sin(pi * (x[d] - lo) / length);
          c[d] = std::cos(pi * (x[d] - lo) / length);
        }
      const double   k  = amplitude * pi / length;
      const double   z  = dim == 3 ? c[dim - 1] : 1.;
      const double   dz = dim == 3 ? -s[dim - 1] : 0.;
      Tensor<2, dim> G;
      G[0][0] = k * c[0] * c[1] * z;
      G[0][1] = -k * s[0] * s[1] * z;
      G[1][0] = k * s[0] * s[1] * z;
      G[1][1] = -k * c[0] * c[1] * z;
      if (dim == 3)
        {
          G[0][dim - 1] = k * s[0] * c[1] * dz;
          G[1][dim - 1] = -k * c[0] * s[1] * dz;
        }
      return G;
    }
  };

  // ------------------------------------------------------------------------
  // bfemp: the scene as a prm text, and the pieces Simulation builds.

  template <int dim>
  std::string
  scene_prm(const CaseSpec &spec)
  {
    const unsigned int n_grid = spec.block_cells + 2 * spec.margin;
    auto               point  = [](const double value) {
      std::ostringstream s;
      s << std::setprecision(17);
      for (unsigned int d = 0; d < dim; ++d)
        s << (d ? ", " : "") << value;
      return s.str();
    };
    std::ostringstream prm;
    prm << std::setprecision(17);
    prm << "set dimension = " << dim << "\n"
        << "set number of bodies = 1\n"
        << "subsection run\n  set name = explicit_throughput\n"
        << "  set end time = 1\n  set quiet = true\nend\n"
        << "subsection grid\n"
        << "  set lower corner = " << point(0.) << "\n"
        << "  set upper corner = " << point(n_grid * cell_size) << "\n"
        << "  set cell size = " << cell_size << "\n"
        << "  set kernel = quadratic\nend\n"
        << "subsection time\n  set integrator = explicit USL\nend\n"
        << "subsection transfer\n  set scheme = APIC\nend\n"
        << "subsection gravity\n  set acceleration = " << point(0.) << "\nend\n"
        << "subsection boundaries\n  set walls = all\n"
        << "  set wall condition = separable slip\n"
        << "  set wall layers = " << wall_layers << "\nend\n"
        << "subsection body 0\n"
        << "  set particles per cell = " << particles_per_direction << "\n"
        << "  set sampling = jittered\n"
        << "  subsection primitive 0\n    set type = box\n"
        << "    set lower corner = " << point(spec.margin * cell_size) << "\n"
        << "    set upper corner = "
        << point((spec.margin + spec.block_cells) * cell_size) << "\n"
        << "  end\n"
        << "  subsection material\n    set model = neo-Hookean\n"
        << "    set Young's modulus = " << youngs_modulus << "\n"
        << "    set Poisson's ratio = " << poisson_ratio << "\n"
        << "    set density = " << density << "\n  end\nend\n";
    return prm.str();
  }

  template <int dim>
  bfemp::SceneParameters<dim>
  read_scene(const CaseSpec &spec)
  {
    const std::string file =
      (std::filesystem::temp_directory_path() /
       ("bfemp_explicit_throughput_" + std::to_string(::getpid()) + "_" +
        std::to_string(dim) + "d.prm"))
        .string();
    {
      std::ofstream out(file);
      out << scene_prm<dim>(spec);
    }
    bfemp::SceneParameters<dim> parameters;
    parameters.read(file);
    std::filesystem::remove(file);
    return parameters;
  }

  /** What Simulation<dim> holds, without output and diagnostics. */
  template <int dim>
  class BfempScene
  {
  public:
    BfempScene(const bfemp::SceneParameters<dim> &scene_parameters,
               const Vortex<dim>                 &vortex)
      : parameters(scene_parameters)
      , grid(parameters.grid)
      , particle_system(grid)
      , transfer(grid, parameters.transfer, materials)
      , integrator(grid,
                   particle_system,
                   transfer,
                   parameters.boundaries,
                   parameters.gravity,
                   parameters.time.integrator)
    {
      using Layout = bfemp::ParticleLayout<dim>;
      AssertThrow(parameters.bodies.size() == 1, ExcInternalError());
      const bfemp::BodyParameters<dim> &body = parameters.bodies[0];
      materials.push_back(bfemp::create_material<dim>(body.material.model,
                                                      body.material.moduli()));
      const bfemp::BodySampler<dim> sampler(body, grid.lattice());
      const std::vector<Point<dim>> samples = sampler.sample();
      const double                  volume  = sampler.particle_volume();

      std::vector<double>     properties(Layout::n_properties, 0.);
      const ArrayView<double> p = make_array_view(properties);
      p[Layout::mass]           = body.material.density * volume;
      p[Layout::rest_volume]    = volume;
      Layout::set_tensor(p,
                         Layout::deformation_gradient,
                         unit_symmetric_tensor<dim>());
      p[Layout::material_id] = 0;
      p[Layout::body_id]     = 0;
      for (const Point<dim> &x : samples)
        {
          AssertThrow(grid.stencil_inside(x),
                      ExcMessage("benchmark block reaches outside the grid"));
          Layout::set_vector(p, Layout::velocity, vortex.velocity(x));
          Layout::set_tensor(p, Layout::affine_velocity, vortex.gradient(x));
          Layout::set_vector(p, Layout::initial_position, x);
          particle_system.insert(x, p);
        }
      particle_system.finish_insertion();
    }

    double
    p_wave_speed() const
    {
      return materials[0]->p_wave_speed(parameters.bodies[0].material.density);
    }

    const bfemp::SceneParameters<dim>                  parameters;
    bfemp::BackgroundGrid<dim>                         grid;
    std::vector<std::unique_ptr<bfemp::Material<dim>>> materials;
    bfemp::ParticleSystem<dim>                         particle_system;
    bfemp::ParticleGridTransfer<dim>                   transfer;
    bfemp::ExplicitMPM<dim>                            integrator;
  };

  // ------------------------------------------------------------------------
  // The hand-written loop: explicit USL, APIC, quadratic B-splines,
  // neo-Hookean, on a fixed grid with plain arrays. Particles are stored as
  // a structure of arrays; the grid as one array of interleaved node records
  // (m, m v | v~, f). Single-threaded.

  template <int dim>
  class HandLoop
  {
  public:
    static constexpr unsigned int dd     = dim * dim;
    static constexpr unsigned int record = 1 + 2 * dim; // m, mv[dim], f[dim]

    HandLoop(const std::array<unsigned int, dim> &n_cells,
             const double                         dx,
             const double                         mu,
             const double                         lambda,
             const unsigned int                   layers)
      : dx(dx)
      , inverse_dx(1. / dx)
      , mu(mu)
      , lambda(lambda)
      , layers(layers)
    {
      std::size_t s = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          n[d]      = n_cells[d];
          stride[d] = s;
          s *= n_cells[d] + 1;
        }
      n_nodes = s;
      grid.assign(n_nodes * record, 0.);
    }

    void
    add(const double   *position,
        const double   *velocity,
        const double   *F_p,
        const double   *C_p,
        const double    mass,
        const double    rest_volume,
        const long long id)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          x[d].push_back(position[d]);
          v[d].push_back(velocity[d]);
        }
      for (unsigned int k = 0; k < dd; ++k)
        {
          F[k].push_back(F_p[k]);
          C[k].push_back(C_p[k]);
        }
      m.push_back(mass);
      V0.push_back(rest_volume);
      ids.push_back(id);
    }

    std::size_t
    size() const
    {
      return m.size();
    }

    // noinline: keeps the step a separate symbol for profilers
    // (valgrind --toggle-collect, perf).
    __attribute__((noinline)) void
    step(const double dt)
    {
      std::fill(grid.begin(), grid.end(), 0.);
      particles_to_grid();
      update_grid(dt);
      grid_to_particles(dt);
    }

    // particles (structure of arrays)
    std::vector<double>    x[dim], v[dim], F[dd], C[dd], m, V0;
    std::vector<long long> ids;

  private:
    /** Quadratic B-spline weights and gradients of particle p. */
    inline void
    weights(const std::size_t p,
            int               base[dim],
            double            w[dim][3],
            double            dw[dim][3],
            double            r[dim][3]) const
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double xi = x[d][p] * inverse_dx; // grid origin is 0
          base[d]         = static_cast<int>(xi - 0.5);
          const double t  = xi - base[d];
          const double a = 1.5 - t, b = t - 1., c = t - 0.5;
          w[d][0]  = 0.5 * a * a;
          w[d][1]  = 0.75 - b * b;
          w[d][2]  = 0.5 * c * c;
          dw[d][0] = -a * inverse_dx;
          dw[d][1] = -2. * b * inverse_dx;
          dw[d][2] = c * inverse_dx;
          for (unsigned int a_ = 0; a_ < 3; ++a_)
            r[d][a_] = (static_cast<double>(a_) - t) * dx; // x_i - x_p
        }
    }

    void
    particles_to_grid()
    {
      double *const     g   = grid.data();
      const std::size_t n_p = size();
      for (std::size_t p = 0; p < n_p; ++p)
        {
          int    base[dim];
          double w[dim][3], dw[dim][3], r[dim][3];
          weights(p, base, w, dw, r);

          // stress = -V0 P F^T, P = mu (F - F^-T) + lambda ln J F^-T
          double f[dd], S[dd];
          for (unsigned int k = 0; k < dd; ++k)
            f[k] = F[k][p];
          if constexpr (dim == 2)
            {
              const double J  = f[0] * f[3] - f[1] * f[2];
              const double iJ = 1. / J;
              // F^-T
              const double fit[4] = {f[3] * iJ,
                                     -f[2] * iJ,
                                     -f[1] * iJ,
                                     f[0] * iJ};
              const double c1     = lambda * std::log(J) - mu;
              double       P[4];
              for (unsigned int k = 0; k < 4; ++k)
                P[k] = mu * f[k] + c1 * fit[k];
              const double s = -V0[p];
              S[0]           = s * (P[0] * f[0] + P[1] * f[1]);
              S[1]           = s * (P[0] * f[2] + P[1] * f[3]);
              S[2]           = s * (P[2] * f[0] + P[3] * f[1]);
              S[3]           = s * (P[2] * f[2] + P[3] * f[3]);
            }
          else
            {
              const double c00 = f[4] * f[8] - f[5] * f[7];
              const double c01 = f[5] * f[6] - f[3] * f[8];
              const double c02 = f[3] * f[7] - f[4] * f[6];
              const double c10 = f[2] * f[7] - f[1] * f[8];
              const double c11 = f[0] * f[8] - f[2] * f[6];
              const double c12 = f[1] * f[6] - f[0] * f[7];
              const double c20 = f[1] * f[5] - f[2] * f[4];
              const double c21 = f[2] * f[3] - f[0] * f[5];
              const double c22 = f[0] * f[4] - f[1] * f[3];
              const double J   = f[0] * c00 + f[1] * c01 + f[2] * c02;
              const double iJ  = 1. / J;
              // F^-T = cofactor(F) / J
              const double fit[9] = {c00 * iJ,
                                     c01 * iJ,
                                     c02 * iJ,
                                     c10 * iJ,
                                     c11 * iJ,
                                     c12 * iJ,
                                     c20 * iJ,
                                     c21 * iJ,
                                     c22 * iJ};
              const double c1     = lambda * std::log(J) - mu;
              double       P[9];
              for (unsigned int k = 0; k < 9; ++k)
                P[k] = mu * f[k] + c1 * fit[k];
              const double s = -V0[p];
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int j = 0; j < 3; ++j)
                  S[i * 3 + j] =
                    s * (P[i * 3] * f[j * 3] + P[i * 3 + 1] * f[j * 3 + 1] +
                         P[i * 3 + 2] * f[j * 3 + 2]);
            }

          const double mp = m[p];
          double       mv[dim], mC[dd];
          for (unsigned int d = 0; d < dim; ++d)
            mv[d] = mp * v[d][p];
          for (unsigned int k = 0; k < dd; ++k)
            mC[k] = mp * C[k][p];

          if constexpr (dim == 2)
            {
              for (unsigned int b = 0; b < 3; ++b)
                {
                  double *row =
                    g + record * ((base[1] + b) * stride[1] + base[0]);
                  for (unsigned int a = 0; a < 3; ++a)
                    {
                      double      *node = row + record * a;
                      const double wt   = w[0][a] * w[1][b];
                      const double g0   = dw[0][a] * w[1][b];
                      const double g1   = w[0][a] * dw[1][b];
                      const double r0 = r[0][a], r1 = r[1][b];
                      node[0] += wt * mp;
                      node[1] += wt * (mv[0] + mC[0] * r0 + mC[1] * r1);
                      node[2] += wt * (mv[1] + mC[2] * r0 + mC[3] * r1);
                      node[3] += S[0] * g0 + S[1] * g1;
                      node[4] += S[2] * g0 + S[3] * g1;
                    }
                }
            }
          else
            {
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int b = 0; b < 3; ++b)
                  {
                    double *row =
                      g + record * ((base[2] + c) * stride[2] +
                                    (base[1] + b) * stride[1] + base[0]);
                    const double wbc = w[1][b] * w[2][c];
                    const double r1 = r[1][b], r2 = r[2][c];
                    for (unsigned int a = 0; a < 3; ++a)
                      {
                        double      *node = row + record * a;
                        const double wt   = w[0][a] * wbc;
                        const double g0   = dw[0][a] * wbc;
                        const double g1   = w[0][a] * dw[1][b] * w[2][c];
                        const double g2   = w[0][a] * w[1][b] * dw[2][c];
                        const double r0   = r[0][a];
                        node[0] += wt * mp;
                        node[1] +=
                          wt * (mv[0] + mC[0] * r0 + mC[1] * r1 + mC[2] * r2);
                        node[2] +=
                          wt * (mv[1] + mC[3] * r0 + mC[4] * r1 + mC[5] * r2);
                        node[3] +=
                          wt * (mv[2] + mC[6] * r0 + mC[7] * r1 + mC[8] * r2);
                        node[4] += S[0] * g0 + S[1] * g1 + S[2] * g2;
                        node[5] += S[3] * g0 + S[4] * g1 + S[5] * g2;
                        node[6] += S[6] * g0 + S[7] * g1 + S[8] * g2;
                      }
                  }
            }
        }
    }

    /** v~ = m v / m + dt f / m (no gravity here), then separable-slip walls. */
    void
    update_grid(const double dt)
    {
      double *const g = grid.data();
      for (std::size_t node = 0; node < n_nodes; ++node)
        {
          double *rec = g + record * node;
          if (!(rec[0] > 0.))
            continue;
          const double inverse_mass = 1. / rec[0];
          std::size_t  rest         = node;
          for (int d = dim - 1; d >= 0; --d)
            {
              const int index = static_cast<int>(rest / stride[d]);
              rest -= index * stride[d];
              double vt = rec[1 + d] * inverse_mass +
                          dt * rec[1 + dim + d] * inverse_mass;
              if (index <= static_cast<int>(layers))
                vt = std::max(vt, 0.);
              else if (index >= static_cast<int>(n[d] - layers))
                vt = std::min(vt, 0.);
              rec[1 + d] = vt;
            }
        }
    }

    void
    grid_to_particles(const double dt)
    {
      const double *const g            = grid.data();
      const std::size_t   n_p          = size();
      const double        apic_inverse = 4. * inverse_dx * inverse_dx;
      for (std::size_t p = 0; p < n_p; ++p)
        {
          int    base[dim];
          double w[dim][3], dw[dim][3], r[dim][3];
          weights(p, base, w, dw, r);
          double vp[dim] = {}, B[dd] = {}, G[dd] = {};
          if constexpr (dim == 2)
            {
              for (unsigned int b = 0; b < 3; ++b)
                {
                  const double *row =
                    g + record * ((base[1] + b) * stride[1] + base[0]);
                  for (unsigned int a = 0; a < 3; ++a)
                    {
                      const double *node = row + record * a;
                      const double  wt   = w[0][a] * w[1][b];
                      const double  g0   = dw[0][a] * w[1][b];
                      const double  g1   = w[0][a] * dw[1][b];
                      const double  v0 = node[1], v1 = node[2];
                      const double  wv0 = wt * v0, wv1 = wt * v1;
                      vp[0] += wv0;
                      vp[1] += wv1;
                      B[0] += wv0 * r[0][a];
                      B[1] += wv0 * r[1][b];
                      B[2] += wv1 * r[0][a];
                      B[3] += wv1 * r[1][b];
                      G[0] += v0 * g0;
                      G[1] += v0 * g1;
                      G[2] += v1 * g0;
                      G[3] += v1 * g1;
                    }
                }
            }
          else
            {
              for (unsigned int c = 0; c < 3; ++c)
                for (unsigned int b = 0; b < 3; ++b)
                  {
                    const double *row =
                      g + record * ((base[2] + c) * stride[2] +
                                    (base[1] + b) * stride[1] + base[0]);
                    const double wbc = w[1][b] * w[2][c];
                    for (unsigned int a = 0; a < 3; ++a)
                      {
                        const double *node  = row + record * a;
                        const double  wt    = w[0][a] * wbc;
                        const double  gr[3] = {dw[0][a] * wbc,
                                               w[0][a] * dw[1][b] * w[2][c],
                                               w[0][a] * w[1][b] * dw[2][c]};
                        const double  rr[3] = {r[0][a], r[1][b], r[2][c]};
                        for (unsigned int i = 0; i < 3; ++i)
                          {
                            const double vi  = node[1 + i];
                            const double wvi = wt * vi;
                            vp[i] += wvi;
                            for (unsigned int j = 0; j < 3; ++j)
                              {
                                B[i * 3 + j] += wvi * rr[j];
                                G[i * 3 + j] += vi * gr[j];
                              }
                          }
                      }
                  }
            }
          // F <- (I + dt grad v) F
          double f[dd];
          for (unsigned int k = 0; k < dd; ++k)
            f[k] = F[k][p];
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              {
                double sum = f[i * dim + j];
                for (unsigned int k = 0; k < dim; ++k)
                  sum += dt * G[i * dim + k] * f[k * dim + j];
                F[i * dim + j][p] = sum;
              }
          for (unsigned int k = 0; k < dd; ++k)
            C[k][p] = apic_inverse * B[k];
          for (unsigned int d = 0; d < dim; ++d)
            {
              v[d][p] = vp[d];
              x[d][p] += dt * vp[d];
            }
        }
    }

    double              dx, inverse_dx, mu, lambda;
    unsigned int        layers;
    unsigned int        n[dim];
    std::size_t         stride[dim];
    std::size_t         n_nodes;
    std::vector<double> grid;
  };

  /** The loop's particles from bfemp's, in the handler's (cell) order. */
  template <int dim>
  HandLoop<dim>
  copy_to_loop(BfempScene<dim> &scene)
  {
    using Layout       = bfemp::ParticleLayout<dim>;
    const auto   &lat  = scene.grid.lattice();
    const auto    mods = scene.materials[0]->moduli();
    HandLoop<dim> loop(lat.n_cells,
                       lat.dx,
                       mods.mu,
                       mods.lambda,
                       wall_layers); // as set in scene_prm()
    auto         &handler = scene.particle_system.handler();
    for (auto particle = handler.begin(); particle != handler.end(); ++particle)
      {
        const ArrayView<const double> p = particle->get_properties();
        const Point<dim>              x = particle->get_location();
        double                        xp[dim];
        for (unsigned int d = 0; d < dim; ++d)
          xp[d] = x[d] - lat.origin[d];
        AssertThrow(lat.origin.norm() == 0., ExcInternalError());
        loop.add(xp,
                 &p[Layout::velocity],
                 &p[Layout::deformation_gradient],
                 &p[Layout::affine_velocity],
                 p[Layout::mass],
                 p[Layout::rest_volume],
                 particle->get_id());
      }
    return loop;
  }

  struct Difference
  {
    double position = 0., velocity = 0., deformation_gradient = 0.;
    bool   all_found = true;
  };

  /** Largest differences between bfemp's and the loop's particle states. */
  template <int dim>
  Difference
  compare(BfempScene<dim> &scene, const HandLoop<dim> &loop)
  {
    using Layout = bfemp::ParticleLayout<dim>;
    std::vector<std::size_t> index_of_id;
    for (std::size_t i = 0; i < loop.size(); ++i)
      {
        const auto id = static_cast<std::size_t>(loop.ids[i]);
        if (id >= index_of_id.size())
          index_of_id.resize(id + 1, std::size_t(-1));
        index_of_id[id] = i;
      }
    Difference diff;
    auto      &handler = scene.particle_system.handler();
    for (auto particle = handler.begin(); particle != handler.end(); ++particle)
      {
        const auto id = particle->get_id();
        if (id >= index_of_id.size() || index_of_id[id] == std::size_t(-1))
          {
            diff.all_found = false;
            continue;
          }
        const std::size_t             i = index_of_id[id];
        const ArrayView<const double> p = particle->get_properties();
        const Point<dim>              x = particle->get_location();
        for (unsigned int d = 0; d < dim; ++d)
          {
            diff.position =
              std::max(diff.position, std::abs(x[d] - loop.x[d][i]));
            diff.velocity =
              std::max(diff.velocity,
                       std::abs(p[Layout::velocity + d] - loop.v[d][i]));
          }
        for (unsigned int k = 0; k < dim * dim; ++k)
          diff.deformation_gradient =
            std::max(diff.deformation_gradient,
                     std::abs(p[Layout::deformation_gradient + k] -
                              loop.F[k][i]));
      }
    return diff;
  }

  /** min det F over bfemp's particles and whether everything is finite. */
  template <int dim>
  std::pair<double, bool>
  check_state(BfempScene<dim> &scene)
  {
    using Layout   = bfemp::ParticleLayout<dim>;
    double min_J   = std::numeric_limits<double>::infinity();
    bool   finite  = true;
    auto  &handler = scene.particle_system.handler();
    for (auto particle = handler.begin(); particle != handler.end(); ++particle)
      {
        const ArrayView<const double> p = particle->get_properties();
        const Tensor<2, dim>          F =
          Layout::get_tensor(p, Layout::deformation_gradient);
        min_J = std::min(min_J, determinant(F));
        for (unsigned int d = 0; d < dim; ++d)
          finite = finite && std::isfinite(particle->get_location()[d]) &&
                   std::isfinite(p[Layout::velocity + d]);
      }
    return {min_J, finite};
  }

  /**
   * One step of bfemp; returns the fraction of particles that changed cells
   * in it (each of them costs a remove and re-insert in update_cells).
   */
  template <int dim>
  double
  one_step_crossings(BfempScene<dim> &scene, const double dt, double &time)
  {
    auto       &handler = scene.particle_system.handler();
    const auto &lattice = scene.grid.lattice();
    std::vector<std::pair<types::particle_index, std::array<int, dim>>> cells;
    for (auto p = handler.begin(); p != handler.end(); ++p)
      cells.emplace_back(p->get_id(), lattice.cell_of(p->get_location()));
    std::sort(cells.begin(), cells.end(), [](const auto &a, const auto &b) {
      return a.first < b.first;
    });
    scene.integrator.step({dt, time});
    time += dt;
    std::size_t crossed = 0;
    for (auto p = handler.begin(); p != handler.end(); ++p)
      {
        const auto it =
          std::lower_bound(cells.begin(),
                           cells.end(),
                           p->get_id(),
                           [](const auto &a, const types::particle_index id) {
                             return a.first < id;
                           });
        if (it != cells.end() && it->first == p->get_id() &&
            it->second != lattice.cell_of(p->get_location()))
          ++crossed;
      }
    return double(crossed) / cells.size();
  }

  // ------------------------------------------------------------------------

  struct Entry
  {
    unsigned int dim = 0, threads = 0, steps = 0;
    std::size_t  particles = 0, grid_nodes = 0;
    double       seconds = 0., rate = 0., loop_seconds = 0., loop_rate = 0.;
    std::vector<double> samples, loop_samples, cpu_samples, loop_cpu_samples;
    double              cpu_rate = 0., loop_cpu_rate = 0.;
    double              speedup       = 0.;
    double              setup_seconds = 0., load_before = 0., load_after = 0.;
    double              crossing_start = 0., crossing_end = 0.;
    Difference          difference;
    double              min_J  = 0.;
    bool                finite = true;
  };

  template <int dim>
  std::vector<Entry>
  run_case(const CaseSpec &spec, const Options &options)
  {
    const double load_before = load_average();
    const auto   setup_start = Clock::now();

    const bfemp::SceneParameters<dim> parameters = read_scene<dim>(spec);
    // The vortex amplitude follows the material's wave speed.
    const bfemp::BodyParameters<dim> &body = parameters.bodies[0];
    const double                      c_p  = std::sqrt(
      (body.material.moduli().lambda + 2. * body.material.moduli().mu) /
      body.material.density);
    const Vortex<dim> vortex{spec.margin * cell_size,
                             spec.block_cells * cell_size,
                             vortex_mach * c_p};
    const double      dt = cfl_number * cell_size / (c_p + vortex.amplitude);

    auto scene = std::make_unique<BfempScene<dim>>(parameters, vortex);
    AssertThrow(std::abs(scene->p_wave_speed() - c_p) < 1e-12 * c_p,
                ExcInternalError());
    // The loop's initial state, copied from bfemp's particles.
    const HandLoop<dim> initial_loop  = copy_to_loop(*scene);
    const double        setup_seconds = seconds_since(setup_start);

    const std::size_t n_particles = scene->particle_system.n_particles();
    const std::size_t n_nodes     = scene->grid.lattice().n_nodes;
    std::cout << "\n"
              << dim << "D case: " << n_particles << " particles, " << n_nodes
              << " grid nodes, dt = " << dt << " s, set-up " << std::fixed
              << std::setprecision(1) << setup_seconds << " s"
              << std::defaultfloat << std::setprecision(3) << std::endl;

    // Warm-up of both, then the same-algorithm check.
    const unsigned int warm_up = 3;
    double             time    = 0.;
    MultithreadInfo::set_thread_limit(1);
    for (unsigned int s = 0; s < warm_up; ++s, time += dt)
      scene->integrator.step({dt, time});
    Difference difference;
    {
      HandLoop<dim> loop = initial_loop;
      for (unsigned int s = 0; s < warm_up; ++s)
        loop.step(dt);
      difference = compare(*scene, loop);
    }
    std::cout << "  after " << warm_up
              << " warm-up steps, bfemp vs loop: max |dx| = "
              << difference.position / cell_size
              << " dx, max |dv| = " << difference.velocity / vortex.amplitude
              << " v_max, max |dF| = " << difference.deformation_gradient
              << std::endl;
    AssertThrow(difference.all_found &&
                  difference.position < 1e-9 * cell_size &&
                  difference.deformation_gradient < 1e-9,
                ExcMessage("the hand-written loop does not reproduce bfemp's "
                           "step: the comparison would be void"));

    if (options.profile_steps > 0)
      {
        const auto start = Clock::now();
        for (unsigned int s = 0; s < options.profile_steps; ++s, time += dt)
          scene->integrator.step({dt, time});
        const double seconds = seconds_since(start);
        std::cout << "  profile: " << options.profile_steps << " steps in "
                  << seconds << " s, "
                  << n_particles * options.profile_steps / seconds
                  << " particle-steps/s on 1 thread" << std::endl;
        return {};
      }

    // Calibrate the number of timed steps on one thread.
    const double crossing_start    = one_step_crossings(*scene, dt, time);
    const auto   calibrate_start   = Clock::now();
    unsigned int calibration_steps = 0;
    do
      {
        scene->integrator.step({dt, time});
        time += dt;
        ++calibration_steps;
    } while (seconds_since(calibrate_start) < 0.1 * options.seconds);
    const double per_step = seconds_since(calibrate_start) / calibration_steps;
    // At least min_steps_per_block, so that every block spans bfemp's whole
    // cycle of cell changes (including its periodic re-ordering of the
    // particle data after about a quarter of the particles moved, every
    // 9-14 steps in these scenes), not a lucky part of it.
    const unsigned int steps =
      std::max<unsigned int>(min_steps_per_block,
                             static_cast<unsigned int>(
                               std::ceil(options.seconds / per_step)));
    std::cout << "  cells changed per step: " << 100. * crossing_start
              << " % of particles; timing " << steps << " steps per block ("
              << per_step << " s/step on 1 thread)" << std::endl;

    // Timed blocks: bfemp on 1 and 2 threads and the loop, interleaved so
    // that load bursts from other processes hit all three alike. Every
    // block starts from the same state (a fresh scene, or a fresh copy of
    // the loop's initial state, each warmed up by warm_up steps), so all
    // blocks time the same steps of the same motion: the vortex slows down
    // as its kinetic energy turns into strain energy, and the rate of cell
    // changes with it. Wall and process CPU time of every block are kept
    // (CPU / wall < threads means the machine was busy with something else).
    const std::vector<unsigned int>  thread_counts = {1, 2};
    std::vector<std::vector<double>> wall(thread_counts.size()),
      cpu(thread_counts.size());
    std::vector<double>     loop_wall, loop_cpu;
    double                  crossing_end = 0.;
    std::pair<double, bool> state;
    for (unsigned int rep = 0; rep < options.repeats; ++rep)
      {
        for (unsigned int t = 0; t < thread_counts.size(); ++t)
          {
            scene.reset();
            scene = std::make_unique<BfempScene<dim>>(parameters, vortex);
            MultithreadInfo::set_thread_limit(thread_counts[t]);
            time = 0.;
            for (unsigned int s = 0; s < warm_up; ++s, time += dt)
              scene->integrator.step({dt, time});
            const double cpu_start = process_cpu_seconds();
            const auto   start     = Clock::now();
            for (unsigned int s = 0; s < steps; ++s, time += dt)
              scene->integrator.step({dt, time});
            wall[t].push_back(seconds_since(start));
            cpu[t].push_back(process_cpu_seconds() - cpu_start);
            std::cout << "  bfemp " << thread_counts[t]
                      << " thread(s): " << wall[t].back() << " s (cpu "
                      << cpu[t].back() << " s)" << std::endl;
            if (rep == 0 && t == 0)
              {
                crossing_end = one_step_crossings(*scene, dt, time);
                state        = check_state(*scene);
              }
          }
        scene.reset();
        MultithreadInfo::set_thread_limit(1);
        HandLoop<dim> loop = initial_loop;
        for (unsigned int s = 0; s < warm_up; ++s)
          loop.step(dt);
        const double cpu_start = process_cpu_seconds();
        const auto   start     = Clock::now();
        for (unsigned int s = 0; s < steps; ++s)
          loop.step(dt);
        loop_wall.push_back(seconds_since(start));
        loop_cpu.push_back(process_cpu_seconds() - cpu_start);
        std::cout << "  loop  1 thread:    " << loop_wall.back() << " s (cpu "
                  << loop_cpu.back() << " s)" << std::endl;
      }

    const double load_after = load_average();
    auto         best       = [](const std::vector<double> &v) {
      return *std::min_element(v.begin(), v.end());
    };
    const double loop_rate     = double(n_particles) * steps / best(loop_wall);
    const double loop_cpu_rate = double(n_particles) * steps / best(loop_cpu);

    std::vector<Entry> entries;
    for (unsigned int t = 0; t < thread_counts.size(); ++t)
      {
        Entry e;
        e.dim              = dim;
        e.threads          = thread_counts[t];
        e.steps            = steps;
        e.particles        = n_particles;
        e.grid_nodes       = n_nodes;
        e.samples          = wall[t];
        e.cpu_samples      = cpu[t];
        e.seconds          = best(wall[t]);
        e.rate             = double(n_particles) * steps / e.seconds;
        e.cpu_rate         = double(n_particles) * steps / best(cpu[t]);
        e.loop_samples     = loop_wall;
        e.loop_cpu_samples = loop_cpu;
        e.loop_seconds     = best(loop_wall);
        e.loop_rate        = loop_rate;
        e.loop_cpu_rate    = loop_cpu_rate;
        e.setup_seconds    = setup_seconds;
        e.load_before      = load_before;
        e.load_after       = load_after;
        e.crossing_start   = crossing_start;
        e.crossing_end     = crossing_end;
        e.difference       = difference;
        e.min_J            = state.first;
        e.finite           = state.second;
        entries.push_back(e);
      }
    for (Entry &e : entries)
      e.speedup = e.rate / entries[0].rate;
    std::cout << "  cells changed per step at the end of a block: "
              << 100. * crossing_end
              << " %; end state: min det F = " << state.first
              << (state.second ? ", finite" : ", NOT FINITE") << std::endl;
    return entries;
  }

  void
  write_json(const std::string        &file,
             const Options            &options,
             const GitState           &git,
             const std::vector<Entry> &entries,
             const double              total_seconds)
  {
    const std::string &commit = git.commit;
    const std::string &dirty  = git.modified;
    char               date[64];
    const std::time_t  now = std::time(nullptr);
    std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));

    std::filesystem::create_directories(
      std::filesystem::path(file).parent_path());
    std::ofstream out(file);
    out << std::setprecision(6);
    auto list = [&](const std::vector<double> &v) {
      std::ostringstream s;
      s << std::setprecision(6) << "[";
      for (unsigned int i = 0; i < v.size(); ++i)
        s << (i ? ", " : "") << v[i];
      return s.str() + "]";
    };
    out << "{\n"
        << "  \"benchmark\": \"explicit_throughput\",\n"
        << "  \"mode\": " << json_string(options.quick ? "quick" : "full")
        << ",\n"
        << "  \"machine\": {\"cpu\": " << json_string(cpu_model())
        << ", \"nproc\": " << std::thread::hardware_concurrency() << "},\n"
        << "  \"date\": " << json_string(date) << ",\n"
        << "  \"git_commit\": " << json_string(commit) << ",\n"
        << "  \"library_files_modified_since_commit\": " << json_string(dirty)
        << ",\n"
        << "  \"build\": " << json_string(build_type()) << ",\n"
        << "  \"total_seconds\": " << total_seconds << ",\n"
        << "  \"scene\": {\"kernel\": \"quadratic\", \"transfer\": \"APIC\", "
           "\"integrator\": \"explicit USL\", \"material\": \"neo-Hookean\", "
           "\"particles_per_cell\": \"2 per direction\", \"initial "
           "velocity\": \"Taylor-Green vortex, peak "
        << vortex_mach << " c_p\", \"cfl\": " << cfl_number << "},\n"
        << "  \"notes\": \"seconds = best (smallest) wall time of "
        << options.repeats
        << " timed blocks of 'steps' explicit steps (bfemp 1 thread, bfemp 2 "
           "threads and the loop interleaved); particle_steps_per_second = "
           "particles * steps / seconds; loop = hand-written single-threaded "
           "fixed-grid loop of the same algorithm; ratio = "
           "particle_steps_per_second / loop_particle_steps_per_second; "
           "ratio_per_core = ratio / threads; speedup = rate / 1-thread rate; "
           "ratio_cpu_time = the same ratio from process CPU time (robust to "
           "other load on the machine); every block starts from the same "
           "warmed-up initial state; cell_change_fraction_per_step = share "
           "of particles that change cells in one step, at the start and at "
           "the end of a block\",\n"
        << "  \"cases\": [\n";
    for (unsigned int i = 0; i < entries.size(); ++i)
      {
        const Entry &e = entries[i];
        out << "    {\"dim\": " << e.dim << ", \"particles\": " << e.particles
            << ", \"grid_nodes\": " << e.grid_nodes
            << ", \"threads\": " << e.threads << ", \"steps\": " << e.steps
            << ",\n     \"seconds\": " << e.seconds
            << ", \"seconds_samples\": " << list(e.samples)
            << ", \"particle_steps_per_second\": " << e.rate
            << ",\n     \"loop_seconds\": " << e.loop_seconds
            << ", \"loop_seconds_samples\": " << list(e.loop_samples)
            << ", \"loop_particle_steps_per_second\": " << e.loop_rate
            << ",\n     \"ratio\": " << e.rate / e.loop_rate
            << ", \"ratio_per_core\": " << e.rate / e.loop_rate / e.threads
            << ", \"speedup\": " << e.speedup
            << ",\n     \"cpu_seconds_samples\": " << list(e.cpu_samples)
            << ", \"loop_cpu_seconds_samples\": " << list(e.loop_cpu_samples)
            << ", \"ratio_cpu_time\": " << e.cpu_rate / e.loop_cpu_rate
            << ",\n     \"cell_change_fraction_per_step\": ["
            << e.crossing_start << ", " << e.crossing_end << "]"
            << ", \"max_position_difference_vs_loop\": "
            << e.difference.position << ", \"max_F_difference_vs_loop\": "
            << e.difference.deformation_gradient
            << ", \"end_min_det_F\": " << e.min_J
            << ", \"end_state_finite\": " << (e.finite ? "true" : "false")
            << ",\n     \"setup_seconds\": " << e.setup_seconds
            << ", \"load_average_before\": " << e.load_before
            << ", \"load_average_after\": " << e.load_after << "}"
            << (i + 1 < entries.size() ? "," : "") << "\n";
      }
    out << "  ]\n}\n";
  }

  void
  print_table(const std::vector<Entry> &entries)
  {
    std::cout << "\n| dim | particles | threads | steps | bfemp s | "
                 "bfemp p-steps/s | loop p-steps/s | bfemp/loop | per core | "
                 "speedup |\n"
              << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Entry &e : entries)
      std::cout << "| " << e.dim << " | " << e.particles << " | " << e.threads
                << " | " << e.steps << " | " << std::fixed
                << std::setprecision(2) << e.seconds << " | " << std::scientific
                << std::setprecision(2) << e.rate << " | " << e.loop_rate
                << " | " << std::fixed << std::setprecision(3)
                << e.rate / e.loop_rate << " | "
                << e.rate / e.loop_rate / e.threads << " | "
                << std::setprecision(2) << e.speedup << " |"
                << std::defaultfloat << "\n";
    std::cout << std::flush;
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      Options options;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--quick")
            options.quick = true;
          else if (arg == "--output" && i + 1 < argc)
            options.output = argv[++i];
          else if (arg == "--repeats" && i + 1 < argc)
            options.repeats = std::max(1, std::atoi(argv[++i]));
          else if (arg == "--seconds" && i + 1 < argc)
            options.seconds = std::atof(argv[++i]);
          else if (arg == "--case" && i + 1 < argc)
            options.only_case = std::atoi(argv[++i]);
          else if (arg == "--profile-steps" && i + 1 < argc)
            options.profile_steps = std::max(1, std::atoi(argv[++i]));
          else
            {
              std::cerr << "usage: " << argv[0]
                        << " [--quick] [--output FILE] [--repeats N] "
                           "[--seconds S] [--case I] [--profile-steps N]\n";
              return 1;
            }
        }
      if (options.quick && options.seconds == 2.5)
        options.seconds = 0.25;
      if (options.output.empty())
        options.output = std::string(BFEMP_SOURCE_DIR) +
                         "/benchmarks/results/explicit_throughput" +
                         (options.quick ? "_quick" : "") + ".json";

      // 2D: 4 particles per cell, 3D: 8; about 1e5 and 1e6 particles.
      const std::vector<CaseSpec> cases =
        options.quick ? std::vector<CaseSpec>{{2, 80, 3}, {3, 16, 3}}
                      : std::vector<CaseSpec>{{2, 160, 3},
                                              {2, 500, 3},
                                              {3, 24, 3},
                                              {3, 50, 3}};
      std::cout << "bfemp explicit_throughput (" << cpu_model() << ", "
                << std::thread::hardware_concurrency() << " cores, "
                << build_type() << " build)" << std::endl;
      if (build_type() != "release")
        std::cout << "WARNING: not a Release build; configure with "
                     "-DCMAKE_BUILD_TYPE=Release for meaningful numbers"
                  << std::endl;

      const GitState     git   = read_git_state();
      const auto         start = Clock::now();
      std::vector<Entry> entries;
      for (unsigned int c = 0; c < cases.size(); ++c)
        {
          if (options.only_case >= 0 &&
              c != static_cast<unsigned int>(options.only_case))
            continue;
          const CaseSpec &spec    = cases[c];
          const auto case_entries = spec.dim == 2 ? run_case<2>(spec, options)
                                                  : run_case<3>(spec, options);
          entries.insert(entries.end(),
                         case_entries.begin(),
                         case_entries.end());
        }
      const double total = seconds_since(start);
      if (options.profile_steps > 0)
        return 0;
      print_table(entries);
      write_json(options.output, options, git, entries, total);
      std::cout << "\nwrote " << options.output << " (total " << total << " s)"
                << std::endl;
    }
  catch (const std::exception &error)
    {
      std::cerr << "explicit_throughput: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
