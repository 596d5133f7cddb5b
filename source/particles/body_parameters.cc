#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/particles/body_parameters.h>

namespace bfemp
{
  template <int dim>
  void
  BodyParameters<dim>::declare_parameters(ParameterHandler  &prm,
                                          const unsigned int n_primitives)
  {
    using namespace parameter_tools;
    prm.declare_entry("number of primitives",
                      "1",
                      Patterns::Integer(1),
                      "[-] Number of 'primitive j' subsections (j = 0, 1, "
                      "...) whose union/difference is the body's shape.");
    prm.declare_entry("particles per cell",
                      "2",
                      Patterns::Integer(1, 10),
                      "[-] Particles per grid cell and direction (2 gives 4 "
                      "per cell in 2D, 8 in 3D).");
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
    declare_point<dim>(prm,
                       "initial velocity",
                       components<dim>(0, 0, 0),
                       "[m/s] Initial velocity of every particle");
    MaterialParameters::declare_parameters(prm);
    for (unsigned int j = 0; j < n_primitives; ++j)
      {
        prm.enter_subsection(numbered("primitive", j));
        ShapePrimitive<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
  }



  template <int dim>
  unsigned int
  BodyParameters<dim>::parse_number_of_primitives(ParameterHandler &prm)
  {
    return prm.get_integer("number of primitives");
  }



  template <int dim>
  void
  BodyParameters<dim>::parse_parameters(ParameterHandler  &prm,
                                        const std::string &where)
  {
    using namespace parameter_tools;
    particles_per_direction = prm.get_integer("particles per cell");
    jittered                = prm.get("sampling") == "jittered";
    jitter_seed             = prm.get_integer("jitter seed");
    initial_velocity        = get_vector<dim>(prm, "initial velocity");
    material.parse_parameters(prm, where);

    primitives.resize(prm.get_integer("number of primitives"));
    for (unsigned int j = 0; j < primitives.size(); ++j)
      {
        prm.enter_subsection(numbered("primitive", j));
        primitives[j].parse_parameters(prm,
                                       where + "/" + numbered("primitive", j));
        prm.leave_subsection();
      }
    require_input(!primitives[0].subtract,
                  where + "/primitive 0",
                  "operation",
                  "subtract",
                  "the first primitive must add material");
  }



  template struct BodyParameters<2>;
  template struct BodyParameters<3>;
} // namespace bfemp
