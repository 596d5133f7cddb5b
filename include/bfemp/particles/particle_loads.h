#ifndef bfemp_particles_particle_loads_h
#define bfemp_particles_particle_loads_h

#include <bfemp/particles/body_parameters.h>
#include <bfemp/particles/particle_layout.h>
#include <bfemp/particles/particle_system.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The surface loads of all MPM bodies ("surface load k" of a body) as
   * forces on particles. Load k of body b acts on the particles of b whose
   * position at t = 0 lies in the layer of depth d below the chosen face
   * of b's bounding box (the box of the particles' positions at t = 0,
   * widened by half a particle spacing h = `grid/cell size` / `particles
   * per cell`, d = h unless `layer depth` says otherwise). The face's
   * total force t(time) A (A its area, its length in 2D) is spread evenly
   * over the N particles of the layer: f_p = t A / N, a uniform dead
   * traction in the particle quadrature.
   *
   * Which particles carry a load follows from their body id and position at
   * t = 0, both particle properties, so the loads keep no list of
   * particles and move with them between cells (and ranks, later).
   */
  template <int dim>
  class ParticleLoads
  {
  public:
    /**
     * Finds every load's layer and particle count. Throws InputError
     * naming the body and load if a layer holds no particle.
     */
    ParticleLoads(const std::vector<BodyParameters<dim>> &bodies,
                  const double                            cell_size,
                  const ParticleSystem<dim>              &particles);

    /** Whether no body has a surface load. */
    bool
    empty() const;

    /** Evaluates every traction at time @p t (once per step, one thread). */
    void
    set_time(const double t);

    /** The force on the particle with @p properties at the time of the
     *  last set_time() [N]. */
    Tensor<1, dim>
    force(const ArrayView<const double> &properties) const;

    /**
     * The P2G of the loads at the time of the last set_time(),
     * grid_force_i += sum_p w_ip f_p with the grid's B-spline kernel (the
     * explicit integrators' external grid force), race-free.
     */
    void
    add_to_grid(const BackgroundGrid<dim>   &grid,
                ParticleSystem<dim>         &particles,
                std::vector<Tensor<1, dim>> &grid_force) const;

    /** The particles that carry load @p k (in the order of the bodies'
     *  loads) and its face area [m^(dim-1)]. */
    unsigned int
    n_particles(const unsigned int k) const;

    double
    area(const unsigned int k) const;

  private:
    struct Load
    {
      const SurfaceLoad<dim> *parameters = nullptr;
      unsigned int            body       = 0;
      /** k of the body's 'surface load k'. */
      unsigned int index = 0;
      /** The layer: position[direction] above (upper face) or below this. */
      double         bound       = 0.;
      double         area        = 0.;
      unsigned int   n_particles = 0;
      Tensor<1, dim> force;

      bool
      carries(const Point<dim> &x) const;
    };

    std::vector<Load> loads;
  };
} // namespace bfemp

#endif
