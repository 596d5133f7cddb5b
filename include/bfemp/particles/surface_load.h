#ifndef bfemp_particles_surface_load_h
#define bfemp_particles_surface_load_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * prm subsection "surface load k" of a body: a dead traction t(time)
   * [N/m^2] on one face of the body's bounding box at t = 0, carried by
   * the particles whose rest position lies within a layer below that face
   * (seed 002 Section 8 loads its cubes and beams with pressures on a face).
   * ParticleLoads spreads the face's total force evenly over those
   * particles.
   */
  template <int dim>
  struct SurfaceLoad
  {
    /** The face's normal direction (0 = x, 1 = y, 2 = z). */
    unsigned int direction = 1;
    /** Whether the face is the upper one (x+, y+, z+). */
    bool upper = true;
    /** The face as written, for messages. */
    std::string face = "y+";
    /** The layer depth [m]; 0 means one particle spacing. */
    double layer_depth = 0.;

    static void
    declare_parameters(ParameterHandler &prm);

    /** Reads and compiles the entries; throws InputError naming @p where. */
    void
    parse_parameters(ParameterHandler &prm, const std::string &where);

    /** The traction at time @p t [N/m^2]. Not thread-safe (sets the
     *  parser's time): call it once per step. */
    Tensor<1, dim>
    traction(const double t) const;

  private:
    std::shared_ptr<FunctionParser<1>> expressions;
  };
} // namespace bfemp

#endif
