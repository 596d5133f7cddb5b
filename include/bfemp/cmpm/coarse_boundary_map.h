#ifndef bfemp_cmpm_coarse_boundary_map_h
#define bfemp_cmpm_coarse_boundary_map_h

#include <bfemp/cmpm/coarse_grid.h>

#include <deal.II/base/point.h>

#include <utility>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * The coarse-boundary map Psi of seed 002 (eqs. 22-24): the intermediate
   * interpolation surface (2D) / volume (3D) I(x) = sum_I psi_I(x) Q_I of an
   * element, sampled at its boundary fine nodes. It acts on each
   * displacement component alike (eq. 23), so a scalar weight psi_kI per
   * boundary fine node k and local coarse node I describes it. It depends
   * only on the element type, L, H and n, so it is computed once for all
   * elements (seed 002 Section 7.2).
   *
   * - B-spline element (Section 5.1.1): psi_I(x) = prod_d N((x_d - X_Id)/L)
   *   with the quadratic B-spline N of eq. 8 on the coarse node lattice.
   * - Boundary B-spline element (Section 5.1.2): eq. 25 (2D) and eq. 36
   *   (3D) with the weights of eqs. 26 and 37. The curve / surface of a face
   *   is the quadratic B-spline over the coarse nodes on the face's line /
   *   plane. Where the seed leaves the choice open (doc/cmpm.md): the face
   *   weight a = (d - s/2) / (H - s) is clamped to [0, 1] for the nodes
   *   outside the element; a node as close to several faces (near an edge or
   *   corner) takes the mean of the eq. 25 / 36 values over those faces,
   *   which in 2D is the seed's corner averaging and makes the value the same
   *   in every element that shares the node (Lemma 2).
   * - Multilinear element: the element's own multilinear interpolation of
   *   its corner nodes, extrapolated to the outer fine rows. Not shared with
   *   the neighbours, so only C0: the comparison case.
   */
  template <int dim>
  class CoarseBoundaryMap
  {
  public:
    explicit CoarseBoundaryMap(const CoarseGrid<dim> &grid);

    /** The nonzero (local coarse node, psi_kI) of fine node k; empty for an
     *  interior fine node. */
    const std::vector<std::pair<unsigned int, double>> &
    row(const unsigned int k) const;

    /**
     * The intermediate interpolation I(x) of the element at a point x in
     * element coordinates, as weights per local coarse node (eq. 22). For the
     * boundary B-spline element x must be a boundary fine node (the extruded
     * surface is defined there only).
     */
    std::vector<double>
    interpolation_weights(
      const Point<dim>                    &x,
      const std::array<unsigned int, dim> &fine_index) const;

  private:
    /** Adds factor * (weights of the face surface on the plane
     *  x_normal = plane_offset L at x) to @p weights. */
    void
    add_face_surface(const unsigned int   normal,
                     const int            plane_offset,
                     const Point<dim>    &x,
                     const double         factor,
                     std::vector<double> &weights) const;

    const CoarseGrid<dim>                                    &grid;
    std::vector<std::vector<std::pair<unsigned int, double>>> rows;
  };
} // namespace bfemp

#endif
