#ifndef bfemp_base_position_field_h
#define bfemp_base_position_field_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * A vector field of the rest position set by one prm entry: dim
   * comma-separated numbers (a constant), or muParser expressions of x, y
   * (z) and pi. Used for a body's initial velocity and initial
   * displacement.
   */
  template <int dim>
  class PositionField
  {
  public:
    /**
     * Reads @p text, the value of entry @p entry in subsection @p where;
     * throws InputError naming both for a wrong count and for expressions
     * muParser rejects (compiled here, at the origin).
     */
    void
    parse(const std::string &text,
          const std::string &where,
          const std::string &entry);

    /** Whether the entry holds numbers only. */
    bool
    is_constant() const;

    /** The field at @p x (not checked for NaN: the caller names the file
     *  and the point). */
    Tensor<1, dim>
    value(const Point<dim> &x) const;

    /**
     * grad u at @p x, (grad u)_ab = du_a/dx_b: zero for a constant, else
     * fourth-order central differences of step @p h [m] (muParser has no
     * symbolic derivative).
     */
    Tensor<2, dim>
    gradient(const Point<dim> &x, const double h) const;

    /** The components as written. */
    const std::vector<std::string> &
    expressions() const;

  private:
    Tensor<1, dim>                       constant;
    std::vector<std::string>             components;
    std::shared_ptr<FunctionParser<dim>> function;
  };
} // namespace bfemp

#endif
