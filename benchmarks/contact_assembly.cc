// Cost of the particle-mesh contact parts of one Newton iteration against
// the number of particles in contact with the FEM boundary (within dhat), in
// 2D and 3D: broad phase + distances, barrier value, gradient and Hessian
// assembly, the CCD step bound along a Newton-like direction, the friction
// update and the friction value, gradient and Hessian; next to them the MPM
// elasticity gradient and Hessian of the same scene for scale.
//
//   cmake --build build --target contact_assembly
//   build/benchmarks/contact_assembly            # full run, a few minutes
//   build/benchmarks/contact_assembly --quick    # smoke run, seconds
//
// Options:
//   --quick          small scenes, short timings (< 20 s)
//   --output FILE    default benchmarks/results/contact_assembly.json in the
//                    source tree (contact_assembly_quick.json with --quick)
//   --seconds S      minimum timed wall time per phase and scene (0.25; 0.005
//                    with --quick); at least --repeats calls are timed
//   --repeats N      minimum timed calls per phase (5; 2 with --quick)
//   --threads N      thread limit of deal.II/TBB (1: the figures are single-
//                    core costs, which is what the scaling is about and what
//                    a machine shared with other jobs measures reliably)
//   --series NAME[,NAME]  only these series (see below)
//   --size I[,I]     only these sizes (0 = smallest of a series)
//   --phases NAME[,NAME]  only these phases (see below; for profiling)
//
// Scene: a block of particles (2 per grid cell and direction, spacing
// s = dx / 2, dx = 0.02 m, quadratic B-splines) resting just above the top
// face y = 0 of an FEM box (linear simplices, target edge length 1.3 s,
// thickness 2 edges, reaching 2 edges beyond the block sideways), dhat =
// 0.4 s. The block's bottom layer of particles sits at heights uniform in
// [0.2, 0.9] dhat (these are the contacting particles), the layers above it
// at s, 2 s, ... higher, i.e. at least 2.5 dhat from the box (the far
// particles). Positions within a layer are regular with a jitter of +-0.1 s.
// The contacting particles are n (2D) or n x n (3D) of the bottom layer, so
// that the FEM box grows with them (its boundary facets near the block are
// about the contact count / 1.7 in 2D and / 1.7^2 * 2 triangles in 3D).
// Series:
//   contact_2d, contact_3d        deformable FEM box (its nodes are unknowns),
//                                 fixed number of layers, contact count varied
//   kinematic_2d, kinematic_3d    the same with a kinematic box (every node
//                                 prescribed, fixed: no FEM unknowns)
//   far_2d, far_3d                deformable box, fixed contact count, layers
//                                 (far particles) varied
// The pieces are built the way ImplicitIntegrator builds them (P2G mass ->
// negligible nodes dropped -> DofSpace -> ContactGeometry::begin_step ->
// BarrierTerm::begin_step -> FrictionTerm::update at u = 0), with the
// backward Euler weight s = dt^2, dt = 5e-3 s, kappa = 1e5 Pa, mu = 0.5,
// eps_v = 1e-3 m/s. The Hessian is a SparseMatrix whose pattern comes from
// add_couplings of the MPM elasticity, FEM elasticity (deformable box),
// barrier and friction terms (as IncrementalPotential::setup_system builds
// it). Every phase is evaluated at a displacement u with random grid and FEM
// node components of up to 0.05 dhat; the CCD direction p moves the grid
// nodes by about (0.5, -1, 0.3) dhat (20 % jitter per component: the block
// slides down onto the box, most contacting particles reach it within the
// step) and deformable FEM nodes by random components of up to 0.1 dhat.
//
// Phases (each one library call as the Newton solver makes it; each timed
// call by itself, one untimed warm-up call first):
//   near_pairs           ContactGeometry::near_pairs(u, dhat): broad phase
//                        (spatial hash over inflated facet boxes) + exact
//                        distances, over all particles
//   barrier_value        BarrierTerm::value
//   barrier_gradient     BarrierTerm::add_gradient
//   barrier_couplings_missing  BarrierTerm::couplings_missing(u, pattern)
//                        (called before every Hessian assembly)
//   barrier_hessian      BarrierTerm::add_hessian into the SparseMatrix
//   ccd_step_bound       BarrierTerm::step_bound(u, p) (time_of_impact)
//   friction_update      FrictionTerm::update(u) (once per friction
//                        iteration of Algorithm 1, not per Newton iteration)
//   friction_value, friction_gradient, friction_couplings_missing,
//   friction_hessian     (couplings_missing: called before every Hessian
//                        assembly, like the barrier's)
//   begin_step           ContactGeometry::begin_step + BarrierTerm::begin_step
//                        (once per time step)
//   mpm_gradient, mpm_hessian  MpmElasticityTerm::add_gradient/add_hessian
//                        over all particles (for the ratios)
// ContactGeometry caches the last near_pairs answer per u: gradient,
// couplings_missing and Hessian at one Newton iterate share one broad phase,
// as in the solver. near_pairs and barrier_value are timed alternating
// between two displacements that differ in one entry by 1e-15 (every call
// misses the cache, as a line-search trial does).
// contact_per_iteration = barrier value + gradient + couplings_missing +
// Hessian + ccd_step_bound + friction value + gradient + couplings_missing +
// Hessian: one Newton iteration with one line-search trial. Reported per call:
// best, median and mean over the timed calls; per contacting particle: median /
// contacting particles. Fits: least-squares slope of log(median) against
// log(contacting particles) (against log(particles) for the far series).

