// Cost of one Newton iteration of bfemp's implicit solver, split into
// assembly, factorization, solve and line search, against the number of
// unknowns, for MPM and FEM blocks in 2D and 3D and the three linear solvers
// (CHOLMOD, UMFPACK, CG AMG).
//
//   cmake --build build --target implicit_newton
//   build/benchmarks/implicit_newton            # full run, about 2 hours
//   build/benchmarks/implicit_newton --quick    # smoke run, seconds
//   python3 benchmarks/plot_implicit_newton.py  #
//   doc/images/implicit_newton.png
//
// The full run (2 cores, Debian's reference BLAS) takes about 2 hours on a
// quiet machine, over half of it in one run: the 3D MPM block at 1.1e5
// unknowns with CHOLMOD, whose factorizations take several minutes each (its
// warm-up step plus one timed step, see --max-run-seconds). Sizes 0-2 of all
// cases take about half an hour. The factorizations spend their time in BLAS;
// the JSON records which BLAS library was loaded, and figures taken with
// another BLAS (OpenBLAS, BLIS) are not comparable.
//
// Options:
//   --quick             tiny blocks (a few hundred unknowns), 1 warm-up step
//   --output FILE       default benchmarks/results/implicit_newton.json in the
//                       source tree (implicit_newton_quick.json with --quick)
//   --repeats N         timed implicit steps per run after the warm-up step
//                       (3); times are summed over them and divided by the
//                       summed Newton iterations
//   --max-run-seconds S stop timing further steps of a run once its timed
//                       steps took S seconds (900; at least one timed step):
//                       bounds the largest 3D runs, whose single
//                       factorizations take minutes
//   --case NAME[,NAME]  only these cases: mpm_2d, mpm_3d, fem_2d, fem_3d
//   --size I[,I]        only these sizes (0 = smallest .. 3 = largest)
//   --solver S[,S]      only these linear solvers: CHOLMOD, UMFPACK, "CG AMG"
//                       (or cg_amg)
//   --threads N         thread limit of deal.II/TBB (default: all cores)
//   --time-step DT      implicit time step [s] (default 5e-3)
//   --max-umfpack-factorization S
//                       skip UMFPACK where one factorization takes (or is
//                       predicted from the smaller sizes to take) more than
//                       S seconds (60; 0 = never skip). The prediction
//                       needs the smaller sizes in the same invocation;
//                       without them (e.g. --size 3 alone) the limit is
//                       only checked after the warm-up step, which at the
//                       largest 3D sizes costs as much as a timed run
//   --list              print the cases and sizes and stop
//
// Each run is one neo-Hookean block of side 1 m (E = 100 kPa, nu = 0.3,
// rho = 1000 kg/m^3) standing on a sticky floor (MPM: the grid's y- wall;
// FEM: the nodes of the bottom face prescribed fixed), thrown at the floor
// with 1 m/s under gravity, so that it is compressed and Newton needs several
// iterations per step. The scene is written as a prm text, read by
// SceneParameters<dim>::read, and assembled the way Simulation<dim> does
// (MPM bodies sampled into particles, FEM bodies meshed from "source =
// rectangle" with the target edge length setting the resolution) into an
// ImplicitIntegrator<dim> with backward Euler at a fixed time step. After one
// untimed warm-up step, --repeats steps are timed; NewtonStatistics of each
// step give the phase times and iterations. Every solver of a size starts
// from a freshly built scene, so all solvers time the same steps.
//
// nnz: ImplicitIntegrator does not expose its IncrementalPotential, so the
// Hessian's sparsity pattern is rebuilt here before each timed step from the
// same pieces (P2G mass -> DofSpace -> energy terms -> setup_system), outside
// the timing; its DoF count is checked against the integrator's.

