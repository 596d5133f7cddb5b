#ifndef bfemp_boundary_grid_boundaries_h
#define bfemp_boundary_grid_boundaries_h

#include <bfemp/boundary/boundary_condition.h>
#include <bfemp/boundary/level_set.h>
#include <bfemp/grid/lattice.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <vector>

namespace bfemp
{
  /**
   * prm subsection "boundaries": the conditions the background grid imposes
   * on node velocities, i.e. domain walls (layers of nodes at the faces of
   * the grid box) and analytic level-set obstacles.
   */
  template <int dim>
  class GridBoundaries
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, const unsigned int n_level_sets);

    /** Reads only "number of level sets" (first pass of the reader). */
    static unsigned int
    parse_number_of_level_sets(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Applies every condition to the velocities of the nodes with mass > 0.
     * Walls act first, level sets after, in prm order.
     */
    void
    apply(const Lattice<dim>          &lattice,
          const std::vector<double>   &mass,
          std::vector<Tensor<1, dim>> &velocity,
          const double                 time) const;


    /** A condition on one node in the implicit solve. */
    struct NodeConstraint
    {
      std::size_t    node;
      Tensor<2, dim> free_projector;
      Tensor<1, dim> obstacle_velocity;
    };

    /**
     * The conditions as constraints of the implicit solve (DofSpace), for
     * the nodes with mass > 0 at the end of the step, @p time: sticky nodes
     * move with the obstacle (projector 0), slip nodes keep only their
     * tangential freedom (I - n n^T), and separable slip acts like slip on
     * the nodes whose start-of-step @p velocity approaches the obstacle and
     * not at all on the others (the contact set is lagged by a step).
     * Coulomb friction of the walls is not applied in implicit steps;
     * frictional boundaries there are FEM bodies with barrier contact.
     */
    std::vector<NodeConstraint>
    implicit_constraints(const Lattice<dim>                &lattice,
                         const std::vector<double>         &mass,
                         const std::vector<Tensor<1, dim>> &velocity,
                         const double                       time) const;

    /**
     * The same conditions for arbitrary points, e.g. FEM nodes at their
     * start-of-step positions: a point inside a wall's layers or a level
     * set is constrained like a grid node there. NodeConstraint::node is
     * the index into @p positions.
     */
    std::vector<NodeConstraint>
    implicit_constraints(const Lattice<dim>                &lattice,
                         const std::vector<Point<dim>>     &positions,
                         const std::vector<Tensor<1, dim>> &velocity,
                         const double                       time) const;

    /** True if any wall or level set is set. */
    bool
    any() const;

    /** True if the level sets exist. */
    bool
    has_level_sets() const;

    /**
     * Whether @p x lies strictly inside a level-set obstacle at @p time
     * (phi < 0): a particle there has penetrated the obstacle, which
     * grid-node conditions cannot prevent (BFEMP Section 6.2).
     */
    bool
    inside_level_set(const Point<dim> &x, const double time) const;

  private:
    /**
     * f(condition, outward normal, obstacle velocity) for every wall and
     * level set that contains the point @p x at @p time.
     */
    template <typename Function>
    void
    for_each_condition(const Lattice<dim> &lattice,
                       const Point<dim>   &x,
                       const double        time,
                       const Function     &f) const;

    /** Appends the implicit constraints at point @p x, tagged @p index. */
    void
    add_implicit_constraints(const Lattice<dim>          &lattice,
                             const std::size_t            index,
                             const Point<dim>            &x,
                             const Tensor<1, dim>        &velocity,
                             const double                 time,
                             std::vector<NodeConstraint> &constraints) const;

    /** wall_active[2 d] is the lower face of direction d, [2 d + 1] upper. */
    std::array<bool, 2 * dim>  wall_active{};
    BoundaryCondition          wall_condition;
    unsigned int               layers = 2;
    std::vector<LevelSet<dim>> level_sets;
  };
} // namespace bfemp

#endif