#include <bfemp/contact/barrier_term.h>
#include <bfemp/contact/contact_geometry.h>
#include <bfemp/contact/contact_parameters.h>
#include <bfemp/contact/friction_term.h>
#include <bfemp/fem/fem_body.h>
#include <bfemp/fem/fem_body_parameters.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/fem_elasticity_term.h>
#include <bfemp/solver/mpm_elasticity_term.h>
#include <bfemp/solver/node_sparsity.h>
#include <bfemp/transfer/particle_grid_transfer.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "machine_info.h"

#ifndef BFEMP_SOURCE_DIR
#  define BFEMP_SOURCE_DIR "."
#endif

namespace
{
  using namespace dealii;
  using namespace machine_info;
  using Clock = std::chrono::steady_clock;

  // ------------------------------------------------------------------------
  // Scene constants.

  constexpr double       cell_size      = 0.02;            // dx [m]
  constexpr double       spacing        = 0.5 * cell_size; // particle spacing s
  constexpr double       dhat           = 0.4 * spacing; // activation distance
  constexpr double       fem_edge       = 1.3 * spacing; // target edge length
  constexpr double       fem_thickness  = 2. * fem_edge;
  constexpr double       youngs_modulus = 1e5;  // [Pa], particles and box
  constexpr double       poisson_ratio  = 0.3;  // [-]
  constexpr double       density        = 1000; // [kg/m^3]
  constexpr double       time_step      = 5e-3; // [s]
  constexpr double       kappa          = 1e5;  // barrier stiffness [Pa]
  constexpr double       friction_mu    = 0.5;
  constexpr double       static_velocity = 1e-3;        // eps_v [m/s]
  constexpr double       u_amplitude     = 0.05 * dhat; // evaluation point
  constexpr double       p_fem_amplitude = 0.1 * dhat;  // FEM part of p
  constexpr unsigned int seed            = 20240611;
  constexpr unsigned int grid_slack      = 4; // cells around everything

  const std::vector<std::string> phase_names = {"near_pairs",
                                                "barrier_value",
                                                "barrier_gradient",
                                                "barrier_couplings_missing",
                                                "barrier_hessian",
                                                "ccd_step_bound",
                                                "friction_update",
                                                "friction_value",
                                                "friction_gradient",
                                                "friction_couplings_missing",
                                                "friction_hessian",
                                                "begin_step",
                                                "mpm_gradient",
                                                "mpm_hessian"};

  /** The phases of one Newton iteration with one line-search trial. */
  const std::vector<std::string> iteration_phases = {
    "barrier_value",
    "barrier_gradient",
    "barrier_couplings_missing",
    "barrier_hessian",
    "ccd_step_bound",
    "friction_value",
    "friction_gradient",
    "friction_couplings_missing",
    "friction_hessian"};

  struct Options
  {
    bool                  quick   = false;
    double                seconds = 0.25;
    unsigned int          repeats = 5;
    unsigned int          threads = 1;
    std::string           output;
    std::set<std::string> series;
    /** Only these sizes (indices within a series; all if empty). */
    std::set<unsigned int> sizes;
    /** Only these phases (all if empty): for profiling one of them. */
    std::set<std::string> phases;
  };

  /** One scene to measure. */
  struct SceneSpec
  {
    std::string  series;
    unsigned int dim;
    bool         kinematic;
    /** Contacting particles per direction of the bottom layer. */
    unsigned int n_side;
    /** Particle layers of the block (the bottom one in contact). */
    unsigned int layers;
    /** What the series varies: "contacting" or "far". */
    std::string varies;
  };

  std::vector<SceneSpec>
  make_scenes(const bool quick)
  {
    std::vector<SceneSpec> scenes;
    const auto             add = [&](const std::string               &series,
                         const unsigned int               dim,
                         const bool                       kinematic,
                         const std::vector<unsigned int> &n_sides,
                         const std::vector<unsigned int> &layers,
                         const std::string               &varies) {
      for (const unsigned int n : n_sides)
        for (const unsigned int l : layers)
          scenes.push_back({series, dim, kinematic, n, l, varies});
    };
    if (quick)
      {
        add("contact_2d", 2, false, {100, 1000}, {8}, "contacting");
        add("contact_3d", 3, false, {6, 12}, {4}, "contacting");
        add("kinematic_2d", 2, true, {300}, {8}, "contacting");
        add("kinematic_3d", 3, true, {10}, {4}, "contacting");
        add("far_2d", 2, false, {300}, {2, 16}, "far");
        add("far_3d", 3, false, {8}, {2, 8}, "far");
        return scenes;
      }
    add("contact_2d",
        2,
        false,
        {100, 300, 1000, 3000, 10000},
        {8},
        "contacting");
    add("contact_3d", 3, false, {10, 18, 32, 50, 71}, {4}, "contacting");
    add("kinematic_2d",
        2,
        true,
        {100, 300, 1000, 3000, 10000},
        {8},
        "contacting");
    add("kinematic_3d", 3, true, {10, 18, 32, 50, 71}, {4}, "contacting");
    add("far_2d", 2, false, {1000}, {2, 8, 32, 128, 256}, "far");
    add("far_3d", 3, false, {20}, {2, 8, 32, 128}, "far");
    return scenes;
  }

  // ------------------------------------------------------------------------
  // Timing.

