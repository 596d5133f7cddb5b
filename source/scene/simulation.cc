#include <bfemp/base/blas_threads.h>
#include <bfemp/base/input_error.h>
#include <bfemp/base/stop_signals.h>
#include <bfemp/particles/body_sampler.h>
#include <bfemp/particles/shape.h>
#include <bfemp/scene/simulation.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <regex>
#include <sstream>

namespace bfemp
{
  template <int dim>
  Simulation<dim>::Simulation(const SceneParameters<dim> &parameters,
                              const std::string          &parameter_file,
                              std::ostream               &console)
    : parameters(parameters)
    , parameter_file(parameter_file)
    , console(console)
    , grid(parameters.grid)
    , particle_system(grid)
    , transfer(grid, parameters.transfer, materials)
  {
    if (parameters.run.threads > 0)
      MultithreadInfo::set_thread_limit(parameters.run.threads);
    BlasThreads::configure(parameters.run.blas_threads, parameters.run.threads);
    for (const auto &body : parameters.bodies)
      {
        first_material.push_back(materials.size());
        for (const MaterialParameters *material : body.all_materials())
          {
            materials.push_back(
              create_material<dim>(material->model, material->moduli()));
            material_densities.push_back(material->density);
          }
      }
    create_fem_bodies();
    create_bodies();
    create_integrator();
  }



  template <int dim>
  void
  Simulation<dim>::create_integrator()
  {
    // The one place that maps 'time/integrator' (and the scene: FEM bodies,
    // cMPM) to a TimeIntegrator; the time loop only sees the interface.
    const TimeParameters &time = parameters.time;
    // the bodies' surface loads (SceneParameters refused them with other
    // integrators)
    if (std::any_of(parameters.bodies.begin(),
                    parameters.bodies.end(),
                    [](const auto &body) {
                      return !body.surface_loads.empty();
                    }))
      try
        {
          particle_loads =
            std::make_unique<ParticleLoads<dim>>(parameters.bodies,
                                                 parameters.grid.cell_size,
                                                 particle_system);
        }
      catch (const InputError &error)
        {
          throw InputError(parameter_file + ": " + error.what());
        }
    if (parameters.cmpm.enabled)
      cmpm = std::make_unique<CmpmDiscretization<dim>>(grid, parameters.cmpm);
    std::unique_ptr<SubsteppedMPM<dim>> substepped;
    if (time.is_substepped())
      {
        if (time.substepping.own_macro_transfer)
          {
            TransferParameters macro = parameters.transfer;
            macro.scheme             = time.substepping.macro_transfer;
            macro_transfer =
              std::make_unique<ParticleGridTransfer<dim>>(grid,
                                                          macro,
                                                          materials);
          }
        substepped =
          std::make_unique<SubsteppedMPM<dim>>(grid,
                                               particle_system,
                                               transfer,
                                               macro_transfer ? *macro_transfer
                                                              : transfer,
                                               parameters.boundaries,
                                               parameters.gravity,
                                               time.substepping,
                                               particle_loads.get());
        // Without FEM bodies the macro step is the substeps alone; with them
        // the substeps' prediction enters the implicit contact solve below.
        if (fem_body_list.empty())
          {
            time_integrator = std::move(substepped);
            return;
          }
      }
    if (time.is_implicit() || substepped)
      {
        auto implicit =
          std::make_unique<ImplicitIntegrator<dim>>(grid,
                                                    particle_system,
                                                    macro_transfer
                                                      ? *macro_transfer
                                                      : transfer,
                                                    materials,
                                                    fem_body_list,
                                                    parameters.boundaries,
                                                    parameters.gravity,
                                                    time.implicit_scheme(),
                                                    parameters.solver,
                                                    parameters.contact,
                                                    std::move(substepped),
                                                    cmpm.get(),
                                                    particle_loads.get());
        check_bodies_apart(*implicit);
        time_integrator = std::move(implicit);
      }
    else
      time_integrator =
        std::make_unique<ExplicitMPM<dim>>(grid,
                                           particle_system,
                                           transfer,
                                           parameters.boundaries,
                                           parameters.gravity,
                                           time.integrator,
                                           particle_loads.get());
  }



