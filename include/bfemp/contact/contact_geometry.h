#ifndef bfemp_contact_contact_geometry_h
#define bfemp_contact_contact_geometry_h

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/contact/chain_rule.h>
#include <bfemp/contact/contact_surface.h>
#include <bfemp/fem/fem_body.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/dof_space.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/bounding_box.h>
#include <deal.II/lac/vector.h>

#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace bfemp
{
  /**
   * Where the two sides of the particle-mesh contact are during one implicit
   * step, as functions of the unified displacement u (DofSpace):
   *
   * - a particle moves with the grid, x_q(u) = x_q^n + sum_i w_iq u_i, the
   *   same interpolation as the G2P position update, so that dx_q/du_i =
   *   w_iq I is the chain rule of BFEMP eq. 29; with cMPM (seed 002) the
   *   unknowns are coarse nodes and x_q(u) = x_q^n + sum_I Phi_I(x_q^n) u_I,
   *   dx_q/du_I = Phi_I, the matrix-valued case of the same chain rule;
   * - a node of a deformable FEM body is x_a^n + u_a;
   * - a node of a kinematic FEM body (every node prescribed, Section 4.4)
   *   is no unknown: it follows x_a^n + s (x_a^{n+1} - x_a^n) with the
   *   obstacle progress s in [0, 1] that the Newton loop raises from 0 to 1
   *   as collision detection allows (see NewtonSolver).
   *
   * It also answers the two geometric queries of the solve: which particles
   * are within a distance of which facets (spatial hash broad phase plus
   * exact distances) and how far u may move along p, with the obstacles
   * moving along their path, before a particle touches a facet (CCD).
   */
  template <int dim>
  class ContactGeometry
  {
  public:
    /** A facet of surface @p surface. */
    struct FacetReference
    {
      unsigned int surface;
      unsigned int facet;
    };

    /** For each particle near some facet, the facets near it. */
    struct NearPairs
    {
      std::vector<unsigned int> particles;
      /** Facets of particles[k]: facets[offsets[k]] ... [offsets[k+1]). */
      std::vector<unsigned int>   offsets = {0};
      std::vector<FacetReference> facets;

      NearPairs &
      operator+=(const NearPairs &other);

      unsigned int
      size() const
      {
        return static_cast<unsigned int>(particles.size());
      }
    };

    ContactGeometry(const BackgroundGrid<dim>                        &grid,
                    ParticleSystem<dim>                              &particles,
                    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies,
                    const DofSpace<dim>                              &dofs,
                    const CmpmDiscretization<dim> *cmpm = nullptr);

    /**
     * Takes the particles and FEM nodes at the start of the step; kinematic
     * bodies' end positions are their prescribed positions at @p end_time.
     * The obstacle progress is reset to 0.
     */
    void
    begin_step(const double end_time);

    /**
     * Kinematic nodes sit at progress @p from; time_of_impact() moves them
     * on to @p to along with u + t p.
     */
    void
    set_obstacle_path(const double from, const double to);

    double
    obstacle_progress() const;

    unsigned int
    n_particles() const;

    Point<dim>
    particle_position(const unsigned int q, const Vector<double> &u) const;

    /** sum_i w_iq v_i (sum_I Phi_Iq v_I with cMPM): the particle's share
     *  of a grid vector. */
    Tensor<1, dim>
    particle_interpolation(const unsigned int q, const Vector<double> &v) const;

    /**
     * The unknowns particle @p q moves with. Available for the particles
     * near_pairs() returned (cMPM gathers the stencils of the particles
     * that can reach the FEM surfaces only; the B-spline kernel has them
     * all).
     */
    ArrayView<const unsigned int>
    stencil_nodes(const unsigned int q) const;

    /** Adds particle @p q's unknowns with their factors dx_q/du_i
     *  (w_iq I or Phi_Iq) to @p rule as block @p block. */
    void
    add_particle_stencil(ChainRule<dim>    &rule,
                         const unsigned int q,
                         const unsigned int block) const;

    /**
     * omega_q of eq. 28: the largest cross-section of a sphere of the
     * particle's rest volume, 2 sqrt(V/pi) in 2D, pi (3V/(4pi))^(2/3) in 3D.
     */
    double
    particle_weight(const unsigned int q) const;

    unsigned int
    particle_body(const unsigned int q) const;

    unsigned int
    n_surfaces() const;

    const ContactSurface<dim> &
    surface(const unsigned int s) const;

    bool
    is_kinematic(const unsigned int s) const;

    /** Unified node of local node @p a of surface @p s, or invalid. */
    unsigned int
    node_dof(const unsigned int s, const unsigned int a) const;

    /** Position of local node @p a of surface @p s at u. */
    Point<dim>
    node_position(const unsigned int    s,
                  const unsigned int    a,
                  const Vector<double> &u) const;

    /** x_a(u) - x_a^n. */
    Tensor<1, dim>
    node_displacement(const unsigned int    s,
                      const unsigned int    a,
                      const Vector<double> &u) const;

    /**
     * Positions at u of every node of every surface's mesh (boundary nodes
     * only are filled; obstacles at the path's start).
     */
    std::vector<std::vector<Point<dim>>>
    surface_positions(const Vector<double> &u) const;

    /** Particles within @p distance of facets at u, with those facets. */
    NearPairs
    near_pairs(const Vector<double> &u, const double distance) const;

    /**
     * A fraction t such that no particle touches a facet on the way from u
     * to u + t p (obstacles moving from their path's start to its end as t
     * goes from 0 to 1), conservative, or +inf if nothing is hit before
     * t = 1. Counts the queries.
     */
    double
    time_of_impact(const Vector<double> &u, const Vector<double> &p) const;

    /** Smallest particle-facet distance at u (+inf if none within reach). */
    double
    minimum_distance(const Vector<double> &u, const double reach) const;

    /**
     * Particles inside an FEM element at u: an unsigned distance cannot see
     * a particle that crossed a boundary, this can (invariant checks and
     * the input check at t = 0).
     */
    unsigned int
    particles_inside(const Vector<double> &u) const;

    /**
     * The (MPM body, FEM body) pairs with a particle of the first inside an
     * element of the second at u: what the input check at t = 0 names.
     */
    std::set<std::pair<unsigned int, unsigned int>>
    overlapping_bodies(const Vector<double> &u) const;

    /** CCD pair tests since construction. */
    unsigned long
    n_ccd_queries() const;

  private:
    /** The particles' start positions, weights and bodies; no stencils. */
    void
    gather_particles();

    /** The B-spline kernel's stencils of every particle. */
    template <int degree>
    void
    gather_kernel_stencils();

    /**
     * Makes sure every particle whose start lies in @p reachable has its
     * stencil. The B-spline kernel's are all there; cMPM gathers Phi at
     * the particles in the region (and a coarse element around it) on
     * demand: evaluating Phi costs microseconds per particle, and most
     * particles of a scene never come near an FEM surface. Called from the
     * serial start of the queries, never from their threads.
     */
    void
    gather_stencils(const BoundingBox<dim> &reachable) const;

    /**
     * C such that |x_q(u) - x_q^n| <= C sqrt(dim) |u|_inf for every
     * particle: 1 for the B-spline kernels (weights >= 0 summing to at most
     * one), the largest row sum of the fine control matrices for cMPM.
     */
    double
    interpolation_bound() const;

    /** For every particle the FEM body with an element containing it at u,
     *  or numbers::invalid_unsigned_int. */
    std::vector<unsigned int>
    containing_bodies(const Vector<double> &u) const;

    /** Motion of every surface node along p (obstacles: to - from). */
    std::vector<std::vector<Tensor<1, dim>>>
    surface_motions(const Vector<double> &p) const;

    const BackgroundGrid<dim>                        &grid;
    ParticleSystem<dim>                              &particles;
    const std::vector<std::unique_ptr<FemBody<dim>>> &bodies;
    const DofSpace<dim>                              &dofs;

    std::vector<ContactSurface<dim>> surfaces;
    std::vector<bool>                kinematic;

    const CmpmDiscretization<dim> *cmpm;

    static constexpr std::size_t no_stencil =
      std::numeric_limits<std::size_t>::max();

    std::vector<Point<dim>> start_positions;
    /** Particle q's stencil: entries stencil_start[q] ... + length[q] of
     *  the lists (no_stencil: not gathered yet). */
    mutable std::vector<std::size_t>  stencil_start;
    mutable std::vector<unsigned int> stencil_length;
    mutable std::vector<unsigned int> stencil_node_list;
    /** B-spline kernel: w_iq. */
    std::vector<double> stencil_weight_list;
    /** cMPM: Phi_Iq. */
    mutable std::vector<Tensor<2, dim>> stencil_matrix_list;
    /** cMPM: the region whose particles have their stencils. */
    mutable std::optional<BoundingBox<dim>> gathered_region;
    std::vector<double>                     weights;
    std::vector<unsigned int>               body_ids;

    std::vector<std::vector<Point<dim>>> node_start;
    std::vector<std::vector<Point<dim>>> node_end;
    double                               progress_from = 0.;
    double                               progress_to   = 0.;

    mutable unsigned long ccd_queries = 0;

    /** The last near_pairs() answer and what it was asked. */
    struct NearPairsCache
    {
      bool           valid    = false;
      double         distance = 0.;
      double         progress = 0.;
      Vector<double> u;
      NearPairs      near;
    };
    mutable NearPairsCache cache;
  };
} // namespace bfemp

#endif
