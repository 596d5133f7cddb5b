#ifndef bfemp_contact_barrier_term_h
#define bfemp_contact_barrier_term_h

#include <bfemp/contact/contact_geometry.h>
#include <bfemp/contact/contact_parameters.h>
#include <bfemp/solver/energy_term.h>

#include <deal.II/lac/full_matrix.h>

#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace bfemp
{
  /**
   * The particle-mesh barrier potential of BFEMP, scaled by the incremental
   * potential's weight s = 2 alpha beta dt^2 (eq. 33):
   * @f[
   *   s B(u) = s \sum_q \omega_q \Big( \sum_{f} b(d(x_q, f))
   *          - \sum_{k} c_k\, b(d(x_q, \cdot_k)) \Big),
   * @f]
   * facets f (2D edges, 3D triangles) with the duplicate subtraction of
   * eq. 31 (2D) and eq. 32 (3D) over vertices and edges (ContactSurface),
   * b of eq. 27 evaluated on squared distances (barrier.h).
   *
   * Each particle's terms form one local stencil: the particle and the FEM
   * nodes of the primitives within dhat. Its local Hessian (the subtracted
   * terms included, which is what makes them harmless) is projected onto
   * the PSD cone unless the exact Hessian is asked for, then carried to the
   * unknowns by the chain rule of eq. 29 (ChainRule), dx_q/du_i = w_iq I for
   * grid nodes (Phi_iq for cMPM's coarse nodes) and the identity for FEM
   * nodes. Kinematic (fully prescribed) FEM bodies
   * contribute positions only.
   *
   * The step bound is collision detection along u + t p (ContactGeometry);
   * the Hessian's couplings follow the particles within dhat and grow
   * during a step as new pairs appear.
   */
  template <int dim>
  class BarrierTerm : public EnergyTerm<dim>
  {
  public:
    /** One particle's contact with the FEM surfaces. */
    struct ParticleContact
    {
      unsigned int particle = 0;
      /** FEM nodes of the stencil, (surface, local node); local node k + 1. */
      std::vector<std::pair<unsigned int, unsigned int>> nodes;
      /** omega_q sum c b (unscaled). */
      double energy = 0.;
      /** d/d(x_q, x_nodes) of energy, (1 + nodes.size()) dim entries. */
      Vector<double> gradient;
      /** The local Hessian of that kind (only if asked for). */
      FullMatrix<double> hessian;
      /** The distance to the nearest facet. */
      double distance = 0.;

      /** The particle's contact with one surface. */
      struct SurfaceContact
      {
        unsigned int surface;
        /** Barrier force on the particle from the surface, -dB_s/dx_q. */
        Tensor<1, dim> force;
        /** The surface's facet nearest to the particle. */
        unsigned int nearest_facet;
        double       nearest_squared_distance;
      };
      std::vector<SurfaceContact> surfaces;
    };

    /** What the diagnostics report of the contact state at u. */
    struct Measurement
    {
      unsigned int pairs            = 0;
      unsigned int particles        = 0;
      double       minimum_distance = 0.;
      /** Unscaled B. */
      double energy = 0.;
      /** Force on FEM body f from MPM body m, keyed (m, f). */
      std::map<std::pair<unsigned int, unsigned int>, Tensor<1, dim>> force;
    };

    BarrierTerm(ContactGeometry<dim>    &geometry,
                const ContactParameters &parameters);

    void
    set_scale(const double scale);

    /** Forgets the couplings of the last step, registers the pairs near now. */
    void
    begin_step(const Vector<double> &u);

    std::string
    name() const override;

    bool
    is_contact() const override;

    void
    add_couplings(NodeSparsity &sparsity) const override;

    bool
    couplings_missing(const Vector<double>  &u,
                      const SparsityPattern &pattern) const override;

    double
    value(const Vector<double> &u) const override;

    double
    magnitude() const override;

    void
    add_gradient(const Vector<double> &u,
                 Vector<double>       &gradient) const override;

    void
    add_hessian(const Vector<double> &u,
                SparseMatrix<double> &hessian,
                const HessianKind     kind) const override;

    double
    step_bound(const Vector<double> &u, const Vector<double> &p) const override;

    void
    set_obstacle_path(const double from, const double to) const override;

    /** 0 if a particle is inside an FEM element, else the least distance. */
    double
    minimum_distance(const Vector<double> &u) const override;

    /**
     * The contact of every particle within dhat at u, with local Hessians of
     * kind @p hessian if one is given.
     */
    std::vector<ParticleContact>
    contacts(const Vector<double>             &u,
             const std::optional<HessianKind> &hessian = {}) const;

    Measurement
    measure(const Vector<double> &u) const;

    /**
     * Records that the Hessian couples @p particle's stencil with the FEM
     * unknowns @p fem_nodes (invalid entries are skipped); returns true if
     * that is new, so the pattern must grow. Friction registers its pairs
     * here too: one registry for all contact couplings.
     */
    bool
    register_couplings(const unsigned int               particle,
                       const std::vector<unsigned int> &fem_nodes) const;

    const ContactGeometry<dim> &
    geometry() const;

  private:
    ParticleContact
    evaluate(const typename ContactGeometry<dim>::NearPairs &near,
             const unsigned int                              k,
             const std::vector<std::vector<Point<dim>>>     &x,
             const Vector<double>                           &u,
             const std::optional<HessianKind>               &hessian) const;

    /** The unknowns of a contact with the factors of eq. 29. */
    void
    chain_rule(const ParticleContact &contact, ChainRule<dim> &rule) const;

    ContactGeometry<dim>    &contact_geometry;
    const ContactParameters &parameters;
    double                   scale = 1.;
    /** FEM unified nodes coupled to each particle in the pattern. */
    mutable std::vector<std::vector<unsigned int>> registered;
    /**
     * Particles whose grid stencil is a clique of the pattern. MPM
     * elasticity couples a stencil anyway, but without it (substepped MPM)
     * a particle touching only a kinematic FEM body registers no FEM node,
     * and its barrier Hessian still couples its stencil nodes.
     */
    mutable std::vector<bool> stencil_registered;
    mutable double            last_magnitude = 0.;
  };
} // namespace bfemp

#endif