  template <int dim>
  void
  Simulation<dim>::check_bodies_apart(ImplicitIntegrator<dim> &implicit) const
  {
    // Bodies must start apart (eq. 15): a particle inside an FEM mesh, or
    // on its boundary where the barrier is infinite, has no valid state.
    const unsigned int touching = implicit.particles_touching_fem();
    if (touching == 0)
      return;
    // name the bodies: those with a particle inside an element, or all when
    // particles only touch a boundary (distance 0)
    std::string which;
    for (const auto &[mpm, fem] : implicit.bodies_overlapping_fem())
      which += std::string(which.empty() ? "" : ", ") + "subsections 'body " +
               std::to_string(mpm) + "' and 'fem body " + std::to_string(fem) +
               "'";
    throw InputError(
      parameter_file + ": " +
      (which.empty() ? std::string("MPM bodies and FEM bodies") : which) +
      ": MPM bodies and FEM bodies overlap at t = 0: " +
      std::to_string(touching) +
      " particle(s) lie inside an FEM mesh or on its boundary. "
      "Bodies must start apart; a particle closer than "
      "'contact/activation distance' feels the barrier from the "
      "first step.");
  }



  template <int dim>
  void
  Simulation<dim>::create_fem_bodies()
  {
    for (unsigned int b = 0; b < parameters.fem_bodies.size(); ++b)
      fem_body_list.push_back(std::make_unique<FemBody<dim>>(
        parameters.fem_bodies[b],
        parameter_file + ": subsection 'fem body " + std::to_string(b) + "'"));
  }



  template <int dim>
  std::vector<std::unique_ptr<FemBody<dim>>> &
  Simulation<dim>::fem_bodies()
  {
    return fem_body_list;
  }



  template <int dim>
  void
  Simulation<dim>::advance(const double dt,
                           const double time,
                           const double max_speed)
  {
    if (parameters.time.is_substepped())
      last_substeps = substeps_for(dt, max_speed);
    time_integrator->step({dt, time, step + 1, last_substeps});
    if (const NewtonStatistics *newton = time_integrator->newton_statistics())
      newton_since_row += *newton;
  }



  template <int dim>
  Tensor<1, dim>
  Simulation<dim>::initial_displacement_at(const unsigned int b,
                                           const Point<dim>  &X) const
  {
    const PositionField<dim> &u     = parameters.bodies[b].initial_displacement;
    const Tensor<1, dim>      value = u.value(X);
    for (unsigned int d = 0; d < dim; ++d)
      if (!std::isfinite(value[d]))
        throw InputError(
          parameter_file + ": subsection 'body " + std::to_string(b) +
          "', entry 'initial displacement': component " + std::to_string(d) +
          " ('" + u.expressions()[d] + "') is not finite at the particle at " +
          to_input_string(X) +
          "; the expressions must be finite on the whole body");
    return value;
  }



  template <int dim>
  Tensor<2, dim>
  Simulation<dim>::initial_deformation_gradient(const unsigned int b,
                                                const Point<dim>  &X) const
  {
    // F = dx/dX = I + grad u, by differences of a thousandth of a cell
    const PositionField<dim> &u = parameters.bodies[b].initial_displacement;
    const Tensor<2, dim>      F =
      unit_symmetric_tensor<dim>() + u.gradient(X, 1e-3 * grid.lattice().dx);
    const double J = determinant(F);
    if (!(J > 0.) || !std::isfinite(F.norm()))
      throw InputError(
        parameter_file + ": subsection 'body " + std::to_string(b) +
        "', entry 'initial displacement': det(I + grad u) = " +
        to_input_string(J) + " at the particle at " + to_input_string(X) +
        "; the initial displacement must not invert or "
        "collapse the body (det F > 0 everywhere)");
    return F;
  }



