#ifndef bfemp_contact_spatial_hash_h
#define bfemp_contact_spatial_hash_h

// The broad phase of particle-mesh contact: which boundary primitives can be
// near which particle. Every primitive (or particle) is represented by an
// axis-aligned box -- its bounding box inflated by the contact distance, or
// the box swept by it along Newton's search direction for the CCD of the
// line search -- and the boxes are bucketed in a uniform grid of cells, so
// that a query only looks at the boxes of the few cells its own box covers
// instead of at all boxes.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cstdint>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * A uniform grid of cells over a set of axis-aligned boxes, for finding
   * the boxes that overlap a query box.
   *
   * Storage: the (cell, box) pairs of all boxes, sorted by the cell's key
   * (its linear index in the grid, x fastest) and then by box index, and
   * compressed into the sorted unique keys with offsets into one array of
   * box indices (like a sparse matrix row structure). Building is a sort,
   * O(E log E) for E pairs; there is no hash table, the layout does not
   * depend on any hash function or insertion order, and the cells of one
   * grid row are contiguous, so a query does one binary search per row of
   * cells it covers and then reads consecutive memory. With the automatic
   * cell size (about one box per cell and direction), E is a small multiple
   * of the number of boxes and a query costs O(log E + candidates): the cost
   * of all queries grows about linearly with their number.
   *
   * Boxes that would cover more than max_cells_per_box cells (a huge
   * primitive, or one moving far along the search direction) are not
   * entered into cells but kept in a list of large boxes that every query
   * tests directly, so one such box cannot blow up the memory. A query box
   * that covers more rows of cells than there are boxes is answered by
   * testing all boxes, which is then cheaper.
   *
   * Boxes are closed: boxes that only touch count as overlapping. Degenerate
   * boxes (zero extent in some direction, e.g. a point) are allowed. The
   * object is not changed by queries, so queries may run in parallel.
   */
  template <int dim>
  class SpatialHash
  {
  public:
    /** The default of max_cells_per_box (see the class documentation). */
    static constexpr unsigned int default_max_cells_per_box = 256;

    /** An empty hash: every query returns no box. */
    SpatialHash() = default;

    /** The same as reinit(). */
    explicit SpatialHash(
      const std::vector<BoundingBox<dim>> &boxes,
      const double                         cell_size = 0.,
      const unsigned int max_cells_per_box = default_max_cells_per_box);

    /**
     * Build the grid over @p boxes (copied). With @p cell_size = 0 the cell
     * size is the mean over the boxes of their largest side, so that a
     * typical box covers at most two cells per direction. (If all boxes are
     * points, the mean spacing of the boxes over their extent is used
     * instead, and 1 if that is zero too.) The cell size is enlarged if
     * needed so that the cell keys fit into 64 bits (at most 2^21 cells per
     * direction in 3D, 2^31 in 2D). Throws for boxes with non-finite
     * corners or a lower corner above the upper one.
     */
    void
    reinit(const std::vector<BoundingBox<dim>> &boxes,
           const double                         cell_size = 0.,
           const unsigned int max_cells_per_box = default_max_cells_per_box);

    /**
     * The indices, ascending and without repetitions, of the boxes that
     * overlap @p box (closed boxes). @p candidates is cleared first; its
     * capacity is reused, so a caller that queries many boxes should pass
     * the same vector each time.
     */
    void
    query(const BoundingBox<dim>    &box,
          std::vector<unsigned int> &candidates) const;

    double
    get_cell_size() const;

    unsigned int
    n_boxes() const;

    /** Boxes kept outside the cells (see the class documentation). */
    unsigned int
    n_large_boxes() const;

    /** Stored (cell, box) pairs, a measure of the memory used. */
    std::size_t
    n_cell_entries() const;

  private:
    using CellIndex = std::array<std::uint64_t, dim>;

    /** The cell containing the coordinates of @p x, clamped to the grid. */
    CellIndex
    cell_of(const Point<dim> &x) const;

    std::uint64_t
    key_of(const CellIndex &cell) const;

    double                        cell_size         = 1.;
    double                        inverse_cell_size = 1.;
    Point<dim>                    origin;
    Point<dim>                    upper_corner;
    CellIndex                     n_cells = {};
    std::vector<BoundingBox<dim>> boxes;

    /** Sorted unique keys of the occupied cells. */
    std::vector<std::uint64_t> cell_keys;

    /** The boxes of cell_keys[i] are cell_boxes[cell_start[i] ..
     * cell_start[i + 1]). */
    std::vector<std::size_t> cell_start;

    std::vector<unsigned int> cell_boxes;

    std::vector<unsigned int> large_boxes;
  };



  /**
   * The box containing the trajectory x + t dx, t in [0, 1], inflated by
   * @p margin and by a few units in the last place of the coordinates, so
   * that it contains the exact trajectory despite the rounding of x + dx.
   */
  template <int dim>
  BoundingBox<dim>
  swept_point_box(const Point<dim>     &x,
                  const Tensor<1, dim> &dx,
                  const double          margin = 0.);

  /**
   * The box containing the segment between a + t da and b + t db for all t
   * in [0, 1] (the box of the four end positions: every point of the moving
   * segment is a convex combination of them), inflated as swept_point_box().
   */
  template <int dim>
  BoundingBox<dim>
  swept_segment_box(const Point<dim>     &a,
                    const Point<dim>     &b,
                    const Tensor<1, dim> &da,
                    const Tensor<1, dim> &db,
                    const double          margin = 0.);

  /** The same for the triangle with the vertices a + t da, b + t db,
   *  c + t dc. */
  template <int dim>
  BoundingBox<dim>
  swept_triangle_box(const Point<dim>     &a,
                     const Point<dim>     &b,
                     const Point<dim>     &c,
                     const Tensor<1, dim> &da,
                     const Tensor<1, dim> &db,
                     const Tensor<1, dim> &dc,
                     const double          margin = 0.);
} // namespace bfemp

#endif
