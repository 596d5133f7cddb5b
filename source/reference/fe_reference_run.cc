#include <bfemp/base/input_error.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/io/atomic_file.h>
#include <bfemp/io/particle_output.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/reference/fe_reference_run.h>
#include <bfemp/reference/linear_elastic_reference.h>
#include <bfemp/scene/simulation.h>

#include <filesystem>
#include <iomanip>

namespace bfemp
{
  namespace
  {
    /** The scene's finest grid spacing: cMPM's knot span, else the cell. */
    template <int dim>
    double
    finest_spacing(const SceneParameters<dim> &parameters)
    {
      return parameters.cmpm.enabled
               ? parameters.grid.cell_size / (parameters.cmpm.n_fine - 2.)
               : parameters.grid.cell_size;
    }
  } // namespace



  template <int dim>
  void
  run_fe_reference(const SceneParameters<dim> &parameters,
                   const std::string          &parameter_file,
                   const double                cell_size,
                   std::ostream               &console)
  {
    if (parameters.bodies.size() != 1 || !parameters.fem_bodies.empty())
      throw InputError(parameter_file +
                       ": the FE reference solves one MPM body; allowed: "
                       "'number of bodies' = 1 and no FEM bodies");
    // the particles, sampled and checked as the scene's run samples them
    Simulation<dim>           simulation(parameters, parameter_file, console);
    const BackgroundGrid<dim> grid(parameters.grid);
    const double h    = cell_size > 0. ? cell_size : finest_spacing(parameters);
    const double time = parameters.run.end_time;

    LinearElasticReference<dim> reference(parameters.bodies[0],
                                          parameters.boundaries,
                                          grid.lattice(),
                                          parameters.gravity,
                                          time,
                                          h,
                                          2,
                                          parameter_file +
                                            ": subsection 'body 0'");
    const auto                  statistics = reference.solve();

    // u and grad u at every particle's rest position, in the handler's order
    using Layout                      = ParticleLayout<dim>;
    ParticleSystem<dim>    &particles = simulation.particles();
    auto                   &handler   = particles.handler();
    std::vector<Point<dim>> X;
    X.reserve(particles.n_particles());
    for (const auto &particle : handler)
      X.emplace_back(Layout::get_vector(particle.get_properties(),
                                        Layout::initial_position));
    const std::vector<Tensor<1, dim>> u = reference.displacements(X);
    const std::vector<Tensor<2, dim>> grad_u =
      reference.displacement_gradients(X);

    // the same materials, in the same order, as the scene's run
    std::vector<std::unique_ptr<Material<dim>>> materials;
    for (const MaterialParameters *material :
         parameters.bodies[0].all_materials())
      materials.push_back(
        create_material<dim>(material->model, material->moduli()));

    const std::string folder =
      parameters.output.directory + "/" + parameters.run.name + "_fe_reference";
    // an earlier benchmark's files go; failures show in create_folder
    std::error_code ignored;
    std::filesystem::remove_all(folder, ignored);
    parameters.output.create_folder(folder);
    ParticleOutput<dim> output(folder, materials);
    output.write(particles, 0., 0);
    const Tensor<2, dim> identity = unit_symmetric_tensor<dim>();
    std::size_t          i        = 0;
    for (auto &particle : handler)
      {
        const ArrayView<double> p = particle.get_properties();
        particle.set_location(X[i] + u[i]);
        Layout::set_tensor(p,
                           Layout::deformation_gradient,
                           identity + grad_u[i]);
        for (unsigned int d = 0; d < dim; ++d)
          p[Layout::velocity + d] = 0.;
        ++i;
      }
    output.write(particles, time, 1);

    write_file_atomically(folder + "/fe_reference.csv", [&](std::ostream &out) {
      out << "cells,dofs,constrained_dofs,degree,cell_size,solver,"
             "iterations,assembly_seconds,solve_seconds,max_displacement,"
             "time\n"
          << std::setprecision(12) << statistics.n_cells << ','
          << statistics.n_dofs << ',' << statistics.n_constrained << ",2," << h
          << ',' << statistics.solver << ',' << statistics.iterations << ','
          << statistics.assembly_seconds << ',' << statistics.solve_seconds
          << ',' << statistics.max_displacement << ',' << time << '\n';
    });
    console << "bfemp: FE reference of " << parameter_file << ": "
            << statistics.n_cells << " cells of " << h << " m, FE_Q(2)^" << dim
            << ", " << statistics.n_dofs << " unknowns ("
            << statistics.n_constrained << " held by the walls), "
            << statistics.solver
            << (statistics.iterations > 0
                  ? " in " + std::to_string(statistics.iterations) +
                      " iterations"
                  : std::string())
            << "; assembly " << statistics.assembly_seconds << " s, solve "
            << statistics.solve_seconds << " s; max |u_i| "
            << statistics.max_displacement << " m; written to " << folder << "/"
            << std::endl;
  }



  template void
  run_fe_reference<2>(const SceneParameters<2> &,
                      const std::string &,
                      const double,
                      std::ostream &);
  template void
  run_fe_reference<3>(const SceneParameters<3> &,
                      const std::string &,
                      const double,
                      std::ostream &);
} // namespace bfemp
