#ifndef bfemp_integrator_macro_velocity_reconstruction_h
#define bfemp_integrator_macro_velocity_reconstruction_h

#include <bfemp/grid/background_grid.h>
#include <bfemp/integrator/time_parameters.h>
#include <bfemp/particles/particle_system.h>
#include <bfemp/solver/cholmod_solver.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <vector>

namespace bfemp
{
  /**
   * What a particle did over the substeps of one macro step (seed 003
   * eq. 1): the secant velocity v*_p = (x_p^{n+1,S} - x_p^n) / dt and
   * velocity gradient C*_p = (F_p^{n+1,S} (F_p^n)^-1 - I) / dt.
   */
  template <int dim>
  struct SecantTarget
  {
    Tensor<1, dim> velocity;
    Tensor<2, dim> velocity_gradient;
  };



  /**
   * The macro-step grid velocity v*_k on the grid of the step's start that
   * best reproduces the particles' secant targets (seed 003 eq. 2):
   *
   * - APIC (eq. 5): m_k v_k = sum_p m_p w_kp (v*_p + C*_p (x_k - x_p)), the
   *   lumped-mass, lambda = D closed form;
   * - least squares (eq. 4): sum_j [sum_p m_p (w_kp w_jp + lambda grad w_kp .
   *   grad w_jp)] v_j = sum_p m_p (w_kp v*_p + lambda C*_p grad w_kp), one
   *   sparse SPD system per velocity component, solved by CHOLMOD.
   *
   * Both return an affine field v*_p = a + B x_p, C*_p = B exactly: eq. 5
   * because sum_p m_p w_kp (a + B x_k) = m_k (a + B x_k); eq. 4 because the
   * B-spline basis reproduces affine functions, so v_j = a + B x_j zeroes
   * both residuals of eq. 2.
   */
  template <int dim>
  class MacroVelocityReconstruction
  {
  public:
    MacroVelocityReconstruction(const BackgroundGrid<dim>         &grid,
                                const TimeParameters::Substepping &parameters);

    /**
     * Writes the fitted grid velocity into @p velocity for every node with
     * @p mass > 0 (others get 0), from the particles at their current
     * positions x_p^n and targets[particle id]. @p mass holds the P2G masses
     * m_k at those positions.
     */
    void
    reconstruct(ParticleSystem<dim>                  &particles,
                const std::vector<SecantTarget<dim>> &targets,
                const std::vector<double>            &mass,
                std::vector<Tensor<1, dim>>          &velocity);

    /** lambda of eq. 2 [m^2]: 'least squares weight' times D. */
    double
    gradient_weight() const;

  private:
    /** Eq. 5. */
    template <int degree>
    void
    apic_closed_form(ParticleSystem<dim>                  &particles,
                     const std::vector<SecantTarget<dim>> &targets,
                     const std::vector<double>            &mass,
                     std::vector<Tensor<1, dim>>          &velocity) const;

    /** Eq. 4. */
    template <int degree>
    void
    least_squares(ParticleSystem<dim>                  &particles,
                  const std::vector<SecantTarget<dim>> &targets,
                  const std::vector<double>            &mass,
                  std::vector<Tensor<1, dim>>          &velocity);

    /** Both triangles of the node couplings through shared particles. */
    template <int degree>
    void
    make_sparsity(ParticleSystem<dim>             &particles,
                  const std::vector<unsigned int> &unknown_of_node,
                  const unsigned int               n_unknowns);

    const BackgroundGrid<dim>        &grid;
    const TimeParameters::Substepping parameters;
    SparsityPattern                   sparsity;
    SparseMatrix<double>              matrix;
    CholmodSolver                     solver;
  };
} // namespace bfemp

#endif
