#include <bfemp/contact/contact_surface.h>

#include <algorithm>
#include <map>

namespace bfemp
{
  template <int dim>
  ContactSurface<dim>::ContactSurface(const FemMesh<dim> &mesh)
    : facet_list(mesh.boundary_facets())
  {
    for (const Facet &f : facet_list)
      node_list.insert(node_list.end(), f.begin(), f.end());
    std::sort(node_list.begin(), node_list.end());
    node_list.erase(std::unique(node_list.begin(), node_list.end()),
                    node_list.end());
    node_to_vertex.assign(mesh.n_nodes(), numbers::invalid_unsigned_int);
    for (unsigned int k = 0; k < node_list.size(); ++k)
      node_to_vertex[node_list[k]] = k;

    // Incident facets per vertex: in 2D eta_k, in 3D T_v.
    std::vector<unsigned int> incident_facets(node_list.size(), 0);
    for (const Facet &f : facet_list)
      for (const unsigned int a : f)
        ++incident_facets[node_to_vertex[a]];

    if constexpr (dim == 2)
      {
        vertex_weights.resize(node_list.size());
        for (unsigned int k = 0; k < node_list.size(); ++k)
          vertex_weights[k] = 1. - incident_facets[k];
      }
    else
      {
        std::map<Edge, unsigned int> edge_index;
        std::vector<unsigned int>    incident_triangles;
        edges_of_facet.resize(facet_list.size());
        for (unsigned int f = 0; f < facet_list.size(); ++f)
          for (unsigned int k = 0; k < 3; ++k)
            {
              Edge e = {{facet_list[f][k], facet_list[f][(k + 1) % 3]}};
              if (e[0] > e[1])
                std::swap(e[0], e[1]);
              const auto inserted =
                edge_index.emplace(e,
                                   static_cast<unsigned int>(edge_list.size()));
              if (inserted.second)
                {
                  edge_list.push_back(e);
                  incident_triangles.push_back(0);
                }
              ++incident_triangles[inserted.first->second];
              edges_of_facet[f][k] = inserted.first->second;
            }
        edge_weights.resize(edge_list.size());
        vertex_weights.resize(node_list.size());
        for (unsigned int k = 0; k < node_list.size(); ++k)
          vertex_weights[k] = 1. - incident_facets[k];
        for (unsigned int e = 0; e < edge_list.size(); ++e)
          {
            const double excess = incident_triangles[e] - 1.;
            edge_weights[e]     = -excess;
            for (const unsigned int a : edge_list[e])
              vertex_weights[node_to_vertex[a]] += excess;
          }
      }
  }



  template <int dim>
  const std::vector<typename ContactSurface<dim>::Facet> &
  ContactSurface<dim>::facets() const
  {
    return facet_list;
  }



  template <int dim>
  const std::vector<unsigned int> &
  ContactSurface<dim>::nodes() const
  {
    return node_list;
  }



  template <int dim>
  double
  ContactSurface<dim>::vertex_weight(const unsigned int k) const
  {
    return vertex_weights[k];
  }



  template <int dim>
  unsigned int
  ContactSurface<dim>::vertex_index(const unsigned int node) const
  {
    return node_to_vertex[node];
  }



  template <int dim>
  const std::vector<typename ContactSurface<dim>::Edge> &
  ContactSurface<dim>::edges() const
  {
    return edge_list;
  }



  template <int dim>
  double
  ContactSurface<dim>::edge_weight(const unsigned int e) const
  {
    return edge_weights[e];
  }



  template <int dim>
  const std::array<unsigned int, 3> &
  ContactSurface<dim>::facet_edges(const unsigned int f) const
  {
    return edges_of_facet[f];
  }



  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace bfemp