  struct PhaseTiming
  {
    unsigned int calls  = 0;
    double       best   = std::numeric_limits<double>::quiet_NaN();
    double       median = std::numeric_limits<double>::quiet_NaN();
    double       mean   = std::numeric_limits<double>::quiet_NaN();
    double       total  = 0.;
    /** Median process CPU time per call (robust to time sharing). */
    double cpu_median = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * Calls @p f once untimed, then times single calls until at least
   * @p min_calls took at least @p min_seconds together.
   */
  PhaseTiming
  time_phase(const std::function<void()> &f,
             const double                 min_seconds,
             const unsigned int           min_calls)
  {
    f();
    std::vector<double> times, cpu_times;
    double              total = 0.;
    while (times.size() < min_calls || total < min_seconds)
      {
        const double cpu_start = process_cpu_seconds();
        const auto   start     = Clock::now();
        f();
        const double t = seconds_since(start);
        cpu_times.push_back(process_cpu_seconds() - cpu_start);
        times.push_back(t);
        total += t;
        if (times.size() >= 100000)
          break;
      }
    const auto median = [](std::vector<double> &v) {
      std::sort(v.begin(), v.end());
      const std::size_t n = v.size();
      return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    };
    PhaseTiming result;
    result.cpu_median = median(cpu_times);
    result.calls      = times.size();
    result.total      = total;
    result.mean       = total / times.size();
    result.median     = median(times);
    result.best       = times.front();
    return result;
  }

  // ------------------------------------------------------------------------
  // One scene.

  struct SceneResult
  {
    SceneSpec    spec;
    unsigned int particles            = 0;
    unsigned int contact_layer        = 0; // particles of the bottom layer
    unsigned int contacting           = 0; // within dhat at u
    unsigned int facet_pairs          = 0; // (particle, facet) within dhat
    unsigned int friction_pairs       = 0;
    unsigned int fem_nodes            = 0;
    unsigned int fem_boundary_facets  = 0;
    unsigned int grid_nodes           = 0; // unknown grid nodes
    unsigned int n_dofs               = 0;
    std::size_t  nnz                  = 0;
    std::size_t  contact_nnz_estimate = 0; // entries added by contact cliques
    double       ccd_queries_per_call = 0.;
    double       step_bound           = 0.;
    double       setup_seconds        = 0.;
    double       load_before = -1., load_after = -1.;
    std::map<std::string, PhaseTiming> phases;

    double
    median(const std::string &name) const
    {
      const auto it = phases.find(name);
      return it == phases.end() ? std::numeric_limits<double>::quiet_NaN()
                                : it->second.median;
    }

    double
    per_iteration() const
    {
      double sum = 0.;
      for (const std::string &name : iteration_phases)
        sum += median(name);
      return sum;
    }

    /** The quantity the series varies (for the fits). */
    double
    abscissa() const
    {
      return spec.varies == "far" ? particles : contacting;
    }
  };

  template <int dim>
  class Scene
  {
  public:
    using Layout = bfemp::ParticleLayout<dim>;

    explicit Scene(const SceneSpec &spec)
      : spec(spec)
      , random(seed + spec.n_side + 1000 * spec.layers)
      , grid(grid_parameters(spec))
      , particles(grid)
      , transfer(grid, bfemp::TransferParameters(), materials)
    {
      materials.push_back(bfemp::create_material<dim>(
        "neo-Hookean",
        bfemp::ElasticModuli::from_young_poisson(youngs_modulus,
                                                 poisson_ratio)));
      insert_particles();
      fem_bodies.push_back(
        std::make_unique<bfemp::FemBody<dim>>(box_parameters(spec),
                                              "fem body 0"));

      // P2G mass, negligible nodes dropped, unknowns numbered: as
      // ImplicitIntegrator::particles_to_grid() and number_unknowns().
      state.reinit(grid.lattice().n_nodes);
      transfer.particles_to_grid(particles, state, false);
      const double max_mass =
        *std::max_element(state.mass.begin(), state.mass.end());
      for (double &m : state.mass)
        if (!(m > 1e-12 * max_mass))
          m = 0.;
      dofs.reinit({spec.kinematic ? 0u : fem_bodies[0]->n_nodes()}, state.mass);

      contact.activation_distance          = dhat;
      contact.barrier_stiffness            = kappa;
      contact.static_friction_velocity     = static_velocity;
      contact.default_friction_coefficient = friction_mu;

      const double scale = time_step * time_step; // backward Euler
      geometry           = std::make_unique<bfemp::ContactGeometry<dim>>(grid,
                                                               particles,
                                                               fem_bodies,
                                                               dofs);
      barrier = std::make_unique<bfemp::BarrierTerm<dim>>(*geometry, contact);
      barrier->set_scale(scale);
      friction = std::make_unique<bfemp::FrictionTerm<dim>>(*barrier, contact);
      friction->set_scale(scale, time_step);
      mpm = std::make_unique<bfemp::MpmElasticityTerm<dim>>(grid,
                                                            particles,
                                                            materials,
                                                            dofs);
      mpm->set_scale(scale);
      fem = std::make_unique<bfemp::FemElasticityTerm<dim>>(fem_bodies, dofs);
      fem->set_scale(scale);

      zero.reinit(dofs.n_dofs());
      begin_step();
      friction->update(zero);

      u = random_vector(u_amplitude, u_amplitude);
      p = direction();
      build_pattern();
      // Pairs that appear between u = 0 and u join the pattern, as in
      // IncrementalPotential::hessian().
      if (barrier->couplings_missing(u, pattern) ||
          friction->couplings_missing(u, pattern))
        build_pattern();
    }

    void
    begin_step()
    {
      geometry->begin_step(time_step);
      barrier->begin_step(zero);
    }

    void
    build_pattern()
    {
      bfemp::NodeSparsity sparsity(dofs.n_nodes());
      mpm->add_couplings(sparsity);
      if (!spec.kinematic)
        fem->add_couplings(sparsity);
      barrier->add_couplings(sparsity);
      friction->add_couplings(sparsity);
      sparsity.build(dim, pattern);
      matrix.reinit(pattern);
    }

