#include <bfemp/cmpm/coarse_boundary_map.h>
#include <bfemp/grid/bspline_kernel.h>

#include <algorithm>

namespace bfemp
{
  template <int dim>
  CoarseBoundaryMap<dim>::CoarseBoundaryMap(const CoarseGrid<dim> &grid)
    : grid(grid)
    , rows(grid.n_fine())
  {
    for (unsigned int k = 0; k < grid.n_fine(); ++k)
      if (grid.is_boundary_fine_node(k))
        {
          const std::vector<double> weights =
            interpolation_weights(grid.fine_node_position(k),
                                  grid.fine_multi_index(k));
          for (unsigned int I = 0; I < weights.size(); ++I)
            if (weights[I] != 0.)
              rows[k].emplace_back(I, weights[I]);
        }
  }



  template <int dim>
  const std::vector<std::pair<unsigned int, double>> &
  CoarseBoundaryMap<dim>::row(const unsigned int k) const
  {
    AssertIndexRange(k, rows.size());
    return rows[k];
  }



  template <int dim>
  void
  CoarseBoundaryMap<dim>::add_face_surface(const unsigned int   normal,
                                           const int            plane_offset,
                                           const Point<dim>    &x,
                                           const double         factor,
                                           std::vector<double> &weights) const
  {
    const double L = grid.node_lattice().dx;
    for (unsigned int I = 0; I < grid.n_local_nodes(); ++I)
      {
        const auto &o = grid.local_node_offset(I);
        if (o[normal] != plane_offset)
          continue;
        double w = factor;
        for (unsigned int e = 0; e < dim; ++e)
          if (e != normal)
            w *= BSplineKernel<2>::value((x[e] - o[e] * L) / L);
        weights[I] += w;
      }
  }



  template <int dim>
  std::vector<double>
  CoarseBoundaryMap<dim>::interpolation_weights(
    const Point<dim>                    &x,
    const std::array<unsigned int, dim> &fine_index) const
  {
    const CmpmParameters &prm = grid.parameters();
    const double          H   = grid.element_size();
    const double          s   = grid.knot_span();
    const double          L   = grid.node_lattice().dx;
    const int             l   = prm.nodes_per_span;
    std::vector<double>   weights(grid.n_local_nodes(), 0.);

    switch (prm.element_type)
      {
        case CmpmParameters::ElementType::bspline:
          // eq. 22 with psi_I = B_I on the coarse nodes (eq. 7 with h = L)
          for (unsigned int I = 0; I < grid.n_local_nodes(); ++I)
            {
              const auto &o = grid.local_node_offset(I);
              double      w = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                w *= BSplineKernel<2>::value((x[d] - o[d] * L) / L);
              weights[I] = w;
            }
          break;

        case CmpmParameters::ElementType::multilinear:
          for (unsigned int I = 0; I < grid.n_local_nodes(); ++I)
            {
              const auto &o = grid.local_node_offset(I);
              double      w = 1.;
              for (unsigned int d = 0; d < dim; ++d)
                w *= o[d] == 1 ? x[d] / H : 1. - x[d] / H;
              weights[I] = w;
            }
          break;

        case CmpmParameters::ElementType::boundary_bspline:
          {
            // The faces the node is closest to (distance s/2 to their plane).
            const unsigned int                        n = grid.n_fine_1d();
            std::vector<std::pair<unsigned int, int>> near_faces;
            for (unsigned int d = 0; d < dim; ++d)
              if (fine_index[d] < 2)
                near_faces.emplace_back(d, 0);
              else if (fine_index[d] + 2 >= n)
                near_faces.emplace_back(d, l);
            Assert(!near_faces.empty(),
                   ExcMessage("the extruded interpolation is defined at "
                              "boundary fine nodes only"));

            const double share = 1. / near_faces.size();
            for (const auto &[d, plane] : near_faces)
              {
                // S^0(x^0): the face's own curve / surface (eqs. 25, 36)
                add_face_surface(d, plane, x, share, weights);
                // the extrusion along the adjacent faces, each pair of
                // opposite faces weighted by 1 - a and a (eqs. 26, 37), and
                // the dim - 1 pairs averaged (the 1/2 of eq. 36)
                for (unsigned int e = 0; e < dim; ++e)
                  if (e != d)
                    {
                      const double a =
                        std::clamp((x[e] - 0.5 * s) / (H - s), 0., 1.);
                      Point<dim> edge_point = x;
                      edge_point[d]         = plane * L;
                      for (const auto &[side, weight] :
                           {std::pair<int, double>(0, 1. - a),
                            std::pair<int, double>(l, a)})
                        {
                          const double f = share * weight / (dim - 1);
                          add_face_surface(e, side, x, f, weights);
                          add_face_surface(e, side, edge_point, -f, weights);
                        }
                    }
              }
            break;
          }
      }
    return weights;
  }



  template class CoarseBoundaryMap<2>;
  template class CoarseBoundaryMap<3>;
} // namespace bfemp