  template <int dim>
  void
  Simulation<dim>::create_bodies()
  {
    using Layout = ParticleLayout<dim>;
    std::vector<std::vector<Point<dim>>> samples;
    for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
      {
        const BodyParameters<dim> &body = parameters.bodies[b];
        const std::string          where =
          parameter_file + ": subsection 'body " + std::to_string(b) + "'";
        samples.push_back(BodySampler<dim>(body, grid.lattice()).sample());
        if (samples.back().empty())
          throw InputError(where +
                           ": the shape contains no particle (it is empty, "
                           "or smaller than a sub-cell of size dx / "
                           "'particles per cell')");
        for (const Point<dim> &X : samples.back())
          {
            initial_deformation_gradient(b, X); // det F > 0 first
            const Point<dim> x = X + initial_displacement_at(b, X);
            if (!grid.stencil_inside(x))
              throw InputError(
                where + ": the body reaches outside the grid (particle at " +
                to_input_string(x) +
                (x == X ? std::string()
                        : ", displaced by 'initial displacement' from " +
                            to_input_string(X)) +
                "); every particle's kernel stencil must lie inside "
                "'grid/lower corner' .. 'grid/upper corner'");
          }
      }

    // Bodies must not overlap at t = 0 (BFEMP Section 2, eq. 15 assumes
    // disjoint undeformed domains).
    for (unsigned int a = 0; a < samples.size(); ++a)
      {
        const Shape<dim> shape(parameters.bodies[a].primitives);
        for (unsigned int b = 0; b < samples.size(); ++b)
          if (b != a)
            for (const Point<dim> &x : samples[b])
              if (shape.contains_strictly(x))
                throw InputError(
                  parameter_file + ": subsections 'body " + std::to_string(a) +
                  "' and 'body " + std::to_string(b) +
                  "': the bodies overlap at t = 0 (a particle of body " +
                  std::to_string(b) + " at " + to_input_string(x) +
                  " lies inside body " + std::to_string(a) +
                  "); bodies must start apart");
      }

    std::vector<double> properties(Layout::n_properties);
    for (unsigned int b = 0; b < samples.size(); ++b)
      {
        const BodyParameters<dim> &body = parameters.bodies[b];
        const double               volume =
          BodySampler<dim>(body, grid.lattice()).particle_volume();
        const ArrayView<double> p = make_array_view(properties);
        std::fill(properties.begin(), properties.end(), 0.);
        p[Layout::rest_volume] = volume;

        p[Layout::body_id] = b;
        for (const Point<dim> &x : samples[b])
          {
            // the body's own material or that of its region at x
            const unsigned int material =
              first_material[b] + body.material_index_at(x);
            p[Layout::material_id] = material;
            p[Layout::mass]        = material_densities[material] * volume;
            const Tensor<1, dim> v = body.initial_velocity.value(x);
            for (unsigned int d = 0; d < dim; ++d)
              if (!std::isfinite(v[d]))
                throw InputError(
                  parameter_file + ": subsection 'body " + std::to_string(b) +
                  "', entry 'initial velocity': component " +
                  std::to_string(d) + " ('" +
                  body.initial_velocity.expressions()[d] +
                  "') is not finite at the particle at " + to_input_string(x) +
                  "; the expressions must be finite on the whole body");
            Layout::set_vector(p, Layout::velocity, v);
            Layout::set_vector(p, Layout::initial_position, x);
            Layout::set_tensor(p,
                               Layout::deformation_gradient,
                               initial_deformation_gradient(b, x));
            particle_system.insert(x + initial_displacement_at(b, x), p);
          }
      }
    particle_system.finish_insertion();
  }



  template <int dim>
  double
  Simulation<dim>::cfl_time_scale(const double max_speed) const
  {
    if (parameters.time.is_implicit() || parameters.time.is_substepped())
      return grid.lattice().dx / std::max(max_speed, 1e-300);
    return explicit_time_scale(max_speed);
  }



  template <int dim>
  double
  Simulation<dim>::explicit_time_scale(const double max_speed) const
  {
    double wave_speed = 0.;
    for (unsigned int m = 0; m < materials.size(); ++m)
      wave_speed =
        std::max(wave_speed, materials[m]->p_wave_speed(material_densities[m]));
    return grid.lattice().dx / (wave_speed + max_speed);
  }