    /** Entries of a pattern of the MPM and FEM terms alone. */
    std::size_t
    pattern_without_contact() const
    {
      bfemp::NodeSparsity sparsity(dofs.n_nodes());
      mpm->add_couplings(sparsity);
      if (!spec.kinematic)
        fem->add_couplings(sparsity);
      SparsityPattern p;
      sparsity.build(dim, p);
      return p.n_nonzero_elements();
    }

    static bfemp::GridParameters<dim>
    grid_parameters(const SceneSpec &spec)
    {
      const double               width  = spec.n_side * spacing;
      const double               height = top_of_block(spec);
      bfemp::GridParameters<dim> parameters;
      for (unsigned int d = 0; d < dim; ++d)
        {
          parameters.lower_corner[d] = -double(grid_slack) * cell_size;
          parameters.upper_corner[d] =
            (std::ceil(width / cell_size) + grid_slack) * cell_size;
        }
      parameters.lower_corner[1] =
        -(std::ceil(fem_thickness / cell_size) + grid_slack) * cell_size;
      parameters.upper_corner[1] =
        (std::ceil(height / cell_size) + grid_slack) * cell_size;
      parameters.cell_size     = cell_size;
      parameters.kernel_degree = 2;
      return parameters;
    }

    static double
    top_of_block(const SceneSpec &spec)
    {
      return 0.9 * dhat + (spec.layers - 1) * spacing + 0.5 * spacing;
    }

    static bfemp::FemBodyParameters<dim>
    box_parameters(const SceneSpec &spec)
    {
      const double                  width = spec.n_side * spacing;
      bfemp::FemBodyParameters<dim> parameters;
      parameters.mesh.source = bfemp::FemMeshParameters<dim>::Source::rectangle;
      for (unsigned int d = 0; d < dim; ++d)
        {
          parameters.mesh.lower_corner[d] = -2. * fem_edge;
          parameters.mesh.upper_corner[d] = width + 2. * fem_edge;
        }
      parameters.mesh.lower_corner[1]    = -fem_thickness;
      parameters.mesh.upper_corner[1]    = 0.;
      parameters.mesh.target_edge_length = fem_edge;
      parameters.material.model          = "neo-Hookean";
      parameters.material.youngs_modulus = youngs_modulus;
      parameters.material.poisson_ratio  = poisson_ratio;
      parameters.material.density        = density;
      if (spec.kinematic)
        {
          using Motion = bfemp::PrescribedMotionParameters<dim>;
          parameters.motions.resize(1);
          parameters.motions[0].nodes  = Motion::NodeSelection::all;
          parameters.motions[0].motion = Motion::Motion::fixed;
          parameters.motions[0].where  = "fem body 0/prescribed motion";
        }
      return parameters;
    }

    double
    uniform(const double low, const double high)
    {
      return std::uniform_real_distribution<double>(low, high)(random);
    }

    void
    insert_particles()
    {
      const double            V = std::pow(spacing, dim);
      std::vector<double>     properties(Layout::n_properties, 0.);
      const ArrayView<double> q = make_array_view(properties);
      q[Layout::mass]           = density * V;
      q[Layout::rest_volume]    = V;
      Layout::set_tensor(q,
                         Layout::deformation_gradient,
                         unit_symmetric_tensor<dim>());
      q[Layout::material_id] = 0;
      q[Layout::body_id]     = 0;

      const unsigned int n_in_layer =
        dim == 2 ? spec.n_side : spec.n_side * spec.n_side;
      contact_layer = n_in_layer;
      for (unsigned int layer = 0; layer < spec.layers; ++layer)
        for (unsigned int k = 0; k < n_in_layer; ++k)
          {
            Point<dim> x;
            x[0] = ((k % spec.n_side) + 0.5 + uniform(-0.1, 0.1)) * spacing;
            if (dim == 3)
              x[dim - 1] =
                ((k / spec.n_side) + 0.5 + uniform(-0.1, 0.1)) * spacing;
            x[1] = layer == 0 ? uniform(0.2, 0.9) * dhat
                              : 0.55 * dhat + layer * spacing +
                                  uniform(-0.1, 0.1) * spacing;
            AssertThrow(grid.stencil_inside(x),
                        ExcMessage("benchmark block reaches outside the grid"));
            Layout::set_vector(q, Layout::initial_position, x);
            particles.insert(x, make_array_view(std::as_const(properties)));
          }
      particles.finish_insertion();
    }

    /** Random components in [-grid_amplitude, grid_amplitude] for grid
     * nodes and [-fem_amplitude, fem_amplitude] for FEM nodes. */
    Vector<double>
    random_vector(const double grid_amplitude, const double fem_amplitude)
    {
      Vector<double> v(dofs.n_dofs());
      for (unsigned int i = 0; i < v.size(); ++i)
        {
          const double a =
            i < dim * dofs.n_fem_nodes() ? fem_amplitude : grid_amplitude;
          v[i] = uniform(-a, a);
        }
      return v;
    }

    /**
     * The CCD direction: the block slides down onto the box, grid nodes by
     * about (0.5, -1, 0.3) dhat, FEM nodes randomly by up to 0.1 dhat.
     */
    Vector<double>
    direction()
    {
      Vector<double> v         = random_vector(0., p_fem_amplitude);
      const double   motion[3] = {0.5 * dhat, -dhat, 0.3 * dhat};
      for (unsigned int node = dofs.n_fem_nodes(); node < dofs.n_nodes();
           ++node)
        for (unsigned int d = 0; d < dim; ++d)
          v[dim * node + d] =
            motion[d == 1 ? 1 : (d == 0 ? 0 : 2)] * (1. + uniform(-0.2, 0.2));
      return v;
    }

