#include <bfemp/base/input_error.h>
#include <bfemp/base/muparser_tools.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/particles/body_parameters.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdlib>

namespace bfemp
{
  template <int dim>
  void
  BodyParameters<dim>::declare_parameters(ParameterHandler &prm,
                                          const Counts     &counts)
  {
    using namespace parameter_tools;
    prm.declare_entry("number of primitives",
                      "1",
                      Patterns::Integer(1),
                      "[-] Number of 'primitive j' subsections (j = 0, 1, "
                      "...) whose union/difference is the body's shape.");
    prm.declare_entry("particles per cell",
                      "2",
                      Patterns::Integer(1, 64),
                      "[-] Particles per grid cell and direction (2 gives 4 "
                      "per cell in 2D, 8 in 3D). With cMPM the cell is a "
                      "coarse element of n - 2 knot spans per direction, so "
                      "2 per knot span is 2 (n - 2).");
    prm.declare_entry("sampling",
                      "regular",
                      Patterns::Selection("regular|jittered"),
                      "[-] regular: sub-cell centres; jittered: one random "
                      "point per sub-cell.");
    prm.declare_entry("jitter seed",
                      "1",
                      Patterns::Integer(0),
                      "[-] Seed of the jittered sampling (runs are "
                      "reproducible).");
    prm.declare_entry(
      "initial velocity",
      components<dim>(0, 0, 0),
      Patterns::Anything(),
      std::string("[m/s] Initial velocity of the particles: ") +
        std::to_string(dim) +
        " comma-separated numbers, or muParser expressions of the rest "
        "position " +
        (dim == 2 ? "x, y" : "x, y, z") +
        " (and pi), e.g. a rotating disk: -2*(y - 0.5), 2*(x - 0.5)");
    prm.declare_entry(
      "initial displacement",
      components<dim>(0, 0, 0),
      Patterns::Anything(),
      std::string("[m] Displacement u of the particles at t = 0 from the rest "
                  "position X the shape describes: ") +
        std::to_string(dim) +
        " comma-separated numbers, or muParser expressions of " +
        (dim == 2 ? "x, y" : "x, y, z") +
        " (and pi). A particle starts at X + u(X) with F = I + grad u(X) "
        "(fourth-order differences), a pre-stretched or pre-bent body at "
        "rest mass; det F must stay > 0. E.g. a bar stretched by 1 %: "
        "0.01*x, 0");
    prm.declare_entry("number of material regions",
                      "0",
                      Patterns::Integer(0),
                      "[-] Number of 'material region k' subsections (k = 0, "
                      "1, ...): regions of the body with their own material "
                      "(a heterogeneous body). Each is a primitive (its "
                      "entries as in 'primitive j') and a 'material' "
                      "subsection; they apply in order, the last containing "
                      "a particle wins, and 'operation = subtract' gives the "
                      "body's own material back inside it.");
    prm.declare_entry("number of surface loads",
                      "0",
                      Patterns::Integer(0),
                      "[-] Number of 'surface load k' subsections (k = 0, 1, "
                      "...): dead tractions on faces of the body's bounding "
                      "box, carried by the particles next to the face "
                      "(every integrator, B-spline grid and cMPM).");
    MaterialParameters::declare_parameters(prm);
    for (unsigned int j = 0; j < counts.primitives; ++j)
      {
        prm.enter_subsection(numbered("primitive", j));
        ShapePrimitive<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
    for (unsigned int k = 0; k < counts.regions; ++k)
      {
        prm.enter_subsection(numbered("material region", k));
        ShapePrimitive<dim>::declare_parameters(prm);
        MaterialParameters::declare_parameters(prm);
        prm.leave_subsection();
      }
    for (unsigned int k = 0; k < counts.loads; ++k)
      {
        prm.enter_subsection(numbered("surface load", k));
        SurfaceLoad<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
  }



  template <int dim>
  typename BodyParameters<dim>::Counts
  BodyParameters<dim>::parse_counts(ParameterHandler &prm)
  {
    Counts counts;
    counts.primitives = prm.get_integer("number of primitives");
    counts.regions    = prm.get_integer("number of material regions");
    counts.loads      = prm.get_integer("number of surface loads");
    return counts;
  }



  template <int dim>
  unsigned int
  BodyParameters<dim>::material_index_at(const Point<dim> &x) const
  {
    unsigned int index = 0;
    for (unsigned int k = 0; k < regions.size(); ++k)
      if (regions[k].shape.contains(x))
        index = regions[k].shape.subtract ? 0 : k + 1;
    return index;
  }



  template <int dim>
  std::vector<const MaterialParameters *>
  BodyParameters<dim>::all_materials() const
  {
    std::vector<const MaterialParameters *> result = {&material};
    for (const MaterialRegion &region : regions)
      result.push_back(&region.material);
    return result;
  }



  template <int dim>
  void
  BodyParameters<dim>::parse_parameters(ParameterHandler      &prm,
                                        const std::string     &where,
                                        const PrmEntryOrigins *origins)
  {
    const auto directory = [&](const std::string &subsection) {
      return origins == nullptr
               ? std::string()
               : origins->directory_of({where, subsection}, "image file");
    };
    using namespace parameter_tools;
    particles_per_direction = prm.get_integer("particles per cell");
    jittered                = prm.get("sampling") == "jittered";
    jitter_seed             = prm.get_integer("jitter seed");
    initial_velocity.parse(prm.get("initial velocity"),
                           where,
                           "initial velocity");
    initial_displacement.parse(prm.get("initial displacement"),
                               where,
                               "initial displacement");
    material.parse_parameters(prm, where);

    primitives.resize(prm.get_integer("number of primitives"));
    for (unsigned int j = 0; j < primitives.size(); ++j)
      {
        prm.enter_subsection(numbered("primitive", j));
        primitives[j].parse_parameters(prm,
                                       where + "/" + numbered("primitive", j),
                                       directory(numbered("primitive", j)));
        prm.leave_subsection();
      }
    require_input(!primitives[0].subtract,
                  where + "/primitive 0",
                  "operation",
                  "subtract",
                  "the first primitive must add material");

    regions.resize(prm.get_integer("number of material regions"));
    for (unsigned int k = 0; k < regions.size(); ++k)
      {
        const std::string name = numbered("material region", k);
        prm.enter_subsection(name);
        regions[k].shape.parse_parameters(prm,
                                          where + "/" + name,
                                          directory(name));
        regions[k].material.parse_parameters(prm, where + "/" + name);
        prm.leave_subsection();
      }

    surface_loads.resize(prm.get_integer("number of surface loads"));
    for (unsigned int k = 0; k < surface_loads.size(); ++k)
      {
        const std::string name = numbered("surface load", k);
        prm.enter_subsection(name);
        surface_loads[k].parse_parameters(prm, where + "/" + name);
        prm.leave_subsection();
      }
  }



  template struct BodyParameters<2>;
  template struct BodyParameters<3>;
} // namespace bfemp
