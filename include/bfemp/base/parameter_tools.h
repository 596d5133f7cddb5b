#ifndef bfemp_base_parameter_tools_h
#define bfemp_base_parameter_tools_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * Helpers shared by the declare/parse functions of all parameter structs.
   * Every entry bfemp declares carries its unit in square brackets at the
   * start of its documentation, so the generated reference can show it.
   */
  namespace parameter_tools
  {
    /** Declares an entry holding a point or vector with exactly dim
     *  comma-separated numbers. */
    template <int dim>
    void
    declare_point(ParameterHandler  &prm,
                  const std::string &entry,
                  const std::string &default_value_for_dim,
                  const std::string &documentation);

    template <int dim>
    Tensor<1, dim>
    get_vector(const ParameterHandler &prm, const std::string &entry);

    template <int dim>
    Point<dim>
    get_point(const ParameterHandler &prm, const std::string &entry);

    /** "a, b" in 2D and "a, b, c" in 3D: a default for declare_point(). */
    template <int dim>
    std::string
    components(const double x, const double y, const double z);

    /** The n-th subsection name of a numbered family: "body 0", "body 1". */
    std::string
    numbered(const std::string &family, const unsigned int index);

    /**
     * The place of subsection @p child inside the one @p where names, for
     * messages: "f.prm: subsection 'fem body 0'" becomes "f.prm: subsection
     * 'fem body 0/mesh'", as deal.II writes subsection paths.
     */
    std::string
    nested(const std::string &where, const std::string &child);
  } // namespace parameter_tools
} // namespace bfemp

#endif