    const SceneSpec                                    spec;
    std::mt19937                                       random;
    bfemp::BackgroundGrid<dim>                         grid;
    std::vector<std::unique_ptr<bfemp::Material<dim>>> materials;
    bfemp::ParticleSystem<dim>                         particles;
    bfemp::ParticleGridTransfer<dim>                   transfer;
    std::vector<std::unique_ptr<bfemp::FemBody<dim>>>  fem_bodies;
    bfemp::GridState<dim>                              state;
    bfemp::DofSpace<dim>                               dofs;
    bfemp::ContactParameters                           contact;
    std::unique_ptr<bfemp::ContactGeometry<dim>>       geometry;
    std::unique_ptr<bfemp::BarrierTerm<dim>>           barrier;
    std::unique_ptr<bfemp::FrictionTerm<dim>>          friction;
    std::unique_ptr<bfemp::MpmElasticityTerm<dim>>     mpm;
    std::unique_ptr<bfemp::FemElasticityTerm<dim>>     fem;
    SparsityPattern                                    pattern;
    SparseMatrix<double>                               matrix;
    Vector<double>                                     zero, u, p;
    unsigned int                                       contact_layer = 0;
  };

  volatile double sink = 0.;

  template <int dim>
  SceneResult
  run_scene(const SceneSpec &spec, const Options &options)
  {
    SceneResult result;
    result.spec        = spec;
    result.load_before = load_average();
    const auto start   = Clock::now();
    Scene<dim> scene(spec);
    result.setup_seconds = seconds_since(start);

    result.particles     = scene.particles.n_particles();
    result.contact_layer = scene.contact_layer;
    {
      const auto near    = scene.geometry->near_pairs(scene.u, dhat);
      result.contacting  = near.size();
      result.facet_pairs = near.facets.size();
    }
    result.friction_pairs       = scene.friction->n_pairs();
    result.fem_nodes            = scene.fem_bodies[0]->n_nodes();
    result.fem_boundary_facets  = scene.geometry->surface(0).facets().size();
    result.grid_nodes           = scene.dofs.n_grid_nodes();
    result.n_dofs               = scene.dofs.n_dofs();
    result.nnz                  = scene.pattern.n_nonzero_elements();
    result.contact_nnz_estimate = result.nnz - scene.pattern_without_contact();
    if (result.contacting != result.contact_layer)
      std::cout << "    note: " << result.contacting
                << " particles within dhat, the bottom layer has "
                << result.contact_layer << std::endl;
    AssertThrow(result.friction_pairs > 0,
                ExcMessage("no friction pairs: the scene is not in contact"));

    auto          &s = scene;
    Vector<double> g(s.dofs.n_dofs());
    const auto     measure = [&](const std::string           &name,
                             const std::function<void()> &f) {
      if (options.phases.empty() || options.phases.count(name) > 0)
        result.phases[name] = time_phase(f, options.seconds, options.repeats);
    };

    Vector<double> other_u = s.u;
    other_u[0] += 1e-15;
    bool       flip    = false;
    const auto trial_u = [&]() -> const Vector<double> & {
      flip = !flip;
      return flip ? other_u : s.u;
    };
    measure("near_pairs",
            [&] { sink = s.geometry->near_pairs(trial_u(), dhat).size(); });
    measure("barrier_value", [&] { sink = s.barrier->value(trial_u()); });
    sink += s.barrier->value(s.u); // the iterate's broad phase, cached
    measure("barrier_gradient", [&] { s.barrier->add_gradient(s.u, g); });
    measure("barrier_couplings_missing", [&] {
      const bool missing = s.barrier->couplings_missing(s.u, s.pattern);
      AssertThrow(!missing, ExcMessage("barrier couplings missing"));
    });
    measure("barrier_hessian", [&] {
      s.barrier->add_hessian(s.u, s.matrix, bfemp::HessianKind::projected);
    });

    s.barrier->set_obstacle_path(0., 1.);
    const unsigned long queries_before = s.geometry->n_ccd_queries();
    unsigned int        ccd_calls      = 0;
    measure("ccd_step_bound", [&] {
      result.step_bound = s.barrier->step_bound(s.u, s.p);
      ++ccd_calls;
    });
    if (ccd_calls > 0)
      result.ccd_queries_per_call =
        double(s.geometry->n_ccd_queries() - queries_before) / ccd_calls;
    s.barrier->set_obstacle_path(0., 0.);

    measure("friction_update", [&] { s.friction->update(s.u); });
    // Lagged at the step's start again, so that u slides (kinetic zone).
    s.friction->update(s.zero);
    measure("friction_value", [&] { sink = s.friction->value(s.u); });
    measure("friction_gradient", [&] { s.friction->add_gradient(s.u, g); });
    measure("friction_couplings_missing", [&] {
      const bool missing = s.friction->couplings_missing(s.u, s.pattern);
      AssertThrow(!missing, ExcMessage("friction couplings missing"));
    });
    measure("friction_hessian", [&] {
      s.friction->add_hessian(s.u, s.matrix, bfemp::HessianKind::projected);
    });

    measure("begin_step", [&] { s.begin_step(); });

    measure("mpm_gradient", [&] { s.mpm->add_gradient(s.u, g); });
    measure("mpm_hessian", [&] {
      s.mpm->add_hessian(s.u, s.matrix, bfemp::HessianKind::projected);
    });
    sink = g.l2_norm() + s.matrix.frobenius_norm();

    result.load_after = load_average();
    return result;
  }

  // ------------------------------------------------------------------------
  // Output.

  struct Fit
  {
    std::string series, phase;
    double      slope = std::numeric_limits<double>::quiet_NaN();
    double      x_min = 0., x_max = 0.;
    double      y_min = 0., y_max = 0.;
  };

