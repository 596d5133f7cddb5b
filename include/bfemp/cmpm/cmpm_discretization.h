#ifndef bfemp_cmpm_cmpm_discretization_h
#define bfemp_cmpm_cmpm_discretization_h

#include <bfemp/cmpm/cmpm_parameters.h>
#include <bfemp/cmpm/coarse_grid.h>
#include <bfemp/cmpm/coarsened_shape_functions.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/transfer/transfer_parameters.h>

#include <memory>
#include <vector>

namespace bfemp
{
  /**
   * The cMPM discretization of the MPM bodies (seed 002 Section 7.2,
   * Fig. 17): the coarse mesh is the background grid itself (its cells are
   * the coarse elements, `grid/cell size` = H), the unknowns are the coarse
   * nodes, and each particle's displacement is u_p = sum_I Phi_I(x_p) Q_I
   * with the matrix-valued coarsened shape functions. One step:
   *   reinit(): the boundary-interior maps of every element holding
   *     particles, from the particles' F_p^n and materials (every step);
   *   particles_to_grid(): the coarse nodes that carry particles (mass
   *     sum_p m_p |Phi_Ip| > 0) and the momentum
   *     sum_p m_p Phi_Ip^T v_p; the inertia of the step is the consistent
   *     one over the particles (CmpmInertiaTerm), not a lumped mass;
   *   [the implicit solve on the coarse nodes]
   *   grid_to_particles(): v_p, x_p and F_p through Phi (PIC or FLIP).
   * The particle loops are those of ParticleSystem: its cells are the
   * coarse elements, and an element's coarse nodes stay within the reach
   * its stripes are built for.
   */
  template <int dim>
  class CmpmDiscretization
  {
  public:
    CmpmDiscretization(const BackgroundGrid<dim> &grid,
                       const CmpmParameters      &parameters);

    /**
     * Rebuilds the shape functions of every element with particles: with
     * the first Newton step of the local equilibrium (eq. 30), or, given
     * @p coarse_displacement (one per node of node_lattice()), with the
     * `full Newton` local solve at that displacement (Section 8.1.4).
     */
    void
    reinit(ParticleSystem<dim>                               &particles,
           const std::vector<std::unique_ptr<Material<dim>>> &materials,
           const std::vector<Tensor<1, dim>> *coarse_displacement = nullptr);

    /** Whether `cmpm/local solve` is `full Newton`. */
    bool
    full_newton() const;

    /** The most Newton iterations a full-Newton local solve of the last
     *  reinit() took (0 after a first-Newton-step reinit). */
    unsigned int
    local_iterations() const;

    /** The coarse nodes' activity mass and momentum (see the class
     *  documentation); @p state is resized. */
    void
    particles_to_grid(ParticleSystem<dim> &particles,
                      GridState<dim>      &state) const;

    /**
     * v_p (PIC, or FLIP blended with PIC), x_p += sum_I Phi_I u_I and
     * F_p <- (I + sum_I grad(Phi_I u_I)) F_p from the coarse nodes'
     * displacement, new and old velocity.
     */
    void
    grid_to_particles(ParticleSystem<dim>      &particles,
                      const GridState<dim>     &state,
                      const TransferParameters &transfer) const;

    /** Phi_I and grad Phi_I of the r coarse nodes at x. */
    void
    evaluate(const Point<dim>                   &x,
             std::vector<CoarseShapeValue<dim>> &values) const;

    /**
     * The largest CoarsenedShapeFunctions::interpolation_bound() over the
     * elements built by the last reinit(): no particle moves farther than
     * that times sqrt(dim) max_I |u_I|_inf with the coarse nodes.
     */
    double
    interpolation_bound() const;

    /** The lattice of the unknowns (coarse nodes). */
    const Lattice<dim> &
    node_lattice() const;

    const CoarseGrid<dim> &
    coarse_grid() const;

    const CoarsenedShapeFunctions<dim> &
    shape_functions() const;

  private:
    /** A coarse element: multi-index, flat index, lower corner. */
    struct Element
    {
      std::array<int, dim> index;
      std::size_t          flat = 0;
      Point<dim>           corner;
    };

    /** The element of the particles of one ParticleSystem cell. */
    template <typename ParticleRange>
    Element
    element_of(const ParticleRange &cell_particles) const;

    /** q = p Q of @p element for a field Q on the coarse node lattice. */
    void
    gather(const Element                     &element,
           const std::vector<Tensor<1, dim>> &field,
           std::vector<Tensor<1, dim>>       &fine) const;

    CoarseGrid<dim>              grid;
    CoarsenedShapeFunctions<dim> phi;
    double                       bound                = 1.;
    unsigned int                 max_local_iterations = 0;
  };
} // namespace bfemp

#endif
