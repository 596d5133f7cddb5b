#include <bfemp/base/parameter_tools.h>

#include <deal.II/base/utilities.h>

#include <sstream>

namespace bfemp
{
  namespace parameter_tools
  {
    template <int dim>
    void
    declare_point(ParameterHandler  &prm,
                  const std::string &entry,
                  const std::string &default_value_for_dim,
                  const std::string &documentation)
    {
      prm.declare_entry(entry,
                        default_value_for_dim,
                        Patterns::List(Patterns::Double(), dim, dim, ","),
                        documentation + " (" + std::to_string(dim) +
                          " comma-separated numbers)");
    }



    template <int dim>
    Tensor<1, dim>
    get_vector(const ParameterHandler &prm, const std::string &entry)
    {
      const std::vector<double> values = Utilities::string_to_double(
        Utilities::split_string_list(prm.get(entry), ','));
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = values[d];
      return result;
    }



    template <int dim>
    Point<dim>
    get_point(const ParameterHandler &prm, const std::string &entry)
    {
      return Point<dim>(get_vector<dim>(prm, entry));
    }



    template <int dim>
    std::string
    components(const double x, const double y, const double z)
    {
      const double       values[3] = {x, y, z};
      std::ostringstream result;
      for (unsigned int d = 0; d < dim; ++d)
        result << (d > 0 ? ", " : "") << values[d];
      return result.str();
    }



    std::string
    numbered(const std::string &family, const unsigned int index)
    {
      return family + " " + std::to_string(index);
    }



    std::string
    nested(const std::string &where, const std::string &child)
    {
      if (!where.empty() && where.back() == '\'')
        return where.substr(0, where.size() - 1) + "/" + child + "'";
      return where + "/" + child;
    }



    template void
    declare_point<2>(ParameterHandler &,
                     const std::string &,
                     const std::string &,
                     const std::string &);
    template void
    declare_point<3>(ParameterHandler &,
                     const std::string &,
                     const std::string &,
                     const std::string &);
    template Tensor<1, 2>
    get_vector<2>(const ParameterHandler &, const std::string &);
    template Tensor<1, 3>
    get_vector<3>(const ParameterHandler &, const std::string &);
    template Point<2>
    get_point<2>(const ParameterHandler &, const std::string &);
    template Point<3>
    get_point<3>(const ParameterHandler &, const std::string &);
    template std::string
    components<2>(const double, const double, const double);
    template std::string
    components<3>(const double, const double, const double);
  } // namespace parameter_tools
} // namespace bfemp