  /** Least-squares slope of log y against log x over a series. */
  std::vector<Fit>
  fits(const std::vector<SceneResult> &results)
  {
    std::vector<std::string> series;
    for (const SceneResult &r : results)
      if (std::find(series.begin(), series.end(), r.spec.series) ==
          series.end())
        series.push_back(r.spec.series);
    std::vector<std::string> names = phase_names;
    names.push_back("contact_per_iteration");
    std::vector<Fit> result;
    for (const std::string &name : series)
      for (const std::string &phase : names)
        {
          std::vector<std::pair<double, double>> points;
          for (const SceneResult &r : results)
            if (r.spec.series == name)
              {
                const double y = phase == "contact_per_iteration"
                                   ? r.per_iteration()
                                   : r.median(phase);
                if (y > 0. && r.abscissa() > 0.)
                  points.emplace_back(std::log(r.abscissa()), std::log(y));
              }
          if (points.size() < 2)
            continue;
          double sx = 0., sy = 0., sxx = 0., sxy = 0.;
          for (const auto &[x, y] : points)
            {
              sx += x;
              sy += y;
              sxx += x * x;
              sxy += x * y;
            }
          const double n = points.size();
          Fit          fit;
          fit.series               = name;
          fit.phase                = phase;
          const double denominator = n * sxx - sx * sx;
          if (denominator > 0.)
            fit.slope = (n * sxy - sx * sy) / denominator;
          std::sort(points.begin(), points.end());
          fit.x_min = std::exp(points.front().first);
          fit.x_max = std::exp(points.back().first);
          fit.y_min = std::exp(points.front().second);
          fit.y_max = std::exp(points.back().second);
          result.push_back(fit);
        }
    return result;
  }

  void
  print_table(const std::vector<SceneResult> &results)
  {
    std::string series;
    for (const SceneResult &r : results)
      {
        if (r.spec.series != series)
          {
            series = r.spec.series;
            std::cout
              << "\n"
              << series << " (median per call [s] / per "
              << "contacting particle [s]):\n| contacting | particles |";
            for (const std::string &name : phase_names)
              std::cout << " " << name << " |";
            std::cout << " contact/iteration | barrier H / MPM H |\n|---|---|";
            for (unsigned int i = 0; i <= phase_names.size() + 1; ++i)
              std::cout << "---|";
            std::cout << "\n";
          }
        std::cout << "| " << r.contacting << " | " << r.particles << " |"
                  << std::scientific << std::setprecision(2);
        for (const std::string &name : phase_names)
          std::cout << " " << r.median(name) << " / "
                    << r.median(name) / r.contacting << " |";
        std::cout << " " << r.per_iteration() << " / "
                  << r.per_iteration() / r.contacting << " | " << std::fixed
                  << std::setprecision(3)
                  << r.median("barrier_hessian") / r.median("mpm_hessian")
                  << " |" << std::defaultfloat << "\n";
      }
    std::cout << std::flush;
  }

