#include <bfemp/cmpm/coarsened_shape_functions.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <cmath>

namespace bfemp
{
  template <int dim>
  CoarsenedShapeFunctions<dim>::CoarsenedShapeFunctions(
    const CoarseGrid<dim> &grid)
    : coarse_grid(grid)
    , psi(grid)
    , condensation(grid, psi)
    , control(grid.n_elements_total())
    , bound(grid.n_elements_total(), 0.)
  {
    for (unsigned int k = 0; k < grid.n_fine(); ++k)
      {
        double row_sum = 0.;
        for (const auto &entry : psi.row(k))
          row_sum += std::abs(entry.second);
        boundary_bound = std::max(boundary_bound, row_sum);
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::build(
    const std::size_t                             element,
    const std::vector<LocalQuadraturePoint<dim>> &points)
  {
    condensation.compute(points, control[element]);
    update_bound(element);
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::update_bound(const std::size_t element)
  {
    // Fine node k moves by sum_I p_kI Q_I: component a by at most
    // sum_I sum_c |(p_kI)_ac| |Q|_inf.
    const unsigned int r       = coarse_grid.n_local_nodes();
    const auto        &p       = control[element];
    double             largest = boundary_bound;
    for (std::size_t i = 0; i * r < p.size(); ++i)
      for (unsigned int a = 0; a < dim; ++a)
        {
          double row_sum = 0.;
          for (unsigned int I = 0; I < r; ++I)
            for (unsigned int c = 0; c < dim; ++c)
              row_sum += std::abs(p[i * r + I][a][c]);
          largest = std::max(largest, row_sum);
        }
    bound[element] = largest;
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::reinit(
    const std::vector<std::size_t>                            &elements,
    const std::vector<std::vector<LocalQuadraturePoint<dim>>> &points)
  {
    AssertDimension(elements.size(), points.size());
    clear();
    // one element per task: the per-element work is a dense solve of
    // dim (n - 4)^dim unknowns, large against the scheduling cost
    parallel::apply_to_subranges(
      std::size_t(0),
      elements.size(),
      [&](const std::size_t begin, const std::size_t end) {
        for (std::size_t e = begin; e < end; ++e)
          build(elements[e], points[e]);
      },
      1);
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::clear()
  {
    for (auto &element_control : control)
      element_control.clear();
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::rebuild(
    const std::size_t                             element,
    const std::vector<LocalQuadraturePoint<dim>> &points)
  {
    build(element, points);
  }



  template <int dim>
  LocalSolveStatistics
  CoarsenedShapeFunctions<dim>::rebuild_at_equilibrium(
    const std::size_t                             element,
    const std::vector<LocalQuadraturePoint<dim>> &points,
    const std::vector<Tensor<1, dim>>            &coarse_displacement)
  {
    const LocalSolveStatistics statistics =
      condensation.compute_at_equilibrium(points,
                                          coarse_displacement,
                                          control[element]);
    update_bound(element);
    return statistics;
  }



  template <int dim>
  bool
  CoarsenedShapeFunctions<dim>::is_active(const std::size_t element) const
  {
    return !control[element].empty();
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::evaluate(
    const std::array<int, dim>         &element,
    const Point<dim>                   &x,
    std::vector<CoarseShapeValue<dim>> &values) const
  {
    const std::size_t index = coarse_grid.element_index(element);
    AssertThrow(is_active(index),
                ExcMessage("cMPM: a coarse element without shape functions "
                           "was evaluated (it held no particle when they "
                           "were built)"));
    const unsigned int r = coarse_grid.n_local_nodes();
    values.assign(r, CoarseShapeValue<dim>());
    for (unsigned int I = 0; I < r; ++I)
      values[I].node = coarse_grid.global_node(element, I);

    typename CoarseGrid<dim>::FineStencil stencil;
    coarse_grid.fine_stencil(Point<dim>(x -
                                        coarse_grid.element_origin(element)),
                             stencil);
    const std::vector<Tensor<2, dim>> &p = control[index];

    // eq. 15: Phi_I = sum_k B_k p_kI; p_kI = psi_kI identity on the boundary
    // rows (eq. 31), the condensed blocks on the interior rows
    for (unsigned int q = 0; q < CoarseGrid<dim>::n_stencil; ++q)
      {
        const double          B      = stencil.value[q];
        const Tensor<1, dim> &grad_B = stencil.gradient[q];
        const int             i = coarse_grid.interior_index(stencil.node[q]);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(stencil.node[q]))
            for (unsigned int a = 0; a < dim; ++a)
              {
                values[I].value[a][a] += B * weight;
                values[I].gradient[a][a] += weight * grad_B;
              }
        else
          for (unsigned int I = 0; I < r; ++I)
            {
              const Tensor<2, dim> &p_kI = p[i * r + I];
              values[I].value += B * p_kI;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int c = 0; c < dim; ++c)
                  values[I].gradient[a][c] += p_kI[a][c] * grad_B;
            }
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::values(
    const std::size_t                            element,
    const typename CoarseGrid<dim>::FineStencil &stencil,
    std::vector<Tensor<2, dim>>                 &phi) const
  {
    Assert(is_active(element), ExcInternalError());
    const unsigned int                 r = coarse_grid.n_local_nodes();
    const std::vector<Tensor<2, dim>> &p = control[element];
    // eq. 15 as in evaluate(): the boundary rows are psi_kI I, so their
    // part is a scalar per coarse node
    thread_local std::vector<double> boundary;
    boundary.assign(r, 0.);
    phi.assign(r, Tensor<2, dim>());
    for (unsigned int q = 0; q < CoarseGrid<dim>::n_stencil; ++q)
      {
        const double B = stencil.value[q];
        const int    i = coarse_grid.interior_index(stencil.node[q]);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(stencil.node[q]))
            boundary[I] += B * weight;
        else
          for (unsigned int I = 0; I < r; ++I)
            phi[I] += B * p[i * r + I];
      }
    for (unsigned int I = 0; I < r; ++I)
      for (unsigned int a = 0; a < dim; ++a)
        phi[I][a][a] += boundary[I];
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::evaluate(
    const Point<dim>                   &x,
    std::vector<CoarseShapeValue<dim>> &values) const
  {
    evaluate(coarse_grid.element_of(x), x, values);
  }



  template <int dim>
  double
  CoarsenedShapeFunctions<dim>::averaged_scalar(const Tensor<2, dim> &value)
  {
    return trace(value) / dim;
  }



  template <int dim>
  const CoarseGrid<dim> &
  CoarsenedShapeFunctions<dim>::grid() const
  {
    return coarse_grid;
  }



  template <int dim>
  const CoarseBoundaryMap<dim> &
  CoarsenedShapeFunctions<dim>::coarse_boundary_map() const
  {
    return psi;
  }



  template <int dim>
  double
  CoarsenedShapeFunctions<dim>::interpolation_bound(
    const std::size_t element) const
  {
    Assert(is_active(element), ExcInternalError());
    return bound[element];
  }



  template <int dim>
  const std::vector<Tensor<2, dim>> &
  CoarsenedShapeFunctions<dim>::interior_control(
    const std::size_t element) const
  {
    return control[element];
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::fine_values(
    const std::size_t                  element,
    const std::vector<Tensor<1, dim>> &coarse,
    std::vector<Tensor<1, dim>>       &fine) const
  {
    Assert(is_active(element), ExcInternalError());
    const unsigned int r = coarse_grid.n_local_nodes();
    AssertDimension(coarse.size(), r);
    const std::vector<Tensor<2, dim>> &p = control[element];
    fine.assign(coarse_grid.n_fine(), Tensor<1, dim>());
    for (unsigned int k = 0; k < fine.size(); ++k)
      {
        const int i = coarse_grid.interior_index(k);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(k))
            fine[k] += weight * coarse[I];
        else
          for (unsigned int I = 0; I < r; ++I)
            fine[k] += p[i * r + I] * coarse[I];
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::coarse_forces(
    const std::size_t                  element,
    const std::vector<Tensor<1, dim>> &fine,
    std::vector<Tensor<1, dim>>       &coarse) const
  {
    Assert(is_active(element), ExcInternalError());
    AssertDimension(fine.size(), coarse_grid.n_fine());
    const unsigned int                 r = coarse_grid.n_local_nodes();
    const std::vector<Tensor<2, dim>> &p = control[element];
    coarse.assign(r, Tensor<1, dim>());
    for (unsigned int k = 0; k < fine.size(); ++k)
      {
        const int i = coarse_grid.interior_index(k);
        if (i < 0)
          for (const auto &[I, weight] : psi.row(k))
            coarse[I] += weight * fine[k];
        else
          for (unsigned int I = 0; I < r; ++I)
            coarse[I] += transpose(p[i * r + I]) * fine[k];
      }
  }



  template <int dim>
  void
  CoarsenedShapeFunctions<dim>::condense(
    const std::size_t                  element,
    const std::vector<unsigned int>   &nodes,
    const std::vector<Tensor<2, dim>> &upper,
    std::vector<Tensor<2, dim>>       &coarse) const
  {
    Assert(is_active(element), ExcInternalError());
    const std::size_t m = nodes.size();
    AssertDimension(upper.size(), m * m);
    const unsigned int                 r = coarse_grid.n_local_nodes();
    const std::vector<Tensor<2, dim>> &p = control[element];

    // G = K p, row by row of fine nodes: G[i * r + J] = sum_j K_ij p_jJ
    thread_local std::vector<Tensor<2, dim>>                G;
    thread_local std::vector<std::array<unsigned int, dim>> index;
    G.assign(m * r, Tensor<2, dim>());
    index.resize(m);
    for (unsigned int i = 0; i < m; ++i)
      index[i] = coarse_grid.fine_multi_index(nodes[i]);
    // G_i += K p_j, where p_j is psi_j I on boundary rows
    const auto add_product =
      [&](const Tensor<2, dim> &K, const unsigned int i, const unsigned int j) {
        Tensor<2, dim> *G_i      = &G[i * r];
        const int       interior = coarse_grid.interior_index(nodes[j]);
        if (interior < 0)
          for (const auto &[J, weight] : psi.row(nodes[j]))
            G_i[J] += weight * K;
        else
          for (unsigned int J = 0; J < r; ++J)
            G_i[J] += K * p[interior * r + J];
      };
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = i; j < m; ++j)
        {
          bool couples = true;
          for (unsigned int d = 0; d < dim; ++d)
            couples = couples && std::abs(static_cast<int>(index[i][d]) -
                                          static_cast<int>(index[j][d])) <= 2;
          if (!couples)
            continue;
          const Tensor<2, dim> &K_ij = upper[i * m + j];
          add_product(K_ij, i, j);
          if (j != i)
            add_product(transpose(K_ij), j, i);
        }

    // coarse = p^T G
    coarse.assign(r * r, Tensor<2, dim>());
    for (unsigned int i = 0; i < m; ++i)
      {
        const Tensor<2, dim> *G_i      = &G[i * r];
        const int             interior = coarse_grid.interior_index(nodes[i]);
        if (interior < 0)
          for (const auto &[I, weight] : psi.row(nodes[i]))
            for (unsigned int J = 0; J < r; ++J)
              coarse[I * r + J] += weight * G_i[J];
        else
          for (unsigned int I = 0; I < r; ++I)
            {
              const Tensor<2, dim> p_iI_T = transpose(p[interior * r + I]);
              for (unsigned int J = 0; J < r; ++J)
                coarse[I * r + J] += p_iI_T * G_i[J];
            }
      }
    // p^T K p is symmetric; make it so to the last bit, as the assembled
    // Hessian of the other terms is
    for (unsigned int I = 0; I < r; ++I)
      for (unsigned int J = I + 1; J < r; ++J)
        coarse[J * r + I] = transpose(coarse[I * r + J]);
  }



  template class CoarsenedShapeFunctions<2>;
  template class CoarsenedShapeFunctions<3>;
} // namespace bfemp