#include <bfemp/base/input_error.h>
#include <bfemp/fem/fem_body.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/integrator/implicit_integrator.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/body_sampler.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/scene/scene_parameters.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/fem_elasticity_term.h>
#include <bfemp/solver/incremental_potential.h>
#include <bfemp/solver/inertia_term.h>
#include <bfemp/solver/mpm_elasticity_term.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <sys/resource.h>
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
  // Scene constants.

  constexpr double block_length   = 1.;   // [m], side of the block
  constexpr double youngs_modulus = 1e5;  // [Pa]
  constexpr double poisson_ratio  = 0.3;  // [-]
  constexpr double density        = 1000; // [kg/m^3]
  constexpr double impact_speed   = 1.;   // [m/s], initial, towards the floor
  constexpr double gravity        = 9.81; // [m/s^2], in -y
  // MPM: grid cells between the block and the grid boundary; also the
  // thickness of the sticky floor wall (its top layer touches the block).
  constexpr unsigned int margin_cells            = 3;
  constexpr unsigned int particles_per_direction = 2;

  enum class Kind
  {
    mpm,
    fem
  };

  struct CaseSpec
  {
    std::string  name;
    unsigned int dim;
    Kind         kind;
    /** MPM: grid cells per block side; FEM: elements (subdivisions) per
     *  side. From small to large. */
    std::vector<unsigned int> resolutions;
  };

  const std::vector<std::string> all_solvers = {"CHOLMOD", "UMFPACK", "CG AMG"};

  /**
   * Unknowns: MPM with quadratic B-splines and 2 particles per cell and
   * direction activates the (B + 3)^dim nodes around a block of B cells; an
   * FEM rectangle/box of n subdivisions per side has (n + 1)^dim nodes. The
   * sizes span about 1e3 .. 1e5 unknowns in 3D and 1e3 .. 2e5 in 2D.
   */
  std::vector<CaseSpec>
  make_cases(const bool quick)
  {
    if (quick)
      return {{"mpm_2d", 2, Kind::mpm, {8}},
              {"mpm_3d", 3, Kind::mpm, {3}},
              {"fem_2d", 2, Kind::fem, {8}},
              {"fem_3d", 3, Kind::fem, {3}}};
    return {{"mpm_2d", 2, Kind::mpm, {19, 68, 221, 313}},
            {"mpm_3d", 3, Kind::mpm, {4, 9, 17, 30}},
            {"fem_2d", 2, Kind::fem, {21, 70, 223, 315}},
            {"fem_3d", 3, Kind::fem, {6, 11, 20, 32}}};
  }

  unsigned int
  expected_dofs(const CaseSpec &spec, const unsigned int resolution)
  {
    const unsigned int per_side =
      spec.kind == Kind::mpm ? resolution + 3 : resolution + 1;
    return spec.dim * static_cast<unsigned int>(std::pow(per_side, spec.dim));
  }

  struct Options
  {
    bool                     quick     = false;
    bool                     list      = false;
    unsigned int             repeats   = 3;
    unsigned int             threads   = 0; // 0: deal.II's default (all cores)
    double                   time_step = 5e-3;
    double                   max_umfpack_factor = 60.;
    double                   max_run_seconds    = 900.;
    std::string              output;
    std::set<std::string>    cases;
    std::set<unsigned int>   sizes;
    std::vector<std::string> solvers = all_solvers;
  };

  std::string
  solver_from_argument(std::string name)
  {
    for (char &c : name)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (name == "CG_AMG" || name == "CGAMG" || name == "CG-AMG")
      name = "CG AMG";
    if (std::find(all_solvers.begin(), all_solvers.end(), name) ==
        all_solvers.end())
      throw std::runtime_error("unknown solver '" + name +
                               "'; use CHOLMOD, UMFPACK or \"CG AMG\"");
    return name;
  }

  /** A finite number, or null (JSON has no inf/NaN). */
  std::string
  json_number(const double x)
  {
    if (!std::isfinite(x))
      return "null";
    std::ostringstream s;
    s << std::setprecision(6) << x;
    return s.str();
  }

  template <typename T>
  std::string
  json_list(const std::vector<T> &v)
  {
    std::ostringstream s;
    s << "[";
    for (unsigned int i = 0; i < v.size(); ++i)
      {
        s << (i ? ", " : "");
        if constexpr (std::is_floating_point_v<T>)
          s << json_number(v[i]);
        else
          s << v[i];
      }
    return s.str() + "]";
  }

  // ------------------------------------------------------------------------
  // The scene as a prm text.

  template <int dim>
  std::string
  point(const double x, const double y, const double z)
  {
    std::ostringstream s;
    s << std::setprecision(17) << x << ", " << y;
    if (dim == 3)
      s << ", " << z;
    return s.str();
  }

  template <int dim>
  std::string
  uniform(const double value)
  {
    return point<dim>(value, value, value);
  }

  std::string
  material_prm(const std::string &indent)
  {
    std::ostringstream prm;
    prm << indent << "subsection material\n"
        << indent << "  set model           = neo-Hookean\n"
        << indent << "  set Young's modulus = " << youngs_modulus << "\n"
        << indent << "  set Poisson's ratio = " << poisson_ratio << "\n"
        << indent << "  set density         = " << density << "\n"
        << indent << "end\n";
    return prm.str();
  }

  template <int dim>
  std::string
  scene_prm(const CaseSpec    &spec,
            const unsigned int resolution,
            const std::string &solver,
            const double       dt)
  {
    std::ostringstream prm;
    prm << std::setprecision(17);
    prm << "set dimension = " << dim << "\n"
        << "subsection run\n  set name = implicit_newton\n"
        << "  set end time = 1\n  set quiet = true\nend\n"
        << "subsection time\n  set integrator = implicit backward Euler\n"
        << "  set time step mode = fixed\n  set time step = " << dt << "\nend\n"
        << "subsection gravity\n  set acceleration = "
        << point<dim>(0., -gravity, 0.) << "\nend\n"
        << "subsection solver\n  set linear solver = " << solver << "\nend\n";
    if (spec.kind == Kind::mpm)
      {
        const double       dx     = block_length / resolution;
        const unsigned int n_grid = resolution + 2 * margin_cells;
        prm << "set number of bodies = 1\n"
            << "set number of FEM bodies = 0\n"
            << "subsection grid\n"
            << "  set lower corner = " << uniform<dim>(0.) << "\n"
            << "  set upper corner = " << uniform<dim>(n_grid * dx) << "\n"
            << "  set cell size = " << dx << "\n"
            << "  set kernel = quadratic\nend\n"
            << "subsection transfer\n  set scheme = APIC\nend\n"
            << "subsection boundaries\n  set walls = y-\n"
            << "  set wall condition = sticky\n"
            << "  set wall layers = " << margin_cells << "\nend\n"
            << "subsection body 0\n"
            << "  set particles per cell = " << particles_per_direction << "\n"
            << "  set sampling = regular\n"
            << "  set initial velocity = " << point<dim>(0., -impact_speed, 0.)
            << "\n"
            << "  subsection primitive 0\n    set type = box\n"
            << "    set lower corner = " << uniform<dim>(margin_cells * dx)
            << "\n"
            << "    set upper corner = "
            << uniform<dim>((margin_cells + resolution) * dx) << "\n"
            << "  end\n"
            << material_prm("  ") << "end\n";
      }
    else
      {
        prm << "set number of bodies = 0\n"
            << "set number of FEM bodies = 1\n"
            << "subsection boundaries\n  set walls = none\nend\n"
            << "subsection fem body 0\n"
            << "  set initial velocity = " << point<dim>(0., -impact_speed, 0.)
            << "\n"
            << material_prm("  ") << "  subsection mesh\n"
            << "    set source = rectangle\n"
            << "    set lower corner = " << uniform<dim>(0.) << "\n"
            << "    set upper corner = " << uniform<dim>(block_length) << "\n"
            << "    set target edge length = " << block_length / resolution
            << "\n  end\n"
            << "  subsection prescribed motion\n"
            << "    set nodes = box\n"
            << "    set box lower corner = " << point<dim>(-0.1, -0.1, -0.1)
            << "\n"
            << "    set box upper corner = "
            << point<dim>(block_length + 0.1,
                          1e-6 * block_length,
                          block_length + 0.1)
            << "\n    set motion = fixed\n  end\nend\n";
      }
    return prm.str();
  }

  template <int dim>
  bfemp::SceneParameters<dim>
  read_scene(const std::string &text)
  {
    const std::string file =
      (std::filesystem::temp_directory_path() /
       ("bfemp_implicit_newton_" + std::to_string(::getpid()) + "_" +
        std::to_string(dim) + "d.prm"))
        .string();
    {
      std::ofstream out(file);
      out << text;
    }
    bfemp::SceneParameters<dim> parameters;
    try
      {
        parameters.read(file);
      }
    catch (...)
      {
        std::filesystem::remove(file);
        throw;
      }
    std::filesystem::remove(file);
    return parameters;
  }

  // ------------------------------------------------------------------------
  // What Simulation<dim> builds for an implicit scene, without output and
  // diagnostics (see source/scene/simulation.cc).

  template <int dim>
  class Scene
  {
  public:
    explicit Scene(const bfemp::SceneParameters<dim> &scene_parameters)
      : parameters(scene_parameters)
      , grid(parameters.grid)
      , particle_system(grid)
      , transfer(grid, parameters.transfer, materials)
    {
      using Layout = bfemp::ParticleLayout<dim>;
      AssertThrow(parameters.time.is_implicit(), ExcInternalError());
      for (const auto &body : parameters.bodies)
        materials.push_back(
          bfemp::create_material<dim>(body.material.model,
                                      body.material.moduli()));
      for (unsigned int b = 0; b < parameters.fem_bodies.size(); ++b)
        fem_bodies.push_back(
          std::make_unique<bfemp::FemBody<dim>>(parameters.fem_bodies[b],
                                                "fem body " +
                                                  std::to_string(b)));

      std::vector<double> properties(Layout::n_properties);
      for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
        {
          const bfemp::BodyParameters<dim> &body = parameters.bodies[b];
          const bfemp::BodySampler<dim>     sampler(body, grid.lattice());
          const std::vector<Point<dim>>     samples = sampler.sample();
          const double                      volume  = sampler.particle_volume();
          std::fill(properties.begin(), properties.end(), 0.);
          const ArrayView<double> p = make_array_view(properties);
          p[Layout::mass]           = body.material.density * volume;
          p[Layout::rest_volume]    = volume;
          // the benchmark scenes have constant initial velocities
          Layout::set_vector(p,
                             Layout::velocity,
                             body.initial_velocity.value(Point<dim>()));
          Layout::set_tensor(p,
                             Layout::deformation_gradient,
                             unit_symmetric_tensor<dim>());
          p[Layout::material_id] = b;
          p[Layout::body_id]     = b;
          for (const Point<dim> &x : samples)
            {
              AssertThrow(grid.stencil_inside(x),
                          ExcMessage("benchmark block reaches outside the "
                                     "grid"));
              Layout::set_vector(p, Layout::initial_position, x);
              particle_system.insert(x, p);
            }
        }
      particle_system.finish_insertion();

      integrator = std::make_unique<bfemp::ImplicitIntegrator<dim>>(
        grid,
        particle_system,
        transfer,
        materials,
        fem_bodies,
        parameters.boundaries,
        parameters.gravity,
        parameters.time.implicit_scheme(),
        parameters.solver,
        parameters.contact);
    }

    struct Pattern
    {
      unsigned int n_dofs = 0;
      std::size_t  nnz    = 0;
    };

    /**
     * The Hessian's sparsity pattern of the next step, built like
     * ImplicitIntegrator::step() builds it (P2G mass -> DofSpace -> terms
     * -> IncrementalPotential::setup_system()). Changes no state the step
     * reads.
     */
    Pattern
    next_pattern()
    {
      std::vector<double> mass;
      if (particle_system.n_particles() > 0)
        {
          bfemp::GridState<dim> state;
          state.reinit(grid.lattice().n_nodes);
          transfer.particles_to_grid(particle_system, state, false);
          mass = state.mass;
        }
      std::vector<unsigned int> fem_nodes;
      for (const auto &body : fem_bodies)
        fem_nodes.push_back(body->n_nodes());
      bfemp::DofSpace<dim> dofs;
      dofs.reinit(fem_nodes, mass);

      bfemp::InertiaTerm<dim> inertia;
      inertia.reinit(std::vector<double>(dofs.n_nodes(), 1.),
                     Vector<double>(dofs.n_dofs()));
      bfemp::FemElasticityTerm<dim> fem(fem_bodies, dofs);
      bfemp::MpmElasticityTerm<dim> mpm(grid, particle_system, materials, dofs);
      std::vector<const bfemp::EnergyTerm<dim> *> terms = {&inertia};
      if (!fem_bodies.empty())
        terms.push_back(&fem);
      if (particle_system.n_particles() > 0)
        terms.push_back(&mpm);
      bfemp::IncrementalPotential<dim> potential(dofs);
      potential.set_terms(terms);
      potential.setup_system();
      return {dofs.n_dofs(), potential.sparsity_pattern().n_nonzero_elements()};
    }

    unsigned int
    n_fem_nodes() const
    {
      unsigned int n = 0;
      for (const auto &body : fem_bodies)
        n += body->n_nodes();
      return n;
    }

    std::size_t
    n_fem_elements() const
    {
      std::size_t n = 0;
      for (const auto &body : fem_bodies)
        n += body->elements().size();
      return n;
    }

    const bfemp::SceneParameters<dim>                  parameters;
    bfemp::BackgroundGrid<dim>                         grid;
    std::vector<std::unique_ptr<bfemp::Material<dim>>> materials;
    bfemp::ParticleSystem<dim>                         particle_system;
    bfemp::ParticleGridTransfer<dim>                   transfer;
    std::vector<std::unique_ptr<bfemp::FemBody<dim>>>  fem_bodies;
    std::unique_ptr<bfemp::ImplicitIntegrator<dim>>    integrator;
  };

  // ------------------------------------------------------------------------
  // One run: a case at one size with one solver.

  struct StepRecord
  {
    unsigned int            n_dofs  = 0;
    std::size_t             nnz     = 0;
    double                  seconds = 0., cpu_seconds = 0.;
    bfemp::NewtonStatistics newton;

    double
    newton_seconds() const
    {
      return newton.assembly_time + newton.factorization_time +
             newton.solve_time + newton.line_search_time;
    }
  };

  struct Run
  {
    std::string  case_name, kind, solver;
    unsigned int dim = 0, size_index = 0, resolution = 0;
    unsigned int expected_dofs = 0;
    std::size_t  particles = 0, fem_nodes = 0, fem_elements = 0;

    bool        skipped = false, failed = false;
    std::string reason;

    double                  setup_seconds = 0., run_seconds = 0.;
    double                  peak_memory = 0.;
    double                  load_before = -1., load_after = -1.;
    bool                    has_warm_up = false;
    StepRecord              warm_up;
    std::vector<StepRecord> steps;

    unsigned int
    iterations() const
    {
      unsigned int n = 0;
      for (const StepRecord &s : steps)
        n += s.newton.iterations;
      return n;
    }

    /** Phase time summed over the timed steps / their Newton iterations. */
    double
    per_iteration(double bfemp::NewtonStatistics::*phase) const
    {
      double total = 0.;
      for (const StepRecord &s : steps)
        total += s.newton.*phase;
      return iterations() > 0 ? total / iterations()
                              : std::numeric_limits<double>::quiet_NaN();
    }

    /** The smallest per-iteration phase time of any timed step. */
    double
    per_iteration_min(double bfemp::NewtonStatistics::*phase) const
    {
      double best = std::numeric_limits<double>::infinity();
      for (const StepRecord &s : steps)
        if (s.newton.iterations > 0)
          best = std::min(best, s.newton.*phase / s.newton.iterations);
      return std::isfinite(best) ? best
                                 : std::numeric_limits<double>::quiet_NaN();
    }

    double
    factorization() const
    {
      return per_iteration(&bfemp::NewtonStatistics::factorization_time);
    }

    /** (assembly + solve + line search) / factorization per iteration. */
    double
    ratio() const
    {
      using S = bfemp::NewtonStatistics;
      return (per_iteration(&S::assembly_time) + per_iteration(&S::solve_time) +
              per_iteration(&S::line_search_time)) /
             factorization();
    }

    unsigned int
    n_dofs() const
    {
      return !steps.empty() ? steps.front().n_dofs
             : has_warm_up  ? warm_up.n_dofs
                            : expected_dofs;
    }
  };

  template <int dim>
  StepRecord
  timed_step(Scene<dim>        &scene,
             const double       dt,
             const unsigned int step,
             const bool         with_pattern)
  {
    StepRecord record;
    if (with_pattern)
      {
        const auto pattern = scene.next_pattern();
        record.n_dofs      = pattern.n_dofs;
        record.nnz         = pattern.nnz;
      }
    const double cpu_start = process_cpu_seconds();
    const auto   start     = Clock::now();
    scene.integrator->step({dt, step * dt, step + 1});
    record.seconds     = seconds_since(start);
    record.cpu_seconds = process_cpu_seconds() - cpu_start;
    record.newton      = *scene.integrator->newton_statistics();
    if (with_pattern)
      AssertThrow(record.n_dofs == scene.integrator->n_dofs(),
                  ExcMessage("the benchmark's copy of the DoF space has " +
                             std::to_string(record.n_dofs) +
                             " unknowns, the integrator's " +
                             std::to_string(scene.integrator->n_dofs())));
    record.n_dofs = scene.integrator->n_dofs();
    return record;
  }

  void
  print_step(const std::string &label, const StepRecord &s)
  {
    const double n = std::max(1u, s.newton.iterations);
    std::cout << "    " << label << ": " << s.n_dofs << " dofs, "
              << s.newton.iterations << " iterations (" << s.newton.backtracks
              << " backtracks), per iteration: assembly "
              << s.newton.assembly_time / n << " s, factorization "
              << s.newton.factorization_time / n << " s, solve "
              << s.newton.solve_time / n << " s, line search "
              << s.newton.line_search_time / n << " s; step " << s.seconds
              << " s (outside Newton " << s.seconds - s.newton_seconds()
              << " s, cpu " << s.cpu_seconds << " s)" << std::endl;
  }

  template <int dim>
  void
  run_one(const CaseSpec &spec, Run &run, const Options &options, double limit)
  {
    run.load_before                               = load_average();
    const auto                        setup_start = Clock::now();
    const bfemp::SceneParameters<dim> parameters  = read_scene<dim>(
      scene_prm<dim>(spec, run.resolution, run.solver, options.time_step));
    Scene<dim> scene(parameters);
    run.setup_seconds = seconds_since(setup_start);
    run.particles     = scene.particle_system.n_particles();
    run.fem_nodes     = scene.n_fem_nodes();
    run.fem_elements  = scene.n_fem_elements();

    unsigned int step = 0;
    try
      {
        // Warm-up: first touches, library initialization, the first
        // symbolic analysis of the direct solvers.
        run.warm_up     = timed_step(scene, options.time_step, step++, false);
        run.has_warm_up = true;
        print_step("warm-up", run.warm_up);
        const double factorization_per_iteration =
          run.warm_up.newton.factorization_time /
          std::max(1u, run.warm_up.newton.iterations);
        if (limit > 0. && factorization_per_iteration > limit)
          {
            std::ostringstream reason;
            reason << "the warm-up step took " << factorization_per_iteration
                   << " s per factorization (> " << limit
                   << " s, --max-umfpack-factorization); timed steps skipped";
            run.skipped = true;
            run.reason  = reason.str();
            std::cout << "    skipped: " << run.reason << std::endl;
          }
        else
          {
            double timed_seconds = 0.;
            for (unsigned int r = 0; r < options.repeats; ++r)
              {
                if (timed_seconds >= options.max_run_seconds)
                  {
                    std::cout << "    " << r << " timed steps took "
                              << timed_seconds << " s >= --max-run-seconds "
                              << options.max_run_seconds << ": no further steps"
                              << std::endl;
                    break;
                  }
                run.steps.push_back(
                  timed_step(scene, options.time_step, step++, true));
                timed_seconds += run.steps.back().seconds;
                print_step("step " + std::to_string(r + 1), run.steps.back());
              }
          }
      }
    catch (const bfemp::SimulationError &error)
      {
        run.failed = true;
        run.reason = error.what();
        std::cout << "    FAILED: " << run.reason << std::endl;
      }
    run.load_after  = load_average();
    run.run_seconds = seconds_since(setup_start);
    run.peak_memory = peak_memory_gib();
  }

  /**
   * Factorization seconds per iteration predicted for @p n_dofs from the
   * same case and solver at smaller sizes in this run: a power law through
   * the two largest measured sizes (exponent clamped to [1, 3]), or with one
   * size the exponent 2 (3D) / 1.5 (2D). NaN without measurements.
   */
  double
  predict_factorization(const std::vector<Run> &runs, const Run &next)
  {
    std::vector<std::pair<double, double>> points;
    for (const Run &r : runs)
      if (r.case_name == next.case_name && r.solver == next.solver &&
          !r.steps.empty() && r.factorization() > 0.)
        points.emplace_back(r.n_dofs(), r.factorization());
    if (points.empty())
      return std::numeric_limits<double>::quiet_NaN();
    std::sort(points.begin(), points.end());
    const auto &last     = points.back();
    double      exponent = next.dim == 3 ? 2. : 1.5;
    if (points.size() >= 2)
      {
        const auto &before = points[points.size() - 2];
        if (last.first > before.first)
          exponent = std::clamp(std::log(last.second / before.second) /
                                  std::log(last.first / before.first),
                                1.,
                                3.);
      }
    return last.second * std::pow(next.expected_dofs / last.first, exponent);
  }

  // ------------------------------------------------------------------------
  // Output.

  /**
   * The target: in 3D at about 1e5 unknowns, assembly + solve +
   * line search per Newton iteration cost no more than the factorization.
   */
  bool
  is_target_run(const Run &r)
  {
    return r.dim == 3 && r.n_dofs() >= 50000 && !r.steps.empty();
  }

  void
  write_json(const std::string      &file,
             const Options          &options,
             const GitState         &git,
             const std::vector<Run> &runs,
             const double            total_seconds)
  {
    using S = bfemp::NewtonStatistics;
    char              date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));

    const auto parent = std::filesystem::path(file).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);
    std::ofstream out(file);
    out << std::setprecision(6);
    out << "{\n"
        << "  \"benchmark\": \"implicit_newton\",\n"
        << "  \"mode\": " << json_string(options.quick ? "quick" : "full")
        << ",\n"
        << "  \"machine\": {\"cpu\": " << json_string(cpu_model())
        << ", \"nproc\": " << std::thread::hardware_concurrency()
        << ", \"memory_gib\": " << json_number(memory_gib())
        << ", \"blas\": " << json_string(blas_libraries())
        << ", \"OMP_NUM_THREADS\": "
        << json_string(environment("OMP_NUM_THREADS"))
        << ", \"OPENBLAS_NUM_THREADS\": "
        << json_string(environment("OPENBLAS_NUM_THREADS")) << "},\n"
        << "  \"threads\": " << MultithreadInfo::n_threads() << ",\n"
        << "  \"date\": " << json_string(date) << ",\n"
        << "  \"git_commit\": " << json_string(git.commit) << ",\n"
        << "  \"library_files_modified_since_commit\": "
        << json_string(git.modified) << ",\n"
        << "  \"build\": " << json_string(build_type()) << ",\n"
        << "  \"total_seconds\": " << json_number(total_seconds) << ",\n"
        << "  \"scene\": {\"block_length\": " << block_length
        << ", \"material\": \"neo-Hookean\", \"youngs_modulus\": "
        << youngs_modulus << ", \"poisson_ratio\": " << poisson_ratio
        << ", \"density\": " << density
        << ", \"impact_speed\": " << impact_speed
        << ", \"gravity\": " << gravity
        << ", \"integrator\": \"implicit backward Euler\", \"time_step\": "
        << options.time_step
        << ", \"mpm\": \"quadratic B-splines, APIC, 2 particles per cell and "
           "direction, sticky floor wall of "
        << margin_cells
        << " layers\", \"fem\": \"linear simplices from source = rectangle "
           "(2 triangles per square, 5 tetrahedra per cube), bottom face "
           "prescribed fixed\", \"newton_tolerance\": \"default\"},\n"
        << "  \"warm_up_steps\": 1,\n"
        << "  \"timed_steps\": " << options.repeats << ",\n"
        << "  \"max_run_seconds\": " << options.max_run_seconds << ",\n"
        << "  \"max_umfpack_factorization_seconds\": "
        << options.max_umfpack_factor << ",\n"
        << "  \"notes\": \"One neo-Hookean block of side block_length thrown "
           "at a sticky floor under gravity, advanced by ImplicitIntegrator "
           "(backward Euler, fixed time_step): 1 untimed warm-up step, then "
           "timed_steps steps (fewer once a run's timed steps took "
           "max_run_seconds; 'steps' says how many), each run from a freshly "
           "built scene, so all solvers time the same steps. "
           "per_iteration = phase seconds (NewtonStatistics) summed over the "
           "timed steps / their Newton iterations; per_iteration_min = the "
           "smallest per-iteration value of any timed step; "
           "ratio_rest_to_factorization = (assembly + solve + line_search) / "
           "factorization of per_iteration (for CG AMG 'factorization' is "
           "the AMG set-up and 'solve' the CG iterations). n_dofs and nnz "
           "(entries of the Newton matrix, both triangles) are those of the "
           "first timed step; per_step has every step's values. "
           "outside_newton_seconds = step wall time minus the four phases "
           "(P2G, DoF numbering, sparsity pattern, G2P). "
           "peak_memory_gib_so_far = the process's peak resident memory at "
           "the end of the run (runs go from small to large, so it is about "
           "that of the largest run so far). skipped runs were "
           "not timed (reason says why), failed runs threw a "
           "SimulationError. target_3d_1e5 lists the 3D runs with at "
           "least 5e4 unknowns and whether they meet the issue's target "
           "ratio_rest_to_factorization <= 1.\",\n"
        << "  \"runs\": [\n";
    for (unsigned int i = 0; i < runs.size(); ++i)
      {
        const Run &r        = runs[i];
        auto       per_step = [&](auto value) {
          std::vector<decltype(value(r.steps.front()))> v;
          for (const StepRecord &s : r.steps)
            v.push_back(value(s));
          return json_list(v);
        };
        out << "    {\"case\": " << json_string(r.case_name)
            << ", \"dim\": " << r.dim << ", \"kind\": " << json_string(r.kind)
            << ", \"solver\": " << json_string(r.solver)
            << ", \"size_index\": " << r.size_index
            << ", \"resolution\": " << r.resolution
            << ", \"n_dofs\": " << r.n_dofs()
            << ", \"nnz\": " << (r.steps.empty() ? 0 : r.steps.front().nnz)
            << ", \"particles\": " << r.particles
            << ", \"fem_nodes\": " << r.fem_nodes
            << ", \"fem_elements\": " << r.fem_elements
            << ",\n     \"skipped\": " << (r.skipped ? "true" : "false")
            << ", \"failed\": " << (r.failed ? "true" : "false")
            << ", \"reason\": " << json_string(r.reason)
            << ",\n     \"steps\": " << r.steps.size()
            << ", \"iterations\": " << r.iterations()
            << ",\n     \"per_iteration\": {\"assembly\": "
            << json_number(r.per_iteration(&S::assembly_time))
            << ", \"factorization\": "
            << json_number(r.per_iteration(&S::factorization_time))
            << ", \"solve\": " << json_number(r.per_iteration(&S::solve_time))
            << ", \"line_search\": "
            << json_number(r.per_iteration(&S::line_search_time)) << "}"
            << ",\n     \"per_iteration_min\": {\"assembly\": "
            << json_number(r.per_iteration_min(&S::assembly_time))
            << ", \"factorization\": "
            << json_number(r.per_iteration_min(&S::factorization_time))
            << ", \"solve\": "
            << json_number(r.per_iteration_min(&S::solve_time))
            << ", \"line_search\": "
            << json_number(r.per_iteration_min(&S::line_search_time)) << "}"
            << ",\n     \"ratio_rest_to_factorization\": "
            << json_number(r.steps.empty()
                             ? std::numeric_limits<double>::quiet_NaN()
                             : r.ratio());
        if (!r.steps.empty())
          out << ",\n     \"per_step\": {\"n_dofs\": "
              << per_step([](const StepRecord &s) { return s.n_dofs; })
              << ", \"nnz\": "
              << per_step([](const StepRecord &s) { return s.nnz; })
              << ", \"iterations\": " << per_step([](const StepRecord &s) {
                   return s.newton.iterations;
                 })
              << ", \"backtracks\": " << per_step([](const StepRecord &s) {
                   return s.newton.backtracks;
                 })
              << ",\n       \"assembly_seconds\": "
              << per_step(
                   [](const StepRecord &s) { return s.newton.assembly_time; })
              << ", \"factorization_seconds\": "
              << per_step([](const StepRecord &s) {
                   return s.newton.factorization_time;
                 })
              << ", \"solve_seconds\": " << per_step([](const StepRecord &s) {
                   return s.newton.solve_time;
                 })
              << ", \"line_search_seconds\": "
              << per_step([](const StepRecord &s) {
                   return s.newton.line_search_time;
                 })
              << ",\n       \"step_seconds\": "
              << per_step([](const StepRecord &s) { return s.seconds; })
              << ", \"step_cpu_seconds\": "
              << per_step([](const StepRecord &s) { return s.cpu_seconds; })
              << ", \"outside_newton_seconds\": "
              << per_step([](const StepRecord &s) {
                   return s.seconds - s.newton_seconds();
                 })
              << "}";
        if (r.has_warm_up)
          out << ",\n     \"warm_up\": {\"n_dofs\": " << r.warm_up.n_dofs
              << ", \"iterations\": " << r.warm_up.newton.iterations
              << ", \"assembly_seconds\": "
              << json_number(r.warm_up.newton.assembly_time)
              << ", \"factorization_seconds\": "
              << json_number(r.warm_up.newton.factorization_time)
              << ", \"solve_seconds\": "
              << json_number(r.warm_up.newton.solve_time)
              << ", \"line_search_seconds\": "
              << json_number(r.warm_up.newton.line_search_time)
              << ", \"step_seconds\": " << json_number(r.warm_up.seconds)
              << "}";
        out << ",\n     \"setup_seconds\": " << json_number(r.setup_seconds)
            << ", \"run_seconds\": " << json_number(r.run_seconds)
            << ", \"peak_memory_gib_so_far\": " << json_number(r.peak_memory)
            << ", \"load_average_before\": " << json_number(r.load_before)
            << ", \"load_average_after\": " << json_number(r.load_after) << "}"
            << (i + 1 < runs.size() ? "," : "") << "\n";
      }
    out << "  ],\n"
        << "  \"target_3d_1e5\": [";
    bool first = true;
    for (const Run &r : runs)
      if (is_target_run(r))
        {
          out << (first ? "\n" : ",\n")
              << "    {\"case\": " << json_string(r.case_name)
              << ", \"solver\": " << json_string(r.solver)
              << ", \"n_dofs\": " << r.n_dofs()
              << ", \"ratio_rest_to_factorization\": " << json_number(r.ratio())
              << ", \"met\": " << (r.ratio() <= 1. ? "true" : "false") << "}";
          first = false;
        }
    out << (first ? "]\n" : "\n  ]\n") << "}\n";
  }

  void
  print_table(const std::vector<Run> &runs)
  {
    using S = bfemp::NewtonStatistics;
    std::cout << "\nper Newton iteration [s]:\n"
              << "| case | solver | dofs | nnz | its | assembly | "
                 "factorization | solve | line search | rest / factorization "
                 "|\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Run &r : runs)
      {
        std::cout << "| " << r.case_name << " | " << r.solver << " | "
                  << r.n_dofs() << " | ";
        if (r.steps.empty())
          {
            std::cout << "- | - | " << (r.failed ? "FAILED" : "skipped")
                      << " | | | | |\n";
            continue;
          }
        std::cout << r.steps.front().nnz << " | " << r.iterations() << " | "
                  << std::scientific << std::setprecision(2)
                  << r.per_iteration(&S::assembly_time) << " | "
                  << r.per_iteration(&S::factorization_time) << " | "
                  << r.per_iteration(&S::solve_time) << " | "
                  << r.per_iteration(&S::line_search_time) << " | "
                  << std::fixed << std::setprecision(3) << r.ratio() << " |"
                  << std::defaultfloat << "\n";
      }
    for (const Run &r : runs)
      if (is_target_run(r))
        std::cout << "target (3D, ~1e5 unknowns: assembly + solve + line "
                     "search <= factorization): "
                  << r.case_name << " " << r.solver << " at " << r.n_dofs()
                  << " unknowns: ratio " << r.ratio()
                  << (r.ratio() <= 1. ? " (met)" : " (NOT met)") << "\n";
    std::cout << std::flush;
  }
} // namespace