  void
  write_json(const std::string              &file,
             const Options                  &options,
             const GitState                 &git,
             const std::vector<SceneResult> &results,
             const double                    total_seconds,
             const double                    load_before,
             const double                    load_after)
  {
    char              date[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    const auto parent = std::filesystem::path(file).parent_path();
    if (!parent.empty())
      std::filesystem::create_directories(parent);

    double load_max = std::max(load_before, load_after);
    for (const SceneResult &r : results)
      load_max = std::max({load_max, r.load_before, r.load_after});

    std::ofstream out(file);
    out << std::setprecision(6);
    out
      << "{\n"
      << "  \"benchmark\": \"contact_assembly\",\n"
      << "  \"mode\": " << json_string(options.quick ? "quick" : "full")
      << ",\n"
      << "  \"machine\": {\"cpu\": " << json_string(cpu_model())
      << ", \"nproc\": " << std::thread::hardware_concurrency()
      << ", \"memory_gib\": " << json_number(memory_gib()) << "},\n"
      << "  \"threads\": " << MultithreadInfo::n_threads() << ",\n"
      << "  \"date\": " << json_string(date) << ",\n"
      << "  \"git_commit\": " << json_string(git.commit) << ",\n"
      << "  \"library_files_modified_since_commit\": "
      << json_string(git.modified) << ",\n"
      << "  \"build\": " << json_string(build_type()) << ",\n"
      << "  \"load_average_before\": " << json_number(load_before)
      << ", \"load_average_after\": " << json_number(load_after)
      << ", \"load_average_max\": " << json_number(load_max) << ",\n"
      << "  \"total_seconds\": " << json_number(total_seconds) << ",\n"
      << "  \"min_seconds_per_phase\": " << options.seconds
      << ", \"min_calls_per_phase\": " << options.repeats << ",\n"
      << "  \"scene\": {\"cell_size\": " << cell_size
      << ", \"particle_spacing\": " << spacing
      << ", \"activation_distance\": " << dhat
      << ", \"fem_target_edge_length\": " << fem_edge
      << ", \"fem_thickness\": " << fem_thickness
      << ", \"kernel\": \"quadratic B-spline\", \"youngs_modulus\": "
      << youngs_modulus << ", \"poisson_ratio\": " << poisson_ratio
      << ", \"density\": " << density << ", \"time_step\": " << time_step
      << ", \"barrier_stiffness\": " << kappa
      << ", \"friction_coefficient\": " << friction_mu
      << ", \"static_friction_velocity\": " << static_velocity
      << ", \"u_amplitude\": " << u_amplitude
      << ", \"ccd_direction\": \"grid nodes (0.5, -1, 0.3) dhat +-20 %, "
         "FEM nodes random +-0.1 dhat\"},\n"
      << "  \"notes\": \"A particle block (spacing s = dx/2) resting on an "
         "FEM box: the bottom layer within [0.2, 0.9] dhat of the top face "
         "(contacting), the other layers at least 2.5 dhat away (far). "
         "Every phase is one library call, timed call by call after one "
         "untimed call; seconds are wall times per call (best, median, "
         "mean over 'calls'; cpu_median: median process CPU seconds per "
         "call, less sensitive to other jobs on the machine); "
         "per_contacting_particle = median / "
         "contacting. contacting = particles within dhat at u "
         "(near_pairs), facet_pairs = (particle, facet) pairs within dhat. "
         "near_pairs is cached per u: near_pairs and barrier_value are "
         "timed on alternating displacements (cache misses, as line-search "
         "trials); gradient, couplings_missing and Hessian share the "
         "iterate's cached broad phase, as in the solver. "
         "contact_per_iteration = barrier value + gradient + "
         "couplings_missing + Hessian + ccd_step_bound + friction value + "
         "gradient + couplings_missing + Hessian (medians): one Newton iteration with one "
         "line-search trial; friction_update is once per friction "
         "iteration and begin_step once per time step. "
         "ratio_barrier_hessian_to_mpm_hessian and "
         "ratio_contact_iteration_to_mpm_assembly (MPM gradient + "
         "Hessian) compare with the MPM elasticity of all particles of the "
         "same scene. fits: least-squares slope of log(median seconds) "
         "against log(contacting) (contact/kinematic series) or "
         "log(particles) (far series, contacting fixed). The machine may "
         "be shared: see the load averages (per scene too).\",\n"
      << "  \"phases\": [";
    for (unsigned int i = 0; i < phase_names.size(); ++i)
      out << (i ? ", " : "") << json_string(phase_names[i]);
    out << "],\n  \"iteration_phases\": [";
    for (unsigned int i = 0; i < iteration_phases.size(); ++i)
      out << (i ? ", " : "") << json_string(iteration_phases[i]);
    out << "],\n  \"scenes\": [\n";
    for (unsigned int i = 0; i < results.size(); ++i)
      {
        const SceneResult &r = results[i];
        out << "    {\"series\": " << json_string(r.spec.series)
            << ", \"dim\": " << r.spec.dim << ", \"fem\": "
            << json_string(r.spec.kinematic ? "kinematic" : "deformable")
            << ", \"varies\": " << json_string(r.spec.varies)
            << ", \"n_side\": " << r.spec.n_side
            << ", \"layers\": " << r.spec.layers
            << ",\n     \"particles\": " << r.particles
            << ", \"contact_layer\": " << r.contact_layer
            << ", \"contacting\": " << r.contacting
            << ", \"far\": " << r.particles - r.contacting
            << ", \"facet_pairs\": " << r.facet_pairs
            << ", \"friction_pairs\": " << r.friction_pairs
            << ", \"fem_nodes\": " << r.fem_nodes
            << ", \"fem_boundary_facets\": " << r.fem_boundary_facets
            << ", \"grid_unknown_nodes\": " << r.grid_nodes
            << ", \"n_dofs\": " << r.n_dofs << ", \"nnz\": " << r.nnz
            << ", \"nnz_added_by_contact\": " << r.contact_nnz_estimate
            << ",\n     \"ccd_queries_per_call\": "
            << json_number(r.ccd_queries_per_call)
            << ", \"step_bound\": " << json_number(r.step_bound)
            << ", \"setup_seconds\": " << json_number(r.setup_seconds)
            << ", \"load_average_before\": " << json_number(r.load_before)
            << ", \"load_average_after\": " << json_number(r.load_after)
            << ",\n     \"phases\": {";
        for (unsigned int k = 0; k < phase_names.size(); ++k)
          {
            const auto        it = r.phases.find(phase_names[k]);
            const PhaseTiming t =
              it == r.phases.end() ? PhaseTiming() : it->second;
            out << (k ? ",\n       " : "\n       ")
                << json_string(phase_names[k]) << ": {\"calls\": " << t.calls
                << ", \"best\": " << json_number(t.best)
                << ", \"median\": " << json_number(t.median)
                << ", \"mean\": " << json_number(t.mean)
                << ", \"cpu_median\": " << json_number(t.cpu_median)
                << ", \"per_contacting_particle\": "
                << json_number(t.median / r.contacting) << "}";
          }
        const double mpm_assembly =
          r.median("mpm_gradient") + r.median("mpm_hessian");
        out << "},\n     \"contact_per_iteration\": "
            << json_number(r.per_iteration())
            << ", \"contact_per_iteration_per_contacting_particle\": "
            << json_number(r.per_iteration() / r.contacting)
            << ",\n     \"ratio_barrier_hessian_to_mpm_hessian\": "
            << json_number(r.median("barrier_hessian") /
                           r.median("mpm_hessian"))
            << ", \"ratio_contact_hessians_to_mpm_hessian\": "
            << json_number(
                 (r.median("barrier_hessian") + r.median("friction_hessian")) /
                 r.median("mpm_hessian"))
            << ", \"ratio_contact_iteration_to_mpm_assembly\": "
            << json_number(r.per_iteration() / mpm_assembly) << "}"
            << (i + 1 < results.size() ? "," : "") << "\n";
      }
    out << "  ],\n  \"fits\": [\n";
    const std::vector<Fit> all_fits = fits(results);
    for (unsigned int i = 0; i < all_fits.size(); ++i)
      {
        const Fit &f = all_fits[i];
        out << "    {\"series\": " << json_string(f.series)
            << ", \"phase\": " << json_string(f.phase)
            << ", \"slope\": " << json_number(f.slope)
            << ", \"x_min\": " << json_number(f.x_min)
            << ", \"x_max\": " << json_number(f.x_max)
            << ", \"median_at_x_min\": " << json_number(f.y_min)
            << ", \"median_at_x_max\": " << json_number(f.y_max) << "}"
            << (i + 1 < all_fits.size() ? "," : "") << "\n";
      }
    out << "  ]\n}\n";
  }

  void
  print_fits(const std::vector<SceneResult> &results)
  {
    std::cout << "\nlog-log slopes of the median per call (against "
                 "contacting particles; far series: against particles):\n";
    std::string series;
    for (const Fit &f : fits(results))
      {
        if (f.series != series)
          {
            series = f.series;
            std::cout << "  " << series << ":";
          }
        std::cout << " " << f.phase << " " << std::fixed << std::setprecision(2)
                  << f.slope << std::defaultfloat
                  << (f.phase == "contact_per_iteration" ? "\n" : ",");
      }
    std::cout << std::flush;
  }
} // namespace



int
main(int argc, char **argv)
{
  try
    {
      Options options;
      bool    seconds_given = false, repeats_given = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg     = argv[i];
          const bool        has_arg = i + 1 < argc;
          if (arg == "--quick")
            options.quick = true;
          else if (arg == "--output" && has_arg)
            options.output = argv[++i];
          else if (arg == "--seconds" && has_arg)
            options.seconds = std::atof(argv[++i]), seconds_given = true;
          else if (arg == "--repeats" && has_arg)
            options.repeats = std::max(1, std::atoi(argv[++i])),
            repeats_given   = true;
          else if (arg == "--threads" && has_arg)
            options.threads = std::max(1, std::atoi(argv[++i]));
          else if (arg == "--series" && has_arg)
            for (const std::string &name :
                 Utilities::split_string_list(argv[++i], ','))
              options.series.insert(name);
          else if (arg == "--size" && has_arg)
            for (const std::string &index :
                 Utilities::split_string_list(argv[++i], ','))
              options.sizes.insert(std::stoi(index));
          else if (arg == "--phases" && has_arg)
            for (const std::string &name :
                 Utilities::split_string_list(argv[++i], ','))
              {
                if (std::find(phase_names.begin(), phase_names.end(), name) ==
                    phase_names.end())
                  throw std::runtime_error("unknown phase '" + name + "'");
                options.phases.insert(name);
              }
          else
            {
              std::cerr
                << "usage: " << argv[0]
                << " [--quick] [--output FILE] [--seconds S] "
                   "[--repeats N] [--threads N] [--series "
                   "contact_2d,contact_3d,kinematic_2d,kinematic_3d,"
                   "far_2d,far_3d] [--size I,...] [--phases NAME,...]\n";
              return 1;
            }
        }
      if (options.quick && !seconds_given)
        options.seconds = 0.005;
      if (options.quick && !repeats_given)
        options.repeats = 2;
      if (options.output.empty())
        options.output = std::string(BFEMP_SOURCE_DIR) +
                         "/benchmarks/results/contact_assembly" +
                         (options.quick ? "_quick" : "") + ".json";
      MultithreadInfo::set_thread_limit(options.threads);

      std::vector<SceneSpec>              scenes;
      std::map<std::string, unsigned int> index_in_series;
      for (const SceneSpec &spec : make_scenes(options.quick))
        {
          const unsigned int index = index_in_series[spec.series]++;
          if ((options.series.empty() || options.series.count(spec.series)) &&
              (options.sizes.empty() || options.sizes.count(index)))
            scenes.push_back(spec);
        }
      if (scenes.empty())
        throw std::runtime_error("no scene selected (--series)");

      std::cout << "bfemp contact_assembly (" << cpu_model() << ", "
                << std::thread::hardware_concurrency() << " cores, "
                << MultithreadInfo::n_threads() << " threads, " << build_type()
                << " build, load average " << load_average() << ")"
                << std::endl;
      if (build_type() != "release")
        std::cout << "WARNING: not a Release build; configure with "
                     "-DCMAKE_BUILD_TYPE=Release for meaningful numbers"
                  << std::endl;

      const GitState           git         = read_git_state();
      const double             load_before = load_average();
      const auto               start       = Clock::now();
      std::vector<SceneResult> results;
      for (const SceneSpec &spec : scenes)
        {
          std::cout << spec.series << ": " << spec.n_side
                    << (spec.dim == 3 ? "^2" : "") << " contact-layer "
                    << "particles, " << spec.layers << " layers" << std::flush;
          results.push_back(spec.dim == 2 ? run_scene<2>(spec, options)
                                          : run_scene<3>(spec, options));
          const SceneResult &r = results.back();
          std::cout << ": " << r.contacting << " contacting of " << r.particles
                    << " particles, " << r.n_dofs << " dofs, setup "
                    << r.setup_seconds << " s, barrier Hessian "
                    << r.median("barrier_hessian") << " s, CCD "
                    << r.median("ccd_step_bound") << " s, MPM Hessian "
                    << r.median("mpm_hessian") << " s (load " << r.load_after
                    << ")" << std::endl;
        }
      const double total = seconds_since(start);
      print_table(results);
      print_fits(results);
      write_json(options.output,
                 options,
                 git,
                 results,
                 total,
                 load_before,
                 load_average());
      std::cout << "\nwrote " << options.output << " (total " << total << " s)"
                << std::endl;
    }
  catch (const std::exception &error)
    {
      std::cerr << "contact_assembly: " << error.what() << std::endl;
      return 1;
    }
  return 0;
}
