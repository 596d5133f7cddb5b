#ifndef bfemp_grid_grid_parameters_h
#define bfemp_grid_grid_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>

namespace bfemp
{
  using namespace dealii;

  /** prm subsection "grid": the MPM background grid and its kernel. */
  template <int dim>
  struct GridParameters
  {
    Point<dim> lower_corner;
    Point<dim> upper_corner;
    double     cell_size = 0.05;
    /** B-spline degree of the kernel: 1 linear, 2 quadratic, 3 cubic. */
    unsigned int kernel_degree = 2;

    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Cells per direction; the extent must be a multiple of the cell size. */
    std::array<unsigned int, dim>
    n_cells() const;
  };
} // namespace bfemp

#endif
