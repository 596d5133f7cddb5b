#ifndef bfemp_solver_mpm_elasticity_term_h
#define bfemp_solver_mpm_elasticity_term_h

#include <bfemp/cmpm/cmpm_discretization.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/dof_space.h>
#include <bfemp/solver/energy_term.h>

#include <memory>
#include <vector>

namespace bfemp
{
  /**
   * The elastic energy of the MPM particles as a function of the grid
   * displacements, 2 alpha beta dt^2 sum_p V_p^0 psi(F_p(u)) (BFEMP eq. 22),
   * with the particle deformation gradient of eq. 25 written in
   * displacements,
   * @f[
   *   F_p(u) = \Big(I + \sum_i u_i (\nabla w_{ip})^T\Big) F_p^n
   *          = F_p^n + \sum_i u_i \hat g_{ip}^T,
   *   \quad \hat g_{ip} = (F_p^n)^T \nabla w_{ip},
   * @f]
   * which equals eq. 25 because the B-spline kernels reproduce linear
   * fields (sum_i x_i grad w_ip^T = I). F_p is linear in u, so
   * dF_p/du_i = g^_ip and the Hessian blocks are
   * H_ij = s V_p^0 (dP/dF : g^_ip g^_jp), with dP/dF projected onto the
   * PSD cone per particle before the chain rule (projected Newton).
   *
   * Particles stay where they are during the Newton iterations (they move
   * in the G2P after the solve), so the kernel weights are those of the
   * step's start: begin_step() stores every particle's stencil (nodes,
   * weights, g^_ip; about 1 kB per particle in 3D with quadratic
   * B-splines) for the step's evaluations, which otherwise recompute them
   * in every energy, gradient, Hessian and line-search call.
   *
   * With cMPM (seed 002) the unknowns are coarse nodes and the map from
   * them to a particle is matrix-valued, u_p = sum_I Phi_I Q_I with
   * Phi_I = sum_k B_k p_kI (eq. 15); then
   * F_p(u) = (I + sum_I grad(Phi_I u_I)) F_p^n, still linear in u. A cMPM
   * particle is evaluated on its element's fine patch, with the fine
   * control values q = p Q as nodal values, and forces and Hessian blocks
   * are condensed with p once per element (CmpmElementAssembly). The
   * particle's energy, forces and Hessian blocks are written once, over a
   * stencil of scalar functions, for both maps.
   */
  template <int dim>
  class MpmElasticityTerm : public EnergyTerm<dim>
  {
  public:
    MpmElasticityTerm(
      const BackgroundGrid<dim>                         &grid,
      ParticleSystem<dim>                               &particles,
      const std::vector<std::unique_ptr<Material<dim>>> &materials,
      const DofSpace<dim>                               &dofs,
      const CmpmDiscretization<dim>                     *cmpm = nullptr);

    /** s = 2 alpha beta dt^2, the weight of Psi in eq. 22. */
    void
    set_scale(const double scale);

    /**
     * Stores the particles' kernel stencils at their current positions and
     * deformation gradients, with the current DofSpace numbering, for the
     * evaluations until end_step(); the particles and the numbering must
     * not change in between. Does nothing with cMPM.
     */
    void
    begin_step();

    /** Drops the stencils of begin_step(): later evaluations compute them. */
    void
    end_step();

    std::string
    name() const override;

    void
    add_couplings(NodeSparsity &sparsity) const override;

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

    /** Smallest positive root over particles of det F_p(u + t p) = 0. */
    double
    step_bound(const Vector<double> &u, const Vector<double> &p) const override;

    double
    minimum_determinant(const Vector<double> &u) const override;

    /**
     * The largest change of a particle's state along the nodal direction
     * @p p: max over particles of |sum_i w_ip p_i| and @p length |dF_p(p)|
     * (Frobenius), the displacement and the deformation gradient that G2P
     * gives the particle. The Newton increment measured on the material
     * rather than on the grid (`solver/Newton increment`).
     */
    double
    material_increment(const Vector<double> &p, const double length) const;

  private:
    /** Calls f(maker) with the stencil maker of the grid's B-spline kernel
     *  (of the grid's degree). */
    template <typename Function>
    decltype(auto)
    with_kernel(const Function &f) const;

    /**
     * cMPM: f(element, q, particles) for every element with particles,
     * q = p Q its fine control values of @p u (CmpmElementAssembly);
     * race-free for scatters to the unknowns.
     */
    template <typename Function>
    void
    for_each_element(const Vector<double> &u, const Function &f) const;

    /** cMPM: the sum over particles of f(fine stencil, q), formed element
     *  by element in a fixed order. */
    template <typename Result, typename Function>
    Result
    sum_over_elements(const Vector<double> &u, const Function &f) const;

    /** V_p^0 psi(F_p(u)), or +infinity where det F_p(u) <= 0. */
    template <typename Stencil, typename Field>
    double
    particle_energy(const Stencil &s, const Field &u) const;

    /** sink(node k, s V_p^0 P(F_p(u)) : dF_p/du_k) for the stencil's nodes. */
    template <typename Stencil, typename Field, typename Sink>
    void
    add_particle_forces(const Stencil &s,
                        const Field   &u,
                        const Sink    &sink) const;

    /** Adds every particle's blocks s V_p^0 dF:dP/dF:dF to @p cell. */
    template <typename Cell, typename Field>
    void
    add_particle_blocks(Cell             &cell,
                        const Field      &u,
                        const HessianKind kind) const;

    const BackgroundGrid<dim>                         &grid;
    ParticleSystem<dim>                               &particles;
    const std::vector<std::unique_ptr<Material<dim>>> &materials;
    const DofSpace<dim>                               &dofs;
    /** The cMPM discretization, or nullptr for the grid's kernel. */
    const CmpmDiscretization<dim> *cmpm;
    double                         scale = 1.;
    /** begin_step()'s stencils (a std::vector of the kernel's stencil type,
     *  by the particles' local index), or nullptr. */
    std::shared_ptr<const void> stencil_cache;
  };
} // namespace bfemp

#endif
