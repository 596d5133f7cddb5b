#ifndef bfemp_grid_lattice_h
#define bfemp_grid_lattice_h

#include <deal.II/base/point.h>

#include <array>
#include <cmath>
#include <cstddef>

namespace bfemp
{
  using namespace dealii;

  /**
   * Index arithmetic of the uniform background grid: nodes x_i = origin + i dx
   * with lattice multi-index i in [0, n_cells]^dim, numbered with direction 0
   * fastest. The kernel code works on these flat indices; the deal.II
   * DoFHandler numbering is reached through BackgroundGrid's map.
   */
  template <int dim>
  class Lattice
  {
  public:
    Lattice() = default;

    Lattice(const Point<dim>                    &origin,
            const double                         dx,
            const std::array<unsigned int, dim> &n_cells)
      : origin(origin)
      , dx(dx)
      , inverse_dx(1. / dx)
      , n_cells(n_cells)
    {
      std::size_t stride_d = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          stride[d] = stride_d;
          stride_d *= n_cells[d] + 1;
        }
      n_nodes = stride_d;
    }

    inline std::size_t
    node_index(const std::array<int, dim> &multi_index) const
    {
      std::size_t index = 0;
      for (unsigned int d = 0; d < dim; ++d)
        index += multi_index[d] * stride[d];
      return index;
    }

    inline std::array<int, dim>
    node_multi_index(std::size_t index) const
    {
      std::array<int, dim> multi_index;
      for (int d = dim - 1; d >= 0; --d)
        {
          multi_index[d] = index / stride[d];
          index -= multi_index[d] * stride[d];
        }
      return multi_index;
    }

    inline double
    node_coordinate(const unsigned int direction, const int i) const
    {
      return origin[direction] + i * dx;
    }

    inline Point<dim>
    node_position(const std::size_t index) const
    {
      const auto multi_index = node_multi_index(index);
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = node_coordinate(d, multi_index[d]);
      return x;
    }

    /** Lattice multi-index of the cell containing x (not range checked). */
    inline std::array<int, dim>
    cell_of(const Point<dim> &x) const
    {
      std::array<int, dim> cell;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double xi        = (x[d] - origin[d]) * inverse_dx;
          const int    truncated = static_cast<int>(xi);
          cell[d]                = truncated - (xi < truncated);
        }
      return cell;
    }

    /** Flat index of a cell, direction 0 fastest. */
    inline std::size_t
    cell_index(const std::array<int, dim> &cell) const
    {
      std::size_t index = 0, stride_d = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          index += cell[d] * stride_d;
          stride_d *= n_cells[d];
        }
      return index;
    }

    std::size_t
    n_cells_total() const
    {
      std::size_t n = 1;
      for (unsigned int d = 0; d < dim; ++d)
        n *= n_cells[d];
      return n;
    }

    Point<dim>                    origin;
    double                        dx         = 1.;
    double                        inverse_dx = 1.;
    std::array<unsigned int, dim> n_cells{};
    std::array<std::size_t, dim>  stride{};
    std::size_t                   n_nodes = 0;
  };
} // namespace bfemp

#endif
