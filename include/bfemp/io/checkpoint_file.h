#ifndef bfemp_io_checkpoint_file_h
#define bfemp_io_checkpoint_file_h

#include <bfemp/fem/fem_body.h>
#include <bfemp/particles/particle_system.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * The state a run needs to continue, in one HDF5 file (deal.II's HDF5
   * wrappers): every particle (id, location, properties, in loop order),
   * every FEM body's node positions and velocities, and where the run
   * stood. Everything else a step needs (grid state, DoF numbering, contact
   * pairs, the Newmark acceleration a^n) is rebuilt from these at the next
   * step, so a continued run repeats the uninterrupted one bit for bit.
   *
   * The file is written under a temporary name, checked, and renamed, so
   * the previous checkpoint survives a crash during writing.
   */
  template <int dim>
  class CheckpointFile
  {
  public:
    /** Where the run stood when the checkpoint was taken. */
    struct Progress
    {
      unsigned int step = 0;
      double       time = 0.;
      /** Index of the next VTU snapshot. */
      unsigned int snapshot = 0;
      /** Simulated time of the next snapshot. */
      double next_output = 0.;
      /** Wall time of the run so far (all its parts). */
      double wall_time = 0.;
      /** Friction dissipation accumulated over all steps so far. */
      double friction_dissipation = 0.;
    };

    explicit CheckpointFile(const std::string &path);

    const std::string &
    path() const;

    bool
    exists() const;

    /** Saves the state; throws SimulationError if the file is not written. */
    void
    write(const Progress                                   &progress,
          const ParticleSystem<dim>                        &particles,
          const std::vector<std::unique_ptr<FemBody<dim>>> &fem_bodies) const;

    /**
     * Restores the particles and the FEM bodies' state. Throws InputError
     * naming the file if it is not a complete bfemp checkpoint of this
     * scene (dimension, particle properties, FEM meshes).
     */
    Progress
    read(ParticleSystem<dim>                        &particles,
         std::vector<std::unique_ptr<FemBody<dim>>> &fem_bodies) const;

  private:
    std::string file_path;
  };
} // namespace bfemp

#endif
