#ifndef bfemp_grid_grid_state_h
#define bfemp_grid_grid_state_h

#include <deal.II/base/tensor.h>

#include <vector>

namespace bfemp
{
  using namespace dealii;

  /**
   * Nodal fields of the background grid for one step, indexed by lattice
   * node: mass m_i^n, velocity v_i^n (momentum during P2G), force f_i, the
   * end-of-step velocity v~_i^{n+1} and displacement x~_i^{n+1} - x_i^n
   * (BFEMP eq. 21 and Tables 1-3 use x~ and v~).
   */
  template <int dim>
  struct GridState
  {
    std::vector<double>         mass;
    std::vector<Tensor<1, dim>> velocity;
    std::vector<Tensor<1, dim>> force;
    std::vector<Tensor<1, dim>> new_velocity;
    std::vector<Tensor<1, dim>> displacement;

    void
    reinit(const std::size_t n_nodes)
    {
      mass.assign(n_nodes, 0.);
      velocity.assign(n_nodes, Tensor<1, dim>());
      force.assign(n_nodes, Tensor<1, dim>());
      new_velocity.assign(n_nodes, Tensor<1, dim>());
      displacement.assign(n_nodes, Tensor<1, dim>());
    }
  };
} // namespace bfemp

#endif