int
main(int argc, char **argv)
{
  // Trilinos (CG AMG) needs MPI; one process, threads left to deal.II.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  try
    {
      Options options;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg     = argv[i];
          const bool        has_arg = i + 1 < argc;
          if (arg == "--quick")
            options.quick = true;
          else if (arg == "--list")
            options.list = true;
          else if (arg == "--output" && has_arg)
            options.output = argv[++i];
          else if (arg == "--repeats" && has_arg)
            options.repeats = std::max(1, std::atoi(argv[++i]));
          else if (arg == "--threads" && has_arg)
            options.threads = std::max(1, std::atoi(argv[++i]));
          else if (arg == "--time-step" && has_arg)
            options.time_step = std::atof(argv[++i]);
          else if (arg == "--max-run-seconds" && has_arg)
            options.max_run_seconds = std::atof(argv[++i]);
          else if (arg == "--max-umfpack-factorization" && has_arg)
            options.max_umfpack_factor = std::atof(argv[++i]);
          else if (arg == "--case" && has_arg)
            for (const std::string &name :
                 Utilities::split_string_list(argv[++i], ','))
              options.cases.insert(name);
          else if (arg == "--size" && has_arg)
            for (const std::string &index :
                 Utilities::split_string_list(argv[++i], ','))
              options.sizes.insert(std::stoi(index));
          else if (arg == "--solver" && has_arg)
            {
              options.solvers.clear();
              for (const std::string &name :
                   Utilities::split_string_list(argv[++i], ','))
                options.solvers.push_back(solver_from_argument(name));
            }
          else
            {
              std::cerr
                << "usage: " << argv[0]
                << " [--quick] [--output FILE] [--repeats N] [--case "
                   "mpm_2d,mpm_3d,fem_2d,fem_3d] [--size I,...] [--solver "
                   "CHOLMOD,UMFPACK,cg_amg] [--threads N] [--time-step DT] "
                   "[--max-umfpack-factorization S] [--max-run-seconds S] "
                   "[--list]\n";
              return 1;
            }
        }
      if (!(options.time_step > 0.))
        throw std::runtime_error("--time-step must be > 0");
      if (options.output.empty())
        options.output = std::string(BFEMP_SOURCE_DIR) +
                         "/benchmarks/results/implicit_newton" +
                         (options.quick ? "_quick" : "") + ".json";
      if (options.threads > 0)
        MultithreadInfo::set_thread_limit(options.threads);

      const std::vector<CaseSpec> cases = make_cases(options.quick);
      for (const std::string &name : options.cases)
        if (std::none_of(cases.begin(), cases.end(), [&](const CaseSpec &c) {
              return c.name == name;
            }))
          throw std::runtime_error("unknown case '" + name +
                                   "'; use mpm_2d, mpm_3d, fem_2d, fem_3d");

      // The runs in order: case, size (small to large), solver.
      std::vector<std::pair<const CaseSpec *, Run>> plan;
      for (const CaseSpec &spec : cases)
        {
          if (!options.cases.empty() && options.cases.count(spec.name) == 0)
            continue;
          for (unsigned int s = 0; s < spec.resolutions.size(); ++s)
            {
              if (!options.sizes.empty() && options.sizes.count(s) == 0)
                continue;
              for (const std::string &solver : options.solvers)
                {
                  Run run;
                  run.case_name     = spec.name;
                  run.dim           = spec.dim;
                  run.kind          = spec.kind == Kind::mpm ? "MPM" : "FEM";
                  run.solver        = solver;
                  run.size_index    = s;
                  run.resolution    = spec.resolutions[s];
                  run.expected_dofs = expected_dofs(spec, spec.resolutions[s]);
                  plan.emplace_back(&spec, run);
                }
            }
        }

      std::cout << "bfemp implicit_newton (" << cpu_model() << ", "
                << std::thread::hardware_concurrency() << " cores, "
                << MultithreadInfo::n_threads() << " threads, " << build_type()
                << " build)" << std::endl;
      if (options.list)
        {
          for (const auto &[spec, run] : plan)
            std::cout << "  " << run.case_name << " size " << run.size_index
                      << " (resolution " << run.resolution << ", about "
                      << run.expected_dofs << " dofs) " << run.solver
                      << std::endl;
          return 0;
        }
      if (build_type() != "release")
        std::cout << "WARNING: not a Release build; configure with "
                     "-DCMAKE_BUILD_TYPE=Release for meaningful numbers"
                  << std::endl;

      const GitState   git   = read_git_state();
      const auto       start = Clock::now();
      std::vector<Run> runs;
      for (auto &[spec, run] : plan)
        {
          std::cout << spec->name << " size " << run.size_index << " ("
                    << (spec->kind == Kind::mpm ? "cells" : "elements")
                    << " per side " << run.resolution << ", about "
                    << run.expected_dofs << " dofs), " << run.solver
                    << std::endl;
          const double limit =
            run.solver == "UMFPACK" ? options.max_umfpack_factor : 0.;
          const double predicted = limit > 0.
                                     ? predict_factorization(runs, run)
                                     : std::numeric_limits<double>::quiet_NaN();
          if (std::isfinite(predicted) && predicted > limit)
            {
              std::ostringstream reason;
              reason << "predicted " << predicted
                     << " s per factorization from the smaller sizes (> "
                     << limit << " s, --max-umfpack-factorization)";
              run.skipped = true;
              run.reason  = reason.str();
              std::cout << "    skipped: " << run.reason << std::endl;
            }
          else if (spec->dim == 2)
            run_one<2>(*spec, run, options, limit);
          else
            run_one<3>(*spec, run, options, limit);
          runs.push_back(run);
        }
      const double total = seconds_since(start);
      print_table(runs);
      write_json(options.output, options, git, runs, total);
      std::cout << "\nwrote " << options.output << " (total " << total << " s)"
                << std::endl;
    }
  catch (const std::exception &error)
    {
      std::cerr << "implicit_newton: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
