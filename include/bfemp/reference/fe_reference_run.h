#ifndef bfemp_reference_fe_reference_run_h
#define bfemp_reference_fe_reference_run_h

#include <bfemp/scene/scene_parameters.h>

#include <ostream>
#include <string>

namespace bfemp
{
  /**
   * `bfemp --fe-reference FILE.prm [CELL SIZE]`: the static linear-elastic
   * FE solution (LinearElasticReference, degree 2) of the scene's one MPM
   * body at its end time, written as the scene's particles would be: into
   * <output directory>/<run name>_fe_reference/, particles_00000.vtu at
   * t = 0 (rest) and particles_00001.vtu at the end time, with each
   * particle at X + u(X) and F = I + grad u(X), so that
   * doc/experiments/particle_error.py measures r_u and r_sigma (seed 002
   * eq. 38) of the scene's run against it; fe_reference.csv records the
   * mesh, the solver and the times.
   *
   * @p cell_size is the FE mesh's cell edge; 0 chooses the scene's finest
   * grid spacing (cMPM: the knot span s = H / (n - 2); otherwise the grid
   * cell size). Throws InputError for scenes that are not one box body
   * without FEM bodies.
   */
  template <int dim>
  void
  run_fe_reference(const SceneParameters<dim> &parameters,
                   const std::string          &parameter_file,
                   const double                cell_size,
                   std::ostream               &console);
} // namespace bfemp

#endif
