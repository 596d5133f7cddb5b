#ifndef bfemp_fem_fem_mesh_h
#define bfemp_fem_fem_mesh_h

#include <bfemp/fem/fem_mesh_parameters.h>

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The linear simplex mesh of one FEM body (triangles in 2D, tetrahedra in
   * 3D), built from FemMeshParameters (prm subsection "mesh"), with the
   * flat data the FEM energy, the contact module and the solver loop over.
   *
   * <b>Nodes.</b> Node n is the n-th used vertex of the deal.II
   * triangulation (all vertices are used for generated and GridIn meshes,
   * so node n is vertex n). The DoFHandler of FE_SimplexP(1)^dim is
   * renumbered so that component c of node n is DoF dim*n + c: a solver
   * vector in node-major order is directly a deal.II solution vector for
   * DataOut.
   *
   * <b>Elements.</b> Element e is the active cell with active_cell_index()
   * e; its dim+1 node indices are ordered so that
   * det[x_1 - x_0, ..., x_dim - x_0] > 0 at rest (counter-clockwise
   * triangles, right-handed tetrahedra), which SimplexElement requires. This
   * order can differ from the cell's vertex order in deal.II.
   *
   * <b>Boundary ids.</b> rectangle/box: 0..2*dim-1 for the faces x = lower,
   * x = upper, y = lower, y = upper (, z = lower, z = upper), before the
   * rotation (deal.II's colorize convention). disk, ring, semi-ring (and
   * their 3D versions): 0 outer sphere/circle, 1 inner, 2 the flat cut
   * y = center_y of the semi-ring. Files: the physical tag of a boundary
   * line (2D) or triangle (3D) of the .msh; faces without one get 0.
   */
  template <int dim>
  class FemMesh
  {
  public:
    /** The dim node indices of a boundary edge (2D) or triangle (3D). */
    using Facet = std::array<unsigned int, dim>;

    /** The dim+1 node indices of an element, positively oriented. */
    using Element = std::array<unsigned int, dim + 1>;

    /**
     * Builds the mesh (see doc/fem.md): rectangles with
     * GridGenerator::subdivided_hyper_rectangle_with_simplices, disks, rings
     * and semi-rings and .geo files with the gmsh binary, .msh files with
     * GridIn::read_msh. Then rotates and translates it and sets up nodes,
     * elements, boundary facets and the DoFHandler. @p where names the prm
     * subsection for messages. Throws an InputError if gmsh is missing or
     * fails, a file cannot be read, contains cells other than triangles
     * (2D) or tetrahedra (3D), or an element has zero volume.
     */
    explicit FemMesh(const FemMeshParameters<dim> &parameters,
                     const std::string            &where = "mesh");

    FemMesh(const FemMesh &) = delete;
    FemMesh &
    operator=(const FemMesh &) = delete;

    unsigned int
    n_nodes() const;

    unsigned int
    n_elements() const;

    /** X_n, after rotation and translation. */
    const Point<dim> &
    rest_position(const unsigned int node) const;

    /** All rest positions, indexed by node. */
    const std::vector<Point<dim>> &
    rest_positions() const;

    /** Node indices of every element, indexed by active cell index,
     *  positively oriented. */
    const std::vector<Element> &
    elements() const;

    /** Rest area (2D) or volume (3D) of every element. */
    const std::vector<double> &
    element_volumes() const;

    /** Sum of the element volumes. */
    double
    total_volume() const;

    /** The shortest element edge at rest. */
    double
    min_edge_length() const;

    /**
     * Row-sum lumped mass of the linear simplex consistent mass matrix,
     * m_n = sum over elements e containing n of density V_e / (dim+1).
     * Their sum is density * total_volume().
     */
    std::vector<double>
    lumped_masses(const double density) const;

    /**
     * The boundary facets, each once. 2D: edges (a, b) ordered so that the
     * outward normal is the edge direction x_b - x_a rotated clockwise
     * (the body lies to the left, boundary loops run counter-clockwise
     * around the body and clockwise around holes). 3D: triangles (a, b, c)
     * with outward normal (x_b - x_a) x (x_c - x_a).
     */
    const std::vector<Facet> &
    boundary_facets() const;

    /** The boundary id of each facet of boundary_facets(). */
    const std::vector<types::boundary_id> &
    boundary_facet_ids() const;

    /** The nodes on the boundary, sorted. */
    const std::vector<unsigned int> &
    boundary_nodes() const;

    /** The ids of the boundary facets that contain @p node, sorted; empty
     *  for an interior node. */
    const std::vector<types::boundary_id> &
    node_boundary_ids(const unsigned int node) const;

    /** The nodes on at least one facet with boundary id @p id, sorted. */
    std::vector<unsigned int>
    nodes_with_boundary_id(const types::boundary_id id) const;

    /** The boundary ids that occur, sorted. */
    std::vector<types::boundary_id>
    boundary_ids() const;

    const Triangulation<dim> &
    triangulation() const;

    /** FE_SimplexP(1)^dim, DoF dim*n + c is component c of node n. */
    const DoFHandler<dim> &
    dof_handler() const;

    const FESystem<dim> &
    finite_element() const;

    /** The linear mapping of simplices, for DataOut and FEValues. */
    const Mapping<dim> &
    mapping() const;

  private:
    void
    generate(const FemMeshParameters<dim> &parameters,
             const std::string            &where);

    void
    set_up_nodes_and_elements(const std::string &what);

    /** Refuses a mesh in which an element is inverted with respect to a
     *  neighbour (InputError naming both). */
    void
    check_not_folded(const std::string &what) const;

    void
    set_up_boundary();

    void
    set_up_dofs();

    Triangulation<dim> tria;
    FESystem<dim>      fe;
    MappingFE<dim>     linear_mapping;
    DoFHandler<dim>    dofs;

    /** Node of each triangulation vertex (invalid for unused ones). */
    std::vector<unsigned int> vertex_to_node;

    std::vector<Point<dim>>                      positions;
    std::vector<Element>                         element_nodes;
    std::vector<double>                          volumes;
    std::vector<Facet>                           facets;
    std::vector<types::boundary_id>              facet_ids;
    std::vector<unsigned int>                    boundary_node_list;
    std::vector<std::vector<types::boundary_id>> ids_of_node;
    double                                       shortest_edge = 0.;
  };
} // namespace bfemp

#endif