  template <int dim>
  double
  Simulation<dim>::next_time_step(const double time,
                                  const double max_speed) const
  {
    const TimeParameters &p          = parameters.time;
    const double          time_scale = cfl_time_scale(max_speed);
    double                dt         = p.adaptive
                                         ? std::min(p.cfl_number * time_scale, p.maximum_time_step)
                                         : p.time_step;
    if (end_reached(time, dt))
      return 0.;
    if (!p.is_implicit() && !p.is_substepped() &&
        dt / time_scale > p.maximum_cfl_number)
      {
        std::ostringstream message;
        message << "step " << step + 1 << ", t = " << time
                << ": the fixed time step " << dt
                << " s exceeds the explicit stability limit: its CFL number "
                   "dt (c_p + max |v_p|) / dx = "
                << dt / time_scale
                << " > 'time/maximum CFL number' = " << p.maximum_cfl_number
                << "; use a time step <= " << p.maximum_cfl_number * time_scale
                << " s or 'time step mode = CFL'";
        throw SimulationError(message.str());
      }
    // Land on the end time instead of overshooting it. A remainder within
    // round-off of dt (end times that are no binary multiple of dt) is a
    // whole step: the step keeps dt exactly, so a run that stops there and
    // is extended from its checkpoint repeats the uninterrupted run bit for
    // bit, which a last step of end - t (off by an ulp) would not. The
    // sliver of at most 1e-6 dt it leaves counts as the end (end_reached).
    const double remaining = parameters.run.end_time - time;
    if (std::abs(remaining - dt) <= 1e-6 * dt)
      return dt;
    return std::min(dt, remaining);
  }



  template <int dim>
  bool
  Simulation<dim>::end_reached(const double time, const double dt) const
  {
    return parameters.run.end_time - time <= 1e-6 * dt;
  }



  template <int dim>
  unsigned int
  Simulation<dim>::substeps_for(const double dt, const double max_speed) const
  {
    const TimeParameters::Substepping &s = parameters.time.substepping;
    const double time_scale              = explicit_time_scale(max_speed);
    if (s.substeps == 0)
      return std::max(1u,
                      static_cast<unsigned int>(
                        std::ceil(dt / (s.cfl_number * time_scale) - 1e-9)));
    const double substep_cfl = dt / s.substeps / time_scale;
    if (substep_cfl > parameters.time.maximum_cfl_number)
      {
        std::ostringstream message;
        message << "step " << step + 1 << ": the macro step " << dt
                << " s with 'time/substepping/substeps' = " << s.substeps
                << " gives substeps of CFL number dt / S (c_p + max |v_p|) / "
                   "dx = "
                << substep_cfl << " > 'time/maximum CFL number' = "
                << parameters.time.maximum_cfl_number
                << ", where explicit MPM is unstable; use at least "
                << std::ceil(dt /
                             (parameters.time.maximum_cfl_number * time_scale))
                << " substeps or 'substeps = 0' (S from 'substep CFL number')";
        throw SimulationError(message.str());
      }
    return s.substeps;
  }



  template <int dim>
  StepDiagnostics<dim>
  Simulation<dim>::diagnostics() const
  {
    StepDiagnostics<dim> d = StepDiagnostics<dim>::measure(particle_system,
                                                           materials,
                                                           transfer,
                                                           parameters.gravity);
    if (!fem_body_list.empty())
      d += StepDiagnostics<dim>::measure(fem_body_list, parameters.gravity);
    if (parameters.boundaries.has_level_sets())
      d.particles_in_level_sets =
        particle_system
          .template sum<StepDiagnostics<dim>>([&](const auto &particle) {
            StepDiagnostics<dim> inside;
            inside.particles_in_level_sets =
              parameters.boundaries.inside_level_set(particle.get_location(),
                                                     current_time)
                ? 1
                : 0;
            return inside;
          })
          .particles_in_level_sets;
    return d;
  }



