#ifndef bfemp_particles_body_parameters_h
#define bfemp_particles_body_parameters_h

#include <bfemp/base/position_field.h>
#include <bfemp/base/prm_entry_origins.h>
#include <bfemp/material/material_parameters.h>
#include <bfemp/particles/shape_primitive.h>
#include <bfemp/particles/surface_load.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * prm subsection "body i": one MPM body, its shape (a sequence of
   * "primitive j" subsections), how it is sampled with particles, its
   * initial velocity and its material. A heterogeneous body assigns other
   * materials to regions of it ("material region k": a primitive and a
   * material, applied in order; "subtract" gives the body's own material
   * back), so that one body carries several materials (cMPM condenses
   * over them element by element).
   */
  template <int dim>
  struct BodyParameters
  {
    /** The numbers of numbered subsections (settled by a first pass). */
    struct Counts
    {
      unsigned int primitives = 1;
      unsigned int regions    = 0;
      unsigned int loads      = 0;

      bool
      operator==(const Counts &other) const
      {
        return primitives == other.primitives && regions == other.regions &&
               loads == other.loads;
      }
    };

    /** A region of the body with its own material. */
    struct MaterialRegion
    {
      ShapePrimitive<dim> shape;
      MaterialParameters  material;
    };

    std::vector<ShapePrimitive<dim>> primitives;
    std::vector<MaterialRegion>      regions;
    /** Dead tractions on faces of the body ("surface load k"). */
    std::vector<SurfaceLoad<dim>> surface_loads;
    unsigned int                  particles_per_direction = 2;
    bool                          jittered                = false;
    unsigned int                  jitter_seed             = 1;
    /** Entry "initial velocity": numbers, or muParser expressions of the
     *  rest position (x, y, z) and pi. */
    PositionField<dim> initial_velocity;
    /**
     * Entry "initial displacement" u(X): a particle sampled at rest
     * position X starts at X + u(X) with F = I + grad u(X) (a pre-stretched
     * or pre-bent body); the shape and the regions describe the rest
     * configuration.
     */
    PositionField<dim> initial_displacement;
    MaterialParameters material;

    /** Declares the entries of a body with @p counts subsections. */
    static void
    declare_parameters(ParameterHandler &prm, const Counts &counts);

    /** Reads only the counts (first pass of the reader). */
    static Counts
    parse_counts(ParameterHandler &prm);

    /**
     * The material of the body at @p x: 0 for the body's own, k + 1 for
     * 'material region k' (the last region containing x that adds).
     */
    unsigned int
    material_index_at(const Point<dim> &x) const;

    /** The body's materials: its own, then its regions'. */
    std::vector<const MaterialParameters *>
    all_materials() const;

    /** @p origins resolves relative 'image file' paths (null: the working
     *  directory). */
    void
    parse_parameters(ParameterHandler      &prm,
                     const std::string     &where,
                     const PrmEntryOrigins *origins = nullptr);
  };
} // namespace bfemp

#endif
