#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/boundary/grid_boundaries.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace bfemp
{
  namespace
  {
    const char *wall_names[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
  }



  template <int dim>
  void
  GridBoundaries<dim>::declare_parameters(ParameterHandler  &prm,
                                          const unsigned int n_level_sets)
  {
    prm.enter_subsection("boundaries");
    prm.declare_entry("walls",
                      "all",
                      Patterns::Anything(),
                      "[-] Faces of the grid box that act as walls: 'all', "
                      "'none', or a comma-separated list of x-, x+, y-, y+, "
                      "z- and z+.");
    prm.declare_entry("wall condition",
                      "separable slip",
                      Patterns::Selection("sticky|slip|separable slip"),
                      "[-] Condition of the domain walls.");
    prm.declare_entry("wall friction",
                      "0",
                      Patterns::Double(0.),
                      "[-] Coulomb coefficient of the walls (separable slip "
                      "only).");
    prm.declare_entry("wall layers",
                      "2",
                      Patterns::Integer(1),
                      "[cells] Thickness of each wall: the grid nodes within "
                      "this many cells of the face (the face's own nodes "
                      "included) get the wall condition.");
    prm.declare_entry("number of level sets",
                      "0",
                      Patterns::Integer(0),
                      "[-] Number of 'level set i' subsections.");
    for (unsigned int i = 0; i < std::max(n_level_sets, 1u); ++i)
      {
        prm.enter_subsection(parameter_tools::numbered("level set", i));
        LevelSet<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }



  template <int dim>
  unsigned int
  GridBoundaries<dim>::parse_number_of_level_sets(ParameterHandler &prm)
  {
    prm.enter_subsection("boundaries");
    const unsigned int n = prm.get_integer("number of level sets");
    prm.leave_subsection();
    return n;
  }



  template <int dim>
  void
  GridBoundaries<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("boundaries");
    const std::string walls = prm.get("walls");
    wall_active.fill(walls == "all");
    if (walls != "all" && walls != "none")
      for (const std::string &name : Utilities::split_string_list(walls, ','))
        {
          bool known = false;
          for (unsigned int w = 0; w < 2 * dim; ++w)
            if (name == wall_names[w])
              known = wall_active[w] = true;
          require_input(known,
                        "boundaries",
                        "walls",
                        "'" + walls + "'",
                        "unknown face '" + name +
                          "'; allowed: all, none, or a list of x-, x+, y-, y+" +
                          std::string(dim == 3 ? ", z-, z+" : ""));
        }
    wall_condition.type =
      BoundaryCondition::parse_type(prm.get("wall condition"));
    wall_condition.friction = prm.get_double("wall friction");
    layers                  = prm.get_integer("wall layers");

    level_sets.resize(prm.get_integer("number of level sets"));
    for (unsigned int i = 0; i < level_sets.size(); ++i)
      {
        const std::string name = parameter_tools::numbered("level set", i);
        prm.enter_subsection(name);
        level_sets[i].parse_parameters(prm, "boundaries/" + name);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }



  template <int dim>
  template <typename Function>
  void
  GridBoundaries<dim>::for_each_condition(const Lattice<dim> &lattice,
                                          const Point<dim>   &x,
                                          const double        time,
                                          const Function     &f) const
  {
    // A wall acts within 'wall layers' cells of its face. Measured in cells
    // from the face, grid nodes sit at integers; the tolerance keeps the
    // last layer of nodes inside despite round-off.
    const Tensor<1, dim> at_rest;
    const double         tolerance = 1e-9;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double   cells = (x[d] - lattice.origin[d]) * lattice.inverse_dx;
        Tensor<1, dim> inward;
        if (wall_active[2 * d] && cells <= layers + tolerance)
          inward[d] = 1.;
        else if (wall_active[2 * d + 1] &&
                 cells >= lattice.n_cells[d] - layers - tolerance)
          inward[d] = -1.;
        if (inward.norm_square() > 0.)
          f(wall_condition, inward, at_rest);
      }
    for (const LevelSet<dim> &level_set : level_sets)
      if (level_set.value(x, time) <= 0.)
        f(level_set.condition(),
          level_set.normal(x, time),
          level_set.velocity(time));
  }



  template <int dim>
  void
  GridBoundaries<dim>::add_implicit_constraints(
    const Lattice<dim>          &lattice,
    const std::size_t            index,
    const Point<dim>            &x,
    const Tensor<1, dim>        &velocity,
    const double                 time,
    std::vector<NodeConstraint> &constraints) const
  {
    for_each_condition(
      lattice,
      x,
      time,
      [&](const BoundaryCondition &condition,
          const Tensor<1, dim>    &normal,
          const Tensor<1, dim>    &obstacle_velocity) {
        using Type = BoundaryCondition::Type;
        if (condition.type == Type::separable_slip &&
            (velocity - obstacle_velocity) * normal >= 0.)
          return;
        const Tensor<2, dim> free_projector =
          condition.type == Type::sticky
            ? Tensor<2, dim>()
            : Tensor<2, dim>(unit_symmetric_tensor<dim>()) -
                outer_product(normal, normal);
        constraints.push_back({index, free_projector, obstacle_velocity});
      });
  }



  template <int dim>
  void
  GridBoundaries<dim>::apply(const Lattice<dim>          &lattice,
                             const std::vector<double>   &mass,
                             std::vector<Tensor<1, dim>> &velocity,
                             const double                 time) const
  {
    for (std::size_t node = 0; node < mass.size(); ++node)
      if (mass[node] > 0.)
        for_each_condition(lattice,
                           lattice.node_position(node),
                           time,
                           [&](const BoundaryCondition &condition,
                               const Tensor<1, dim>    &normal,
                               const Tensor<1, dim>    &obstacle_velocity) {
                             condition.apply(velocity[node],
                                             normal,
                                             obstacle_velocity);
                           });
  }



  template <int dim>
  std::vector<typename GridBoundaries<dim>::NodeConstraint>
  GridBoundaries<dim>::implicit_constraints(
    const Lattice<dim>                &lattice,
    const std::vector<double>         &mass,
    const std::vector<Tensor<1, dim>> &velocity,
    const double                       time) const
  {
    std::vector<NodeConstraint> constraints;
    for (std::size_t node = 0; node < mass.size(); ++node)
      if (mass[node] > 0.)
        add_implicit_constraints(lattice,
                                 node,
                                 lattice.node_position(node),
                                 velocity[node],
                                 time,
                                 constraints);
    return constraints;
  }



  template <int dim>
  std::vector<typename GridBoundaries<dim>::NodeConstraint>
  GridBoundaries<dim>::implicit_constraints(
    const Lattice<dim>                &lattice,
    const std::vector<Point<dim>>     &positions,
    const std::vector<Tensor<1, dim>> &velocity,
    const double                       time) const
  {
    std::vector<NodeConstraint> constraints;
    for (std::size_t i = 0; i < positions.size(); ++i)
      add_implicit_constraints(lattice,
                               i,
                               positions[i],
                               velocity[i],
                               time,
                               constraints);
    return constraints;
  }



  template <int dim>
  bool
  GridBoundaries<dim>::any() const
  {
    return !level_sets.empty() ||
           std::find(wall_active.begin(), wall_active.end(), true) !=
             wall_active.end();
  }



  template <int dim>
  bool
  GridBoundaries<dim>::has_level_sets() const
  {
    return !level_sets.empty();
  }



  template <int dim>
  bool
  GridBoundaries<dim>::inside_level_set(const Point<dim> &x,
                                        const double      time) const
  {
    for (const LevelSet<dim> &level_set : level_sets)
      if (level_set.value(x, time) < 0.)
        return true;
    return false;
  }



  template class GridBoundaries<2>;
  template class GridBoundaries<3>;
} // namespace bfemp