  template <int dim>
  void
  Simulation<dim>::write_body_diagnostics(
    BodyDiagnosticsWriter<dim> &writer) const
  {
    std::vector<StepDiagnostics<dim>> mpm, fem;
    for (unsigned int b = 0; b < parameters.bodies.size(); ++b)
      mpm.push_back(StepDiagnostics<dim>::measure(particle_system,
                                                  materials,
                                                  transfer,
                                                  parameters.gravity,
                                                  b));
    for (const auto &body : fem_body_list)
      fem.push_back(StepDiagnostics<dim>::measure(*body, parameters.gravity));
    writer.write(step, current_time, mpm, fem);
  }



  template <int dim>
  const ParticleSystem<dim> &
  Simulation<dim>::particles() const
  {
    return particle_system;
  }



  template <int dim>
  const TimeIntegrator<dim> &
  Simulation<dim>::integrator() const
  {
    return *time_integrator;
  }



  template <int dim>
  ParticleSystem<dim> &
  Simulation<dim>::particles()
  {
    return particle_system;
  }



  template <int dim>
  void
  Simulation<dim>::check_state(const StepDiagnostics<dim> &d) const
  {
    if (!d.finite || !(d.min_J > 0.))
      {
        std::ostringstream message;
        message << "step " << step << ": the state became "
                << (!d.finite ? "non-finite (NaN or inf)"
                              : "inverted (min det F = ")
                << (d.finite ? std::to_string(d.min_J) + ")" : "")
                << "; the step is not written. Reduce the time step or the "
                   "CFL number.";
        throw SimulationError(message.str());
      }
  }



  template <int dim>
  void
  Simulation<dim>::write_snapshot(const double time)
  {
    if (particle_output)
      particle_output->write(particle_system, time, snapshot);
    if (grid_output)
      grid_output->write(time_integrator->grid_state(), time, snapshot);
    if (coarse_grid_output)
      coarse_grid_output->write(time_integrator->grid_state(), time, snapshot);
    if (fem_output)
      fem_output->write(time, snapshot);
    ++snapshot;
  }



  template <int dim>
  void
  Simulation<dim>::print_test_summary(const double                time,
                                      const StepDiagnostics<dim> &d) const
  {
    console << std::scientific << std::setprecision(6) << "t " << time
            << " E_kin " << d.kinetic_energy << " E_el " << d.elastic_energy
            << " E_grav " << d.gravitational_energy << " p";
    for (unsigned int c = 0; c < dim; ++c)
      console << ' ' << d.linear_momentum[c];
    console << " min_J " << d.min_J << std::defaultfloat << std::endl;
  }



  template <int dim>
  void
  Simulation<dim>::prepare_output_folder(const bool resuming)
  {
    parameters.output.create_folder(output_folder);
    if (resuming)
      {
        // The continued run keeps the earlier output; its parameter file
        // (which may differ, e.g. in the end time) is kept next to it.
        std::filesystem::copy_file(
          parameter_file,
          output_folder + "/input_resumed_at_step_" + std::to_string(step) +
            ".prm",
          std::filesystem::copy_options::overwrite_existing);
        return;
      }
    // Files of an earlier run in the same folder would sit next to this
    // run's series and mislead; only bfemp's own file names are removed.
    const std::regex ours(
      "(particles|grid|fem_body_[0-9]+)(_[0-9]+\\.vtu|\\.pvd)(\\.part)?|"
      "diagnostics\\.csv|bodies\\.csv|checkpoint\\.h5(\\.part)?|"
      "input_resumed_at_step_[0-9]+\\.prm");
    for (const auto &entry : std::filesystem::directory_iterator(output_folder))
      if (entry.is_regular_file() &&
          std::regex_match(entry.path().filename().string(), ours))
        std::filesystem::remove(entry.path());
    std::filesystem::copy_file(
      parameter_file,
      output_folder + "/input.prm",
      std::filesystem::copy_options::overwrite_existing);
  }



