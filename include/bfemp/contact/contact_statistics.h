#ifndef bfemp_contact_contact_statistics_h
#define bfemp_contact_contact_statistics_h

#include <deal.II/base/tensor.h>

#include <limits>
#include <map>
#include <utility>

namespace bfemp
{
  using namespace dealii;

  /** The particle-mesh contact state after an implicit step (diagnostics). */
  template <int dim>
  struct ContactStatistics
  {
    /** Whether the scene has particle-mesh contact at all. */
    bool active = false;
    /** Particle-facet pairs within dhat. */
    unsigned int pairs = 0;
    /** Particles within dhat of some facet. */
    unsigned int particles = 0;
    /**
     * Particles inside an FEM element at the end of the step: 0 unless the
     * barrier failed (BFEMP Section 6.2 counts them).
     */
    unsigned int particles_inside = 0;
    /** Smallest particle-facet distance among those (+inf if none). */
    double minimum_distance = std::numeric_limits<double>::infinity();
    /** B of eqs. 31/32 (not scaled by the step) [J]. */
    double       barrier_energy     = 0.;
    unsigned int friction_pairs     = 0;
    unsigned int friction_updates   = 0;
    bool         friction_converged = true;
    /** Friction work of the last step and summed since the start [J]. */
    double step_dissipation        = 0.;
    double accumulated_dissipation = 0.;
    /**
     * Contact force (barrier and friction) on FEM body f from MPM body m,
     * keyed (m, f) [N].
     */
    std::map<std::pair<unsigned int, unsigned int>, Tensor<1, dim>> force;
  };
} // namespace bfemp

#endif
