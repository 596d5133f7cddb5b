#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/grid/grid_parameters.h>

#include <cmath>

namespace bfemp
{
  template <int dim>
  void
  GridParameters<dim>::declare_parameters(ParameterHandler &prm)
  {
    using namespace parameter_tools;
    prm.enter_subsection("grid");
    declare_point<dim>(prm,
                       "lower corner",
                       components<dim>(0, 0, 0),
                       "[m] Lower corner of the background grid");
    declare_point<dim>(prm,
                       "upper corner",
                       components<dim>(1, 1, 1),
                       "[m] Upper corner of the background grid");
    prm.declare_entry("cell size",
                      "0.05",
                      Patterns::Double(),
                      "[m] Grid spacing dx, the same in every direction; "
                      "each extent must be a whole multiple of it.");
    prm.declare_entry("kernel",
                      "quadratic",
                      Patterns::Selection("linear|quadratic|cubic"),
                      "[-] B-spline kernel of the grid (C0, C1, C2).");
    prm.leave_subsection();
  }



  template <int dim>
  void
  GridParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("grid");
    lower_corner = parameter_tools::get_point<dim>(prm, "lower corner");
    upper_corner = parameter_tools::get_point<dim>(prm, "upper corner");
    cell_size    = prm.get_double("cell size");
    const std::string kernel = prm.get("kernel");
    kernel_degree = (kernel == "linear" ? 1 : kernel == "quadratic" ? 2 : 3);
    prm.leave_subsection();

    require_input(cell_size > 0.,
                  "grid",
                  "cell size",
                  to_input_string(cell_size),
                  "must be > 0 [m]");
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double extent = upper_corner[d] - lower_corner[d];
        require_input(extent > 0.,
                      "grid",
                      "upper corner",
                      to_input_string(upper_corner),
                      "must exceed the lower corner in every direction");
        const double n = extent / cell_size;
        require_input(std::abs(n - std::round(n)) < 1e-8 * n && n >= 4.,
                      "grid",
                      "cell size",
                      to_input_string(cell_size),
                      "each grid extent must be a whole multiple (>= 4) of "
                      "the cell size; direction " +
                        std::to_string(d) + " has " + to_input_string(n) +
                        " cells");
      }
  }



  template <int dim>
  std::array<unsigned int, dim>
  GridParameters<dim>::n_cells() const
  {
    std::array<unsigned int, dim> n;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = static_cast<unsigned int>(
        std::round((upper_corner[d] - lower_corner[d]) / cell_size));
    return n;
  }



  template struct GridParameters<2>;
  template struct GridParameters<3>;
} // namespace bfemp