  template <int dim>
  std::string
  Simulation<dim>::scene_summary() const
  {
    std::ostringstream summary;
    summary << particle_system.n_particles() << " particles, "
            << grid.lattice().n_nodes << " grid nodes";
    if (!fem_body_list.empty())
      {
        unsigned int n_nodes = 0, n_elements = 0;
        for (const auto &body : fem_body_list)
          {
            n_nodes += body->n_nodes();
            n_elements += body->elements().size();
          }
        summary << ", " << fem_body_list.size() << " FEM bodies (" << n_nodes
                << " nodes, " << n_elements << " elements)";
      }
    return summary.str();
  }



  template <int dim>
  std::string
  Simulation<dim>::checkpoint_path() const
  {
    return output_folder + "/checkpoint.h5";
  }



  template <int dim>
  void
  Simulation<dim>::report_added_columns(
    const std::string              &file_name,
    const std::vector<std::string> &columns) const
  {
    if (columns.empty())
      return;
    console << "bfemp: " << file_name << " was written by an older bfemp; "
            << "its rows before the checkpoint hold nan in the new column(s)";
    for (unsigned int c = 0; c < columns.size(); ++c)
      console << (c == 0 ? " " : ", ") << columns[c];
    console << std::endl;
  }



  template <int dim>
  std::optional<typename CheckpointFile<dim>::Progress>
  Simulation<dim>::resume_from_checkpoint()
  {
    using Resume = CheckpointParameters::Resume;
    const CheckpointFile<dim> checkpoint(checkpoint_path());
    const Resume              resume = parameters.checkpoint.resume;
    if (resume == Resume::never ||
        (resume == Resume::if_present && !checkpoint.exists()))
      return std::nullopt;
    const std::string entry =
      parameter_file + ": subsection 'checkpoint', entry 'resume' = " +
      (resume == Resume::always ? "true" : "auto") + ": ";
    if (!checkpoint.exists())
      throw InputError(entry + "there is no checkpoint " + checkpoint.path() +
                       " to continue from ('auto' starts at t = 0 when "
                       "there is none)");
    typename CheckpointFile<dim>::Progress progress;
    try
      {
        progress = checkpoint.read(particle_system, fem_body_list);
      }
    catch (const InputError &error)
      {
        throw InputError(entry + error.what());
      }
    time_integrator->resume_friction_dissipation(progress.friction_dissipation);
    step         = progress.step;
    current_time = progress.time;
    snapshot     = progress.snapshot;
    return progress;
  }



  template <int dim>
  void
  Simulation<dim>::write_checkpoint(const double next_output,
                                    const double wall_time) const
  {
    typename CheckpointFile<dim>::Progress progress;
    progress.step        = step;
    progress.time        = current_time;
    progress.snapshot    = snapshot;
    progress.next_output = next_output;
    progress.wall_time   = wall_time;
    if (const ContactStatistics<dim> *contact =
          time_integrator->contact_statistics())
      progress.friction_dissipation = contact->accumulated_dissipation;
    CheckpointFile<dim>(checkpoint_path())
      .write(progress, particle_system, fem_body_list);
  }



