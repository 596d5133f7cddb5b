#ifndef bfemp_io_particle_output_h
#define bfemp_io_particle_output_h

#include <bfemp/io/pvd_series.h>
#include <bfemp/material/material.h>
#include <bfemp/particles/particle_system.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * The particle snapshots of a run: particles_NNNNN.vtu files (one VTK
   * vertex per particle, in particle-id order, so that a point index names
   * the same particle in every snapshot) and particles.pvd listing them with
   * their times.
   * Point data: velocity, displacement (x - X), cauchy_stress (tensor),
   * von_mises, J, mass, volume (the rest volume V_p^0), material_id, body_id.
   */
  template <int dim>
  class ParticleOutput
  {
  public:
    ParticleOutput(
      const std::string                                 &folder,
      const std::vector<std::unique_ptr<Material<dim>>> &materials);

    void
    write(const ParticleSystem<dim> &particles,
          const double               time,
          const unsigned int         snapshot);

    /** Continues the series of a checkpointed run (PvdSeries::resume()). */
    void
    resume(const unsigned int next_snapshot);

  private:
    std::string                                        folder;
    const std::vector<std::unique_ptr<Material<dim>>> &materials;
    PvdSeries                                          series;
  };
} // namespace bfemp

#endif
