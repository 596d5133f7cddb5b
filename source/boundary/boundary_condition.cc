#include <bfemp/boundary/boundary_condition.h>

namespace bfemp
{
  BoundaryCondition::Type
  BoundaryCondition::parse_type(const std::string &name)
  {
    if (name == "sticky")
      return Type::sticky;
    if (name == "slip")
      return Type::slip;
    return Type::separable_slip;
  }
} // namespace bfemp
