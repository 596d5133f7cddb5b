#include <bfemp/contact/spatial_hash.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace bfemp
{
  namespace
  {
    constexpr double epsilon = std::numeric_limits<double>::epsilon();

    /**
     * Cells per direction such that the linear index of a cell fits into
     * 63 bits.
     */
    template <int dim>
    constexpr std::uint64_t
    max_cells_per_direction()
    {
      return dim == 1   ? (std::uint64_t(1) << 62)
             : dim == 2 ? (std::uint64_t(1) << 31)
                        : (std::uint64_t(1) << 21);
    }



    template <int dim>
    bool
    overlap(const BoundingBox<dim> &a, const BoundingBox<dim> &b)
    {
      const auto &pa = a.get_boundary_points();
      const auto &pb = b.get_boundary_points();
      for (unsigned int d = 0; d < dim; ++d)
        if (!(pa.first[d] <= pb.second[d] && pb.first[d] <= pa.second[d]))
          return false;
      return true;
    }



    /**
     * Call @p f for every cell of the block [lower, upper] whose index in
     * the directions below @p first_direction is that of @p lower, in the
     * order of the keys (x fastest).
     */
    template <int dim, typename Function>
    void
    for_each_cell(const std::array<std::uint64_t, dim> &lower,
                  const std::array<std::uint64_t, dim> &upper,
                  const unsigned int                    first_direction,
                  const Function                       &f)
    {
      std::array<std::uint64_t, dim> cell = lower;
      while (true)
        {
          f(cell);
          unsigned int d = first_direction;
          for (; d < dim; ++d)
            {
              if (cell[d] < upper[d])
                {
                  ++cell[d];
                  break;
                }
              cell[d] = lower[d];
            }
          if (d == dim)
            return;
        }
    }



    /**
     * The box of the positions x_j and x_j + dx_j, padded by @p margin and
     * by 4 ulps of the coordinates (the rounding of x + dx and of the
     * padding itself are each at most half an ulp).
     */
    template <int dim, std::size_t n>
    BoundingBox<dim>
    swept_box(const std::array<Point<dim>, n>     &x,
              const std::array<Tensor<1, dim>, n> &dx,
              const double                         margin)
    {
      AssertThrow(margin >= 0.,
                  ExcMessage("swept box: the margin must be >= 0"));
      Point<dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::numeric_limits<double>::infinity();
          upper[d] = -std::numeric_limits<double>::infinity();
        }
      for (std::size_t j = 0; j < n; ++j)
        {
          const Point<dim> end = x[j] + dx[j];
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min({lower[d], x[j][d], end[d]});
              upper[d] = std::max({upper[d], x[j][d], end[d]});
            }
        }
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double pad =
            margin +
            4. * epsilon * std::max(std::abs(lower[d]), std::abs(upper[d]));
          lower[d] -= pad;
          upper[d] += pad;
        }
      return BoundingBox<dim>(std::make_pair(lower, upper));
    }
  } // namespace



  template <int dim>
  SpatialHash<dim>::SpatialHash(const std::vector<BoundingBox<dim>> &boxes,
                                const double                         cell_size,
                                const unsigned int max_cells_per_box)
  {
    reinit(boxes, cell_size, max_cells_per_box);
  }



  template <int dim>
  void
  SpatialHash<dim>::reinit(const std::vector<BoundingBox<dim>> &new_boxes,
                           const double       requested_cell_size,
                           const unsigned int max_cells_per_box)
  {
    AssertThrow(std::isfinite(requested_cell_size) && requested_cell_size >= 0.,
                ExcMessage("SpatialHash: the cell size must be finite and "
                           ">= 0 (0: automatic)"));
    AssertThrow(max_cells_per_box >= 1,
                ExcMessage("SpatialHash: max_cells_per_box must be >= 1"));
    AssertThrow(new_boxes.size() < std::numeric_limits<unsigned int>::max(),
                ExcMessage("SpatialHash: too many boxes"));

    // The extent of all boxes and the mean of their largest sides; checked
    // before anything is changed, so that a throw leaves the hash as it was.
    Point<dim> lower_corner, upper;
    double     size_sum = 0.;
    for (unsigned int i = 0; i < new_boxes.size(); ++i)
      {
        const auto &[box_lower, box_upper] = new_boxes[i].get_boundary_points();
        double largest_side                = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            AssertThrow(std::isfinite(box_lower[d]) &&
                          std::isfinite(box_upper[d]) &&
                          box_lower[d] <= box_upper[d],
                        ExcMessage("SpatialHash: box " + std::to_string(i) +
                                   " is not finite or has its lower corner "
                                   "above its upper corner"));
            lower_corner[d] =
              i == 0 ? box_lower[d] : std::min(lower_corner[d], box_lower[d]);
            upper[d] = i == 0 ? box_upper[d] : std::max(upper[d], box_upper[d]);
            largest_side = std::max(largest_side, box_upper[d] - box_lower[d]);
          }
        size_sum += largest_side;
      }

    boxes = new_boxes;
    cell_keys.clear();
    cell_start.assign(1, 0);
    cell_boxes.clear();
    large_boxes.clear();
    n_cells = {};
    if (boxes.empty())
      return;
    origin       = lower_corner;
    upper_corner = upper;

    double h =
      requested_cell_size > 0. ? requested_cell_size : size_sum / boxes.size();
    if (!(h > 0.))
      {
        double largest_extent = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          largest_extent =
            std::max(largest_extent, upper_corner[d] - origin[d]);
        h = largest_extent /
            std::pow(static_cast<double>(boxes.size()), 1. / dim);
        if (!(h > 0.))
          h = 1.;
      }
    // Keep the number of cells per direction (and with it the keys) in
    // range; the margin of 4 cells covers the rounding of the quotients.
    const double max_cells =
      static_cast<double>(max_cells_per_direction<dim>());
    for (unsigned int d = 0; d < dim; ++d)
      h = std::max(h, (upper_corner[d] - origin[d]) / (max_cells - 4.));
    cell_size         = h;
    inverse_cell_size = 1. / h;
    for (unsigned int d = 0; d < dim; ++d)
      n_cells[d] = max_cells_per_direction<dim>();
    // cell_of() clamps to n_cells - 1, so this is the cell of the corner.
    const CellIndex last = cell_of(upper_corner);
    for (unsigned int d = 0; d < dim; ++d)
      n_cells[d] = last[d] + 1;

    // The (cell key, box) pairs, sorted: by key, then by box index.
    std::vector<std::pair<std::uint64_t, unsigned int>> entries;
    entries.reserve(boxes.size() * (1u << dim));
    for (unsigned int i = 0; i < boxes.size(); ++i)
      {
        const auto &[lower, upper] = boxes[i].get_boundary_points();
        const CellIndex first      = cell_of(lower);
        const CellIndex last_cell  = cell_of(upper);
        double          n_covered  = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          n_covered *= static_cast<double>(last_cell[d] - first[d] + 1);
        if (n_covered > max_cells_per_box)
          large_boxes.push_back(i);
        else
          for_each_cell<dim>(first, last_cell, 0, [&](const CellIndex &cell) {
            entries.emplace_back(key_of(cell), i);
          });
      }
    std::sort(entries.begin(), entries.end());

    cell_boxes.resize(entries.size());
    for (std::size_t k = 0; k < entries.size(); ++k)
      {
        if (k == 0 || entries[k].first != entries[k - 1].first)
          {
            if (k > 0)
              cell_start.push_back(k);
            cell_keys.push_back(entries[k].first);
          }
        cell_boxes[k] = entries[k].second;
      }
    if (!entries.empty())
      cell_start.push_back(entries.size());
  }



  template <int dim>
  void
  SpatialHash<dim>::query(const BoundingBox<dim>    &box,
                          std::vector<unsigned int> &candidates) const
  {
    candidates.clear();
    if (boxes.empty())
      return;

    // All boxes lie in [origin, upper_corner]: a query outside has none.
    const auto &[lower, upper] = box.get_boundary_points();
    for (unsigned int d = 0; d < dim; ++d)
      if (!(upper[d] >= origin[d] && lower[d] <= upper_corner[d]))
        return;

    const CellIndex first = cell_of(lower);
    const CellIndex last  = cell_of(upper);
    double          rows  = 1.;
    for (unsigned int d = 1; d < dim; ++d)
      rows *= static_cast<double>(last[d] - first[d] + 1);

    if (rows > static_cast<double>(boxes.size()))
      {
        // Testing every box is cheaper than a binary search per row.
        for (unsigned int i = 0; i < boxes.size(); ++i)
          if (overlap(box, boxes[i]))
            candidates.push_back(i);
        return;
      }

    // One row at a time: the keys from (first[0], rest) to (last[0], rest)
    // are consecutive in the sorted keys. Since cell_of() is monotone in
    // each coordinate (and so is its clamping), a box overlapping the query
    // has a cell in the query's block.
    for_each_cell<dim>(first, last, 1, [&](const CellIndex &row_start) {
      CellIndex row_end             = row_start;
      row_end[0]                    = last[0];
      const std::uint64_t first_key = key_of(row_start);
      const std::uint64_t last_key  = key_of(row_end);
      for (auto key =
             std::lower_bound(cell_keys.begin(), cell_keys.end(), first_key);
           key != cell_keys.end() && *key <= last_key;
           ++key)
        {
          const std::size_t cell = key - cell_keys.begin();
          for (std::size_t k = cell_start[cell]; k < cell_start[cell + 1]; ++k)
            if (overlap(box, boxes[cell_boxes[k]]))
              candidates.push_back(cell_boxes[k]);
        }
    });
    for (const unsigned int i : large_boxes)
      if (overlap(box, boxes[i]))
        candidates.push_back(i);

    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()),
                     candidates.end());
  }



  template <int dim>
  double
  SpatialHash<dim>::get_cell_size() const
  {
    return cell_size;
  }



  template <int dim>
  unsigned int
  SpatialHash<dim>::n_boxes() const
  {
    return boxes.size();
  }



  template <int dim>
  unsigned int
  SpatialHash<dim>::n_large_boxes() const
  {
    return large_boxes.size();
  }



  template <int dim>
  std::size_t
  SpatialHash<dim>::n_cell_entries() const
  {
    return cell_boxes.size();
  }



  template <int dim>
  typename SpatialHash<dim>::CellIndex
  SpatialHash<dim>::cell_of(const Point<dim> &x) const
  {
    // fl(x - origin), fl(* inverse) and floor are monotone in x, so the
    // cells of a box's corners bound the cells of everything in between,
    // also in floating point. Written so that NaN lands in cell 0.
    CellIndex cell;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double s    = std::floor((x[d] - origin[d]) * inverse_cell_size);
        const double last = static_cast<double>(n_cells[d] - 1);
        cell[d] = s > 0. ? static_cast<std::uint64_t>(std::min(s, last)) : 0;
      }
    return cell;
  }



  template <int dim>
  std::uint64_t
  SpatialHash<dim>::key_of(const CellIndex &cell) const
  {
    std::uint64_t key = cell[dim - 1];
    for (unsigned int d = dim - 1; d-- > 0;)
      key = key * n_cells[d] + cell[d];
    return key;
  }



  template <int dim>
  BoundingBox<dim>
  swept_point_box(const Point<dim>     &x,
                  const Tensor<1, dim> &dx,
                  const double          margin)
  {
    return swept_box<dim, 1>({{x}}, {{dx}}, margin);
  }



  template <int dim>
  BoundingBox<dim>
  swept_segment_box(const Point<dim>     &a,
                    const Point<dim>     &b,
                    const Tensor<1, dim> &da,
                    const Tensor<1, dim> &db,
                    const double          margin)
  {
    return swept_box<dim, 2>({{a, b}}, {{da, db}}, margin);
  }



  template <int dim>
  BoundingBox<dim>
  swept_triangle_box(const Point<dim>     &a,
                     const Point<dim>     &b,
                     const Point<dim>     &c,
                     const Tensor<1, dim> &da,
                     const Tensor<1, dim> &db,
                     const Tensor<1, dim> &dc,
                     const double          margin)
  {
    return swept_box<dim, 3>({{a, b, c}}, {{da, db, dc}}, margin);
  }



  template class SpatialHash<2>;
  template class SpatialHash<3>;

  template BoundingBox<2>
  swept_point_box(const Point<2> &, const Tensor<1, 2> &, const double);
  template BoundingBox<3>
  swept_point_box(const Point<3> &, const Tensor<1, 3> &, const double);
  template BoundingBox<2>
  swept_segment_box(const Point<2> &,
                    const Point<2> &,
                    const Tensor<1, 2> &,
                    const Tensor<1, 2> &,
                    const double);
  template BoundingBox<3>
  swept_segment_box(const Point<3> &,
                    const Point<3> &,
                    const Tensor<1, 3> &,
                    const Tensor<1, 3> &,
                    const double);
  template BoundingBox<2>
  swept_triangle_box(const Point<2> &,
                     const Point<2> &,
                     const Point<2> &,
                     const Tensor<1, 2> &,
                     const Tensor<1, 2> &,
                     const Tensor<1, 2> &,
                     const double);
  template BoundingBox<3>
  swept_triangle_box(const Point<3> &,
                     const Point<3> &,
                     const Point<3> &,
                     const Tensor<1, 3> &,
                     const Tensor<1, 3> &,
                     const Tensor<1, 3> &,
                     const double);
} // namespace bfemp
