#ifndef bfemp_particles_body_parameters_h
#define bfemp_particles_body_parameters_h

#include <bfemp/base/prm_entry_origins.h>
#include <bfemp/material/material_parameters.h>
#include <bfemp/particles/shape_primitive.h>

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

      bool
      operator==(const Counts &other) const
      {
        return primitives == other.primitives && regions == other.regions;
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
    unsigned int                     particles_per_direction = 2;
    bool                             jittered                = false;
    unsigned int                     jitter_seed             = 1;
    /** Entry "initial velocity" when it holds numbers only. */
    Tensor<1, dim> initial_velocity;
    /** Its components as written: numbers, or muParser expressions of the
     *  rest position (x, y, z) and pi. */
    std::vector<std::string> initial_velocity_expressions;
    MaterialParameters       material;

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

    /**
     * The initial velocity of a particle at @p x: the constant, or the
     * expressions evaluated there (not checked for NaN: the caller names
     * the file and the point).
     */
    Tensor<1, dim>
    initial_velocity_at(const Point<dim> &x) const;

  private:
    /** Reads the entry "initial velocity" (numbers or expressions). */
    void
    parse_initial_velocity(const std::string &text, const std::string &where);

    /** The parsed expressions; null when the velocity is constant. */
    std::shared_ptr<FunctionParser<dim>> velocity_function;
  };
} // namespace bfemp

#endif
