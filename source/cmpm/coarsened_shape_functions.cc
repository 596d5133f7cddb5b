#include <bfemp/cmpm/coarsened_shape_functions.h>

#include <deal.II/base/parallel.h>
#include <deal.II/lac/lapack_templates.h>

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
        for (const auto &[I, weight] : psi.row(k))
          {
            AssertIndexRange(I, grid.n_local_nodes());
            row_sum += std::abs(weight);
          }
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
    const unsigned int r       = coarse_grid.n_element_unknowns();
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
    const unsigned int r = coarse_grid.n_element_unknowns();
    values.assign(r, CoarseShapeValue<dim>());
    for (unsigned int I = 0; I < r; ++I)
      values[I].node = coarse_grid.unknown_node(element, I);

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
    const unsigned int                 r = coarse_grid.n_element_unknowns();
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
    const unsigned int r = coarse_grid.n_element_unknowns();
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
    const unsigned int                 r = coarse_grid.n_element_unknowns();
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
    const std::vector<char>           &coupled,
    std::vector<Tensor<2, dim>>       &coarse) const
  {
    Assert(is_active(element), ExcInternalError());
    const std::size_t m = nodes.size();
    AssertDimension(upper.size(), m * m);
    AssertDimension(coupled.size(), m * m);
    Assert(std::is_sorted(nodes.begin(), nodes.end()), ExcInternalError());
    const unsigned int                 r = coarse_grid.n_element_unknowns();
    const std::vector<Tensor<2, dim>> &p = control[element];
    const unsigned int     n_interior    = coarse_grid.n_interior_fine();
    const std::size_t      cols          = dim * r;
    constexpr unsigned int block         = dim * dim;

    // p has two kinds of rows (eq. 31): the dense blocks P_k on the
    // interior fine nodes and psi_kI I on the boundary ones. K = U + U^T,
    // U the upper fine blocks (node i <= node j) with the diagonal ones
    // halved, so K_alpha = p^T K p = W + W^T with W = p^T U p, and W splits
    // by the kinds of i and j:
    //   W = P^T (U_II P + U_IB psi) + (psi^T U_BI) P + psi^T (U_BB psi).
    // The products with P are BLAS calls on scalar matrices (row a of fine
    // node k is row dim k + a, column b of coarse node J is column dim J +
    // b; BLAS is column-major, so a row-major matrix is passed as its
    // transpose): G_I = U_II P + U_IB psi (dim n_interior x cols),
    // A = psi^T U_BI (cols x dim n_interior). The parts through psi are
    // sparse sums over U's nonzero blocks and psi's few entries per row,
    // one fine node's row of U at a time in a buffer that stays in cache:
    // a boundary node's row of U_BB psi goes into W straight away, so no
    // boundary row of U p is ever stored (they were 2/3 of the rows of a
    // dgemm and the matrix that psi^T was applied to, neither of which
    // stayed in cache).
    thread_local std::vector<double> p_interior;
    p_interior.resize(dim * n_interior * cols);
    for (unsigned int i = 0; i < n_interior; ++i)
      for (unsigned int J = 0; J < r; ++J)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            p_interior[(dim * i + a) * cols + dim * J + b] = p[i * r + J][a][b];

    thread_local std::vector<double> U_II, G_I, A, C, G_node, G_row;
    const types::blas_int            n_axpy = dim * r, unit = 1;
    U_II.assign(dim * n_interior * dim * n_interior, 0.);
    G_I.assign(dim * n_interior * cols, 0.);
    A.assign(cols * dim * n_interior, 0.);
    C.assign(cols * cols, 0.);
    G_row.resize(dim * cols);

    // Fine nodes more than two apart in a direction share no knot span, so
    // node i couples only with the 5^dim nodes around it: they are visited
    // through a position map of the patch in increasing node number (the
    // order of @p nodes), not by testing all m^2 pairs.
    const unsigned int            n_1d = coarse_grid.n_fine_1d();
    thread_local std::vector<int> position;
    position.assign(coarse_grid.n_fine(), -1);
    for (unsigned int i = 0; i < m; ++i)
      position[nodes[i]] = i;
    for (unsigned int i = 0; i < m; ++i)
      {
        const int i_interior = coarse_grid.interior_index(nodes[i]);
        G_node.assign(r * block, 0.);
        const std::array<unsigned int, dim> index =
          coarse_grid.fine_multi_index(nodes[i]);
        unsigned int lower[dim], extent[dim], n_neighbours = 1;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d]  = index[d] >= 2 ? index[d] - 2 : 0;
            extent[d] = std::min(index[d] + 2, n_1d - 1) - lower[d] + 1;
            n_neighbours *= extent[d];
          }
        for (unsigned int t = 0; t < n_neighbours; ++t)
          {
            // t's digits, the first direction fastest: k increases with t
            unsigned int k = 0, stride = 1, rest = t;
            for (unsigned int d = 0; d < dim; ++d)
              {
                k += (lower[d] + rest % extent[d]) * stride;
                rest /= extent[d];
                stride *= n_1d;
              }
            const int j = position[k];
            // not in @p nodes, a lower block, or one that no particle forms
            if (j < static_cast<int>(i) || coupled[i * m + j] == 0)
              continue;
            const double          factor = j == static_cast<int>(i) ? 0.5 : 1.;
            const Tensor<2, dim> &U_ij   = upper[i * m + j];
            double                K[block];
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                K[a * dim + b] = factor * U_ij[a][b];
            const int j_interior = coarse_grid.interior_index(k);
            if (j_interior >= 0 && i_interior >= 0)
              // U_II
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  U_II[(dim * i_interior + a) * dim * n_interior +
                       dim * j_interior + b] = K[a * dim + b];
            else if (j_interior >= 0)
              // A += psi_i^T U_ij
              for (const auto &[I, weight] : psi.row(nodes[i]))
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = 0; b < dim; ++b)
                    A[(dim * I + a) * dim * n_interior + dim * j_interior +
                      b] += weight * K[a * dim + b];
            else
              // node i's row of U_.B psi, block-major (coarse node, a, b)
              for (const auto &[J, weight] : psi.row(k))
                {
                  double *G_J = &G_node[J * block];
                  for (unsigned int c = 0; c < block; ++c)
                    G_J[c] += weight * K[c];
                }
          }
        // node i's row of U_.B psi by scalar rows
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int J = 0; J < r; ++J)
            for (unsigned int b = 0; b < dim; ++b)
              G_row[a * cols + dim * J + b] = G_node[J * block + a * dim + b];
        if (i_interior >= 0)
          // its rows of G_I (U_IB psi)
          std::copy(G_row.begin(), G_row.end(), &G_I[dim * i_interior * cols]);
        else
          // W += psi_i^T (U_BB psi)_i, contiguous rows of C (BLAS axpy:
          // its vector kernels, where the compiler's baseline has none)
          for (const auto &[I, weight] : psi.row(nodes[i]))
            for (unsigned int a = 0; a < dim; ++a)
              axpy(&n_axpy,
                   &weight,
                   &G_row[a * cols],
                   &unit,
                   &C[(dim * I + a) * cols],
                   &unit);
      }

    // ('cmpm/fine nodes per direction' >= 5: at least one interior fine
    // node, so BLAS's leading dimensions are >= 1)
    Assert(n_interior > 0, ExcInternalError());
    const types::blas_int n_cols = cols, n_inner = dim * n_interior;
    const double          one = 1.;
    // G_I += U_II P, i.e. G_I^T += P^T U_II^T
    gemm("N",
         "N",
         &n_cols,
         &n_inner,
         &n_inner,
         &one,
         p_interior.data(),
         &n_cols,
         U_II.data(),
         &n_inner,
         &one,
         G_I.data(),
         &n_cols);
    // W += P^T G_I, i.e. W^T += G_I^T P
    gemm("N",
         "T",
         &n_cols,
         &n_cols,
         &n_inner,
         &one,
         G_I.data(),
         &n_cols,
         p_interior.data(),
         &n_cols,
         &one,
         C.data(),
         &n_cols);
    // W += A P, i.e. W^T += P^T A^T
    gemm("N",
         "N",
         &n_cols,
         &n_cols,
         &n_inner,
         &one,
         p_interior.data(),
         &n_cols,
         A.data(),
         &n_inner,
         &one,
         C.data(),
         &n_cols);

    // p^T K p = W + W^T, symmetric to the last bit (the upper blocks
    // mirrored), as the assembled Hessian of the other terms is
    coarse.resize(r * r);
    for (unsigned int I = 0; I < r; ++I)
      for (unsigned int J = I; J < r; ++J)
        {
          Tensor<2, dim> &block = coarse[I * r + J];
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              block[a][b] = C[(dim * I + a) * cols + dim * J + b] +
                            C[(dim * J + b) * cols + dim * I + a];
          coarse[J * r + I] = transpose(block);
        }
  }



  template class CoarsenedShapeFunctions<2>;
  template class CoarsenedShapeFunctions<3>;
} // namespace bfemp
