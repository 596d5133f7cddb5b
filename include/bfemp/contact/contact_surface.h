#ifndef bfemp_contact_contact_surface_h
#define bfemp_contact_contact_surface_h

#include <bfemp/fem/fem_mesh.h>

#include <array>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The boundary of one FEM mesh as the contact potential sees it (BFEMP
   * eqs. 31, 32): the facets (2D edges, 3D triangles) every particle is
   * measured against, and the lower-dimensional primitives whose distance
   * terms are subtracted (or added back) so that a particle near a vertex or
   * an edge shared by several facets is not counted several times.
   *
   * The duplicate-subtraction weights follow inclusion-exclusion over the
   * star of each primitive:
   * - 2D (eq. 31): vertex k gets -(eta_k - 1), eta_k its incident edges;
   * - 3D (eq. 32): edge e gets -(eta_e - 1), eta_e its incident triangles,
   *   and vertex v gets 1 - T_v + sum_{e at v} (eta_e - 1) with T_v its
   *   incident triangles. On a closed manifold surface that is +1 for every
   *   vertex, the set B~ of eq. 32; the general form also covers pinched
   *   (non-manifold) vertices.
   * Node indices are the mesh's local node numbers.
   */
  template <int dim>
  class ContactSurface
  {
  public:
    using Facet = std::array<unsigned int, dim>;
    using Edge  = std::array<unsigned int, 2>;

    explicit ContactSurface(const FemMesh<dim> &mesh);

    /** Boundary facets, outward oriented as FemMesh::boundary_facets(). */
    const std::vector<Facet> &
    facets() const;

    /** The boundary nodes (sorted local node numbers). */
    const std::vector<unsigned int> &
    nodes() const;

    /** Weight of the point-point term of boundary node nodes()[k]. */
    double
    vertex_weight(const unsigned int k) const;

    /** Index into nodes() of local node @p node. */
    unsigned int
    vertex_index(const unsigned int node) const;

    /** 3D: the boundary edges and their point-edge weights -(eta_e - 1). */
    const std::vector<Edge> &
    edges() const;

    double
    edge_weight(const unsigned int e) const;

    /** 3D: the indices into edges() of the three edges of facet f. */
    const std::array<unsigned int, 3> &
    facet_edges(const unsigned int f) const;

  private:
    std::vector<Facet>                       facet_list;
    std::vector<unsigned int>                node_list;
    std::vector<unsigned int>                node_to_vertex;
    std::vector<double>                      vertex_weights;
    std::vector<Edge>                        edge_list;
    std::vector<double>                      edge_weights;
    std::vector<std::array<unsigned int, 3>> edges_of_facet;
  };
} // namespace bfemp

#endif