  template <int dim>
  bool
  Simulation<dim>::run()
  {
    const RunParameters        &run        = parameters.run;
    const CheckpointParameters &checkpoint = parameters.checkpoint;
    output_folder      = parameters.output.directory + "/" + run.name;
    const auto resumed = resume_from_checkpoint();
    if (resumed &&
        end_reached(resumed->time,
                    parameters.time.adaptive ? parameters.time.maximum_time_step
                                             : parameters.time.time_step))
      {
        console << "bfemp: the checkpoint " << checkpoint_path()
                << " is at t = " << resumed->time
                << ", not before 'run/end time' = " << run.end_time
                << "; nothing to do (a larger end time continues the run)"
                << std::endl;
        return true;
      }
    prepare_output_folder(resumed.has_value());
    if (parameters.output.write_particles && particle_system.n_particles() > 0)
      particle_output =
        std::make_unique<ParticleOutput<dim>>(output_folder, materials);
    // cMPM's unknowns are coarse nodes: its grid output is the coarse
    // elements with their knot spans
    if (parameters.output.write_grid && particle_system.n_particles() > 0)
      {
        if (cmpm)
          coarse_grid_output =
            std::make_unique<CoarseGridOutput<dim>>(output_folder, *cmpm);
        else
          grid_output = std::make_unique<GridOutput<dim>>(output_folder, grid);
      }
    if (!fem_body_list.empty())
      fem_output =
        std::make_unique<FemOutput<dim>>(output_folder, fem_body_list);
    std::optional<unsigned int> resume_step;
    if (resumed)
      {
        resume_step = resumed->step;
        if (particle_output)
          particle_output->resume(snapshot);
        if (grid_output)
          grid_output->resume(snapshot);
        if (coarse_grid_output)
          coarse_grid_output->resume(snapshot);
        if (fem_output)
          fem_output->resume(snapshot);
      }
    const ContactStatistics<dim> *contact_state =
      time_integrator->contact_statistics();
    const bool with_contact = contact_state && contact_state->active;
    DiagnosticsWriter<dim> diagnostics_writer =
      with_contact
        ? DiagnosticsWriter<dim>(output_folder + "/diagnostics.csv",
                                 parameters.bodies.size(),
                                 parameters.fem_bodies.size(),
                                 parameters.time.is_substepped(),
                                 resume_step)
        : DiagnosticsWriter<dim>(output_folder + "/diagnostics.csv",
                                 time_integrator->newton_statistics() !=
                                   nullptr,
                                 parameters.time.is_substepped(),
                                 resume_step);
    BodyDiagnosticsWriter<dim> body_writer(output_folder + "/bodies.csv",
                                           parameters.bodies.size(),
                                           parameters.fem_bodies.size(),
                                           resume_step);
    ProgressReporter           progress(console,
                              run.end_time,
                              !run.quiet && !run.test_mode);
    if (resumed)
      progress.resume(resumed->time, resumed->wall_time);

    if (run.test_mode)
      console << "bfemp test run: " << dim << "D, " << scene_summary()
              << std::endl;
    else
      console << "bfemp: " << dim << "D, " << scene_summary() << "; output in "
              << output_folder << std::endl;
    if (!run.test_mode && time_integrator->newton_statistics() != nullptr)
      console << "bfemp: " << BlasThreads::describe() << std::endl;
    if (resumed)
      {
        console << "bfemp: continuing from " << checkpoint_path() << ": step "
                << step << ", t = " << current_time << std::endl;
        report_added_columns("diagnostics.csv",
                             diagnostics_writer.columns_added_on_resume());
        report_added_columns("bodies.csv",
                             body_writer.columns_added_on_resume());
      }

    double               time  = current_time;
    StepDiagnostics<dim> state = diagnostics();
    check_state(state);
    if (!resumed)
      {
        // the contact columns of t = 0: the barrier of bodies that start
        // within dhat (measured by the check that bodies start apart)
        diagnostics_writer.write(step,
                                 time,
                                 0.,
                                 state,
                                 progress.wall_time(),
                                 NewtonStatistics(),
                                 0,
                                 contact_state ? *contact_state
                                               : ContactStatistics<dim>());
        write_body_diagnostics(body_writer);
        write_snapshot(time);
        if (run.test_mode)
          print_test_summary(time, state);
      }

    double next_output =
      resumed ? resumed->next_output : parameters.output.interval;
    // Checkpoints are taken at steps that write a diagnostics row, where
    // nothing is pending in newton_since_row.
    double             next_checkpoint      = time + checkpoint.interval;
    double             last_checkpoint_wall = progress.wall_time();
    bool               saved_this_step      = resumed.has_value();
    const unsigned int first_step           = step;
    for (double dt = next_time_step(time, state.max_speed); dt > 0.;
         dt        = next_time_step(time, state.max_speed))
      {
               advance(dt, time, state.max_speed);
               time         = (dt == run.end_time - time) ? run.end_time : time + dt;
               current_time = time;
               ++step;
               saved_this_step = false;

               // Read once, so that a signal arriving later in this step is
               // handled consistently after the next one.
               const int  stop_signal  = StopSignals::received();
               const bool at_end       = end_reached(time, dt);
               const bool snapshot_due = time >= next_output - 1e-9 * dt || at_end;
               // A checkpoint needs a row (nothing pending in newton_since_row), so
               // a stop adds one at its step; the rows' Newton counts still sum to
               // the run's total.
               const bool row_due =
                 snapshot_due || step % parameters.output.diagnostics_interval == 0 ||
                 stop_signal != 0;
               if (row_due)
          {
                   state = diagnostics();
                   check_state(state);
                   diagnostics_writer.write(step,
                                     time,
                                     dt,
                                     state,
                                     progress.wall_time(),
                                     newton_since_row,
                                     time_integrator->n_dofs(),
                                     contact_state ? *contact_state
                                                          : ContactStatistics<dim>(),
                                     last_substeps);
                   newton_since_row = NewtonStatistics();
                   write_body_diagnostics(body_writer);
          }
        else
          // The next step's CFL check needs the current speed, not the one
          // of the last diagnosed step.
          state.max_speed =
            std::max(StepDiagnostics<dim>::measure_max_speed(particle_system),
                     StepDiagnostics<dim>::measure_max_speed(fem_body_list));
        if (snapshot_due)
          {
                   write_snapshot(time);
                   if (run.test_mode)
              print_test_summary(time, state);
            while (next_output <= time + 1e-9 * dt)
              next_output += std::max(parameters.output.interval, dt);
          }
               if (const NewtonStatistics *newton =
              time_integrator->newton_statistics())
          {
                   progress.report(step,
                            time,
                            dt,
                            newton->iterations,
                            time_integrator->n_dofs(),
                            contact_state && contact_state->active
                                     ? static_cast<int>(contact_state->pairs)
                                     : -1,
                            last_substeps);
                   if (contact_state && !contact_state->friction_converged)
              std::cerr << "bfemp: warning: step " << step
                        << ": friction not converged after "
                        << contact_state->friction_updates
                        << " updates ('contact/maximum friction "
                                  "iterations'); the step goes on with the last "
                                  "lagged friction."
                        << std::endl;
          }
               else
          progress.report(step, time, dt, last_substeps);

        const bool checkpoint_due =
                 (checkpoint.interval > 0. && time >= next_checkpoint - 1e-9 * dt) ||
                 (checkpoint.wall_time_interval > 0. &&
           progress.wall_time() - last_checkpoint_wall >=
             checkpoint.wall_time_interval);
               if (row_due && checkpoint_due)
          {
                   write_checkpoint(next_output, progress.wall_time());
                   saved_this_step      = true;
                   last_checkpoint_wall = progress.wall_time();
                   while (next_checkpoint <= time + 1e-9 * dt)
              next_checkpoint += std::max(checkpoint.interval, dt);
          }
               if (stop_signal != 0 && !at_end)
          {
                   if (!saved_this_step)
              write_checkpoint(next_output, progress.wall_time());
            report_stop(stop_signal, time);
                   return false;
          }
      }
    if (checkpoint.enabled() && !saved_this_step)
      write_checkpoint(next_output, progress.wall_time());
    if (!run.test_mode)
      {
        console << "bfemp: finished " << step - first_step << " steps";
        if (first_step > 0)
          console << " (continued from step " << first_step << ", " << step
                  << " in all)";
        console << " in " << std::fixed << std::setprecision(1)
                << progress.wall_time() << " s" << std::defaultfloat
                << std::setprecision(6) << std::endl;
      }
    return true;
  }



  template <int dim>
  void
  Simulation<dim>::report_stop(const int signal, const double time) const
  {
    console << "bfemp: stopped by " << StopSignals::name(signal)
            << " after step " << step << " (t = " << time
            << "); the checkpoint " << checkpoint_path()
            << " continues the run with 'checkpoint/resume = auto' in "
            << parameter_file << std::endl;
  }



  template class Simulation<2>;
  template class Simulation<3>;
} // namespace bfemp
