#ifndef bfemp_integrator_time_parameters_h
#define bfemp_integrator_time_parameters_h

#include <bfemp/transfer/transfer_parameters.h>

#include <deal.II/base/parameter_handler.h>

namespace bfemp
{
  using namespace dealii;

  /** prm subsection "time": the integrator and its time step. */
  struct TimeParameters
  {
    enum class Integrator
    {
      explicit_usl,
      explicit_usf,
      implicit_backward_euler,
      implicit_newmark,
      substepped_explicit
    };

    /**
     * subsection "time/substepping" (seed 003): S explicit substeps wrapped
     * into one macro step whose grid velocity is reconstructed on the grid
     * of the step's start.
     */
    struct Substepping
    {
      enum class Reconstruction
      {
        /** Closed form, eq. 5: the APIC transfer of (v*_p, C*_p). */
        apic,
        /** The sparse SPD system of eq. 4 with weight lambda. */
        least_squares
      };

      /** explicit_usl or explicit_usf: the update of every substep. */
      Integrator update = Integrator::explicit_usl;
      /** S; 0 chooses S from cfl_number at every macro step. */
      unsigned int   substeps       = 0;
      double         cfl_number     = 0.3;
      Reconstruction reconstruction = Reconstruction::apic;
      /** lambda / D of eq. 2, D = dx^2 / 4 (quadratic) or dx^2 / 3. */
      double least_squares_weight = 1.;
      /**
       * true: the particles leave the macro step with the reconstructed
       * secant velocity v*_k (seed 003 read literally, v^{n+1} = v*);
       * false: with the reconstruction of their end-of-substep velocities,
       * while positions and F still follow v*_k (doc/substepping.md).
       */
      bool secant_end_velocity = false;
      /** false: the macro G2P uses subsection transfer's scheme. */
      bool                       own_macro_transfer = false;
      TransferParameters::Scheme macro_transfer =
        TransferParameters::Scheme::apic;
    };

    /**
     * The (alpha, beta, gamma) of the implicit family of BFEMP eq. 21:
     * backward Euler (1, 1/2, 1) or midpoint Newmark (1/2, 1/4, 1/2).
     */
    struct ImplicitScheme
    {
      double alpha = 1.;
      double beta  = 0.5;
      double gamma = 1.;
      /**
       * Whether the contact terms (barrier, lagged friction) act at the
       * step's end only, with impulse dt f(x^{n+1}) as in backward Euler,
       * instead of entering Newmark's trapezoidal average of a^n and
       * a^{n+1}. Identical for backward Euler (gamma = 1).
       */
      bool contact_at_step_end = true;

      /** 2 alpha beta, the weight of dt^2 Psi in eq. 22. */
      double
      potential_weight() const
      {
        return 2. * alpha * beta;
      }

      /**
       * The weight of dt^2 (B + D) in eq. 22. A term that enters only
       * a^{n+1} changes v by gamma dt a^{n+1}, so the full impulse dt f
       * needs a^{n+1} = f / (gamma m), i.e. the weight 2 alpha beta / gamma.
       */
      double
      contact_weight() const
      {
        return contact_at_step_end ? potential_weight() / gamma
                                   : potential_weight();
      }
    };

    bool
    is_substepped() const
    {
      return integrator == Integrator::substepped_explicit;
    }

    bool
    is_implicit() const
    {
      return integrator == Integrator::implicit_backward_euler ||
             integrator == Integrator::implicit_newmark;
    }

    /**
     * The scheme of the chosen implicit integrator; backward Euler for the
     * macro step of the substepped one (its FEM bodies and contact solve).
     */
    ImplicitScheme
    implicit_scheme() const;

    Integrator integrator = Integrator::explicit_usl;
    /** ImplicitScheme::contact_at_step_end of Newmark steps. */
    bool newmark_contact_at_step_end = true;
    /** Fixed dt, or dt = CFL number * dx / (c_p + max |v_p|). */
    bool        adaptive           = false;
    double      time_step          = 1e-4;
    double      cfl_number         = 0.3;
    double      maximum_time_step  = 1e-2;
    double      maximum_cfl_number = 1.;
    Substepping substepping;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

  private:
    static void
    declare_substepping(ParameterHandler &prm);

    void
    parse_substepping(ParameterHandler &prm);

    void
    check_substepping() const;
  };
} // namespace bfemp

#endif
