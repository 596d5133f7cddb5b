#include <bfemp/contact/friction_mollifier.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <string>

namespace bfemp
{
  FrictionMollifier::FrictionMollifier(const double sliding_threshold)
    : epsilon(sliding_threshold)
    , inverse_epsilon(1. / sliding_threshold)
  {
    AssertThrow(sliding_threshold > 0. && std::isfinite(sliding_threshold),
                dealii::ExcMessage(
                  "FrictionMollifier: the sliding threshold eps_v dt must be "
                  "positive and finite, not " +
                  std::to_string(sliding_threshold)));
  }



  double
  FrictionMollifier::sliding_threshold() const
  {
    return epsilon;
  }



  double
  FrictionMollifier::f0(const double y) const
  {
    Assert(y >= 0., dealii::ExcMessage("f0: negative argument"));
    if (y >= epsilon)
      return y;
    // eps (1/3 + r^2 - r^3/3) in r = y/eps: all terms positive, no
    // cancellation.
    const double r = y * inverse_epsilon;
    return epsilon * (1. / 3. + r * r * (1. - r / 3.));
  }



  double
  FrictionMollifier::f1(const double y) const
  {
    Assert(y >= 0., dealii::ExcMessage("f1: negative argument"));
    if (y >= epsilon)
      return 1.;
    const double r = y * inverse_epsilon;
    return r * (2. - r);
  }



  double
  FrictionMollifier::f1_over_y(const double y) const
  {
    Assert(y >= 0., dealii::ExcMessage("f1_over_y: negative argument"));
    if (y >= epsilon)
      return 1. / y;
    // f1(y)/y with the y cancelled, so y = 0 gives the limit 2/eps.
    return (2. - y * inverse_epsilon) * inverse_epsilon;
  }



  double
  FrictionMollifier::f1_over_y_derivative_over_y(const double y) const
  {
    Assert(y > 0.,
           dealii::ExcMessage("f1_over_y_derivative_over_y: y must be "
                              "positive (the expression is singular at 0)"));
    if (y >= epsilon)
      return -1. / (y * y * y);
    // f1'(y) y - f1(y) = -y^2/eps^2 below eps.
    return -inverse_epsilon * inverse_epsilon / y;
  }



  double
  FrictionMollifier::f1_derivative_minus_f1_over_y(const double y) const
  {
    Assert(y >= 0.,
           dealii::ExcMessage("f1_derivative_minus_f1_over_y: negative "
                              "argument"));
    if (y >= epsilon)
      return -1. / y;
    return -y * inverse_epsilon * inverse_epsilon;
  }
} // namespace bfemp
