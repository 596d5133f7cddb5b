#include <bfemp/base/input_error.h>
#include <bfemp/cmpm/boundary_interior_map.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace bfemp
{
  namespace
  {
    /** (dP/dF)_{abce} = mu (delta_ac delta_be + delta_ae delta_bc) +
     *  lambda delta_ab delta_ce: small-strain isotropic elasticity. */
    template <int dim>
    Tensor<4, dim>
    isotropic_tangent(const double lambda, const double mu)
    {
      Tensor<4, dim> A;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int e = 0; e < dim; ++e)
              A[a][b][c][e] = mu * ((a == c && b == e) + (a == e && b == c)) +
                              lambda * (a == b && c == e);
      return A;
    }

    /** A stiffness scale of a tangent: sum_ab A_abab / (dim (dim + 1)),
     *  which is mu + lambda / (dim + 1) for isotropic elasticity. */
    template <int dim>
    double
    stiffness_scale(const Tensor<4, dim> &A)
    {
      double sum = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          sum += A[a][b][a][b];
      return sum / (dim * (dim + 1.));
    }
  } // namespace



  template <int dim>
  BoundaryInteriorMap<dim>::BoundaryInteriorMap(
    const CoarseGrid<dim>        &grid,
    const CoarseBoundaryMap<dim> &psi)
    : grid(grid)
    , psi(psi)
  {
    const unsigned int n_i = grid.n_interior_fine();
    const unsigned int r   = grid.n_local_nodes();
    fictitious_K_i.reinit(dim * n_i, dim * n_i);
    fictitious_R.reinit(dim * n_i, dim * r);

    // 2 Gauss points per direction integrate grad B_k . grad B_m (piecewise
    // polynomial of degree <= 2 per direction in each knot span) exactly.
    const QGauss<dim>  gauss(2);
    const double       s     = grid.knot_span();
    const unsigned int spans = grid.n_fine_1d() - 2;
    unsigned int       total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      total *= spans;
    LocalQuadraturePoint<dim> point;
    point.deformation_gradient = unit_symmetric_tensor<dim>();
    point.tangent              = isotropic_tangent<dim>(0., 1.);
    for (unsigned int span = 0; span < total; ++span)
      {
        Point<dim>   corner;
        unsigned int rest = span;
        for (unsigned int d = 0; d < dim; ++d)
          {
            corner[d] = (rest % spans) * s;
            rest /= spans;
          }
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            point.position = corner + s * gauss.point(q);
            point.weight   = gauss.weight(q) * std::pow(s, dim);
            FineStencil stencil;
            grid.fine_stencil(point.position, stencil);
            add_point(point, stencil, fictitious_K_i, fictitious_R);
          }
      }
    mirror_lower_triangle(fictitious_K_i);
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::add_point(const LocalQuadraturePoint<dim> &point,
                                      const FineStencil               &stencil,
                                      FullMatrix<double>              &K_i,
                                      FullMatrix<double>              &R) const
  {
    constexpr unsigned int n_stencil = CoarseGrid<dim>::n_stencil;
    const unsigned int     r         = grid.n_local_nodes();
    const bool             diagonal  = grid.parameters().shape_function_form ==
                          CmpmParameters::ShapeFunctionForm::diagonal;

    // g_k = F^T grad B_k: dF/du_k of BFEMP eq. 25 in displacement form
    const Tensor<2, dim> F_T = transpose(point.deformation_gradient);
    Tensor<1, dim>       g[n_stencil];
    for (unsigned int q = 0; q < n_stencil; ++q)
      g[q] = F_T * stencil.gradient[q];

    // The boundary part mapped to the coarse nodes: G_I = sum_l g_l psi_lI,
    // for the coarse nodes the stencil's boundary nodes reach (kept per
    // thread: this runs for every particle in every step)
    thread_local std::vector<Tensor<1, dim>> G;
    thread_local std::vector<char>           is_touched;
    thread_local std::vector<unsigned int>   touched;
    G.resize(r);
    is_touched.resize(r, 0);
    touched.clear();
    for (unsigned int q = 0; q < n_stencil; ++q)
      for (const auto &[I, weight] : psi.row(stencil.node[q]))
        {
          if (is_touched[I] == 0)
            {
              is_touched[I] = 1;
              touched.push_back(I);
              G[I] = Tensor<1, dim>();
            }
          G[I] += weight * g[q];
        }
    for (const unsigned int I : touched)
      is_touched[I] = 0;

    for (unsigned int q = 0; q < n_stencil; ++q)
      {
        const int i = grid.interior_index(stencil.node[q]);
        if (i < 0)
          continue;
        // T[a][c][e] = w sum_b A_abce g_kb: row block (k, a) of K
        Tensor<3, dim> T;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int e = 0; e < dim; ++e)
                T[a][c][e] +=
                  point.weight * point.tangent[a][b][c][e] * g[q][b];

        // (the diagonal form keeps the blocks within one component, a == c)
        // K_i is symmetric: only its blocks j <= i are summed here, and
        // mirror_lower_triangle() completes it once all points are in
        for (unsigned int m = 0; m < n_stencil; ++m)
          {
            const int j = grid.interior_index(stencil.node[m]);
            if (j < 0 || j > i)
              continue;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int c = 0; c < dim; ++c)
                if (!diagonal || a == c)
                  K_i(dim * i + a, dim * j + c) += T[a][c] * g[m];
          }
        for (const unsigned int I : touched)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int c = 0; c < dim; ++c)
              if (!diagonal || a == c)
                R(dim * i + a, dim * I + c) += T[a][c] * G[I];
      }
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::mirror_lower_triangle(FullMatrix<double> &K_i)
  {
    // add_point() sums the node blocks (i, j) with j <= i, the diagonal
    // blocks whole; their upper halves are overwritten with the lower ones,
    // so K_i is exactly symmetric
    for (unsigned int row = 0; row < K_i.m(); ++row)
      for (unsigned int column = row + 1; column < K_i.n(); ++column)
        K_i(row, column) = K_i(column, row);
  }



  template <int dim>
  double
  BoundaryInteriorMap<dim>::fictitious_weight(
    const std::vector<LocalQuadraturePoint<dim>> &points) const
  {
    double volume = 0., stiffness = 0.;
    for (const LocalQuadraturePoint<dim> &point : points)
      {
        volume += point.weight;
        stiffness += point.weight * stiffness_scale(point.tangent);
      }
    // eps times the mean particle stiffness, or the fictitious material
    // alone (unit stiffness) in an element without particles
    return volume > 0.
             ? grid.parameters().empty_span_stiffness * stiffness / volume
             : 1.;
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::condense(
    const FullMatrix<double>                     &K_i,
    const FullMatrix<double>                     &R,
    const std::vector<LocalQuadraturePoint<dim>> &points,
    const std::vector<FineStencil>               &stencils,
    std::vector<Tensor<2, dim>>                  &control) const
  {
    const unsigned int       n_i     = grid.n_interior_fine();
    const unsigned int       r       = grid.n_local_nodes();
    const unsigned int       columns = grid.n_element_unknowns();
    LAPACKFullMatrix<double> K(dim * n_i, dim * n_i);
    K = K_i;
    K.set_property(LAPACKSupport::symmetric);
    try
      {
        K.compute_cholesky_factorization();
      }
    catch (...)
      {
        throw SimulationError(
          "cmpm: the local stiffness K_i of a coarse element (seed 002 eq. "
          "30) is not positive definite; knot spans without particles need "
          "cmpm/empty span stiffness > 0, an indefinite material tangent "
          "cannot be condensed");
      }
    LAPACKFullMatrix<double> X(dim * n_i, dim * r);
    X = R;
    K.solve(X);
    control.resize(n_i * columns);
    for (unsigned int i = 0; i < n_i; ++i)
      for (unsigned int I = 0; I < r; ++I)
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            control[i * columns + I][a][c] = -X(dim * i + a, dim * I + c);
    if (columns == r)
      return;

    // The interior modes: the interior's static response K_i^-1 f_a to a
    // unit acceleration of the element's particles in direction a, its
    // boundary held. (A solve of their own, so that the coarse columns are
    // those without modes to the last bit.)
    LAPACKFullMatrix<double> Y(dim * n_i, dim);
    for (std::size_t p = 0; p < points.size(); ++p)
      for (unsigned int q = 0; q < CoarseGrid<dim>::n_stencil; ++q)
        {
          const int i = grid.interior_index(stencils[p].node[q]);
          if (i >= 0)
            for (unsigned int a = 0; a < dim; ++a)
              Y(dim * i + a, a) += points[p].mass * stencils[p].value[q];
        }
    K.solve(Y);
    for (unsigned int i = 0; i < n_i; ++i)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          control[i * columns + r][a][c] = Y(dim * i + a, c);
    normalize_mode(stencils, control);
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::normalize_mode(
    const std::vector<FineStencil> &stencils,
    std::vector<Tensor<2, dim>>    &control) const
  {
    // K_i^-1 f_i has the units of m / (m/s^2). Scaled so that its largest
    // entry at a particle is 1, the mode's amplitude is a displacement of
    // the particles (m), as a coarse node's is: Newton's stopping test on
    // the unknowns and the contact's bound on the particles' motion then
    // treat it like the others.
    const unsigned int n_i     = grid.n_interior_fine();
    const unsigned int columns = grid.n_element_unknowns();
    const unsigned int mode    = columns - 1;
    double             largest = 0.;
    for (const FineStencil &stencil : stencils)
      {
        Tensor<2, dim> value;
        for (unsigned int q = 0; q < CoarseGrid<dim>::n_stencil; ++q)
          {
            const int i = grid.interior_index(stencil.node[q]);
            if (i >= 0)
              value += stencil.value[q] * control[i * columns + mode];
          }
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            largest = std::max(largest, std::abs(value[a][c]));
      }
    if (largest > 0.)
      for (unsigned int i = 0; i < n_i; ++i)
        control[i * columns + mode] /= largest;
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::gather_stencils(
    const std::vector<LocalQuadraturePoint<dim>> &points,
    std::vector<FineStencil>                     &stencils) const
  {
    stencils.resize(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
      grid.fine_stencil(points[p].position, stencils[p]);
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::compute(
    const std::vector<LocalQuadraturePoint<dim>> &points,
    std::vector<Tensor<2, dim>>                  &control) const
  {
    // (kept per thread: every element is rebuilt in every step)
    thread_local std::vector<FineStencil> stencils;
    gather_stencils(points, stencils);
    compute(points, stencils, control);
  }



  template <int dim>
  void
  BoundaryInteriorMap<dim>::compute(
    const std::vector<LocalQuadraturePoint<dim>> &points,
    const std::vector<FineStencil>               &stencils,
    std::vector<Tensor<2, dim>>                  &control) const
  {
    AssertDimension(stencils.size(), points.size());
    const unsigned int n_i = grid.n_interior_fine();
    const unsigned int r   = grid.n_local_nodes();
    FullMatrix<double> K_i(dim * n_i, dim * n_i), R(dim * n_i, dim * r);
    for (std::size_t p = 0; p < points.size(); ++p)
      add_point(points[p], stencils[p], K_i, R);
    mirror_lower_triangle(K_i);
    const double fictitious = fictitious_weight(points);
    K_i.add(fictitious, fictitious_K_i);
    R.add(fictitious, fictitious_R);
    condense(K_i, R, points, stencils, control);
  }



  template <int dim>
  LocalSolveStatistics
  BoundaryInteriorMap<dim>::compute_at_equilibrium(
    const std::vector<LocalQuadraturePoint<dim>> &points,
    const std::vector<Tensor<1, dim>>            &coarse_displacement,
    std::vector<Tensor<2, dim>>                  &control) const
  {
    constexpr unsigned int n_stencil = CoarseGrid<dim>::n_stencil;
    const unsigned int     n_i       = grid.n_interior_fine();
    const unsigned int     r         = grid.n_local_nodes();
    AssertDimension(coarse_displacement.size(), r);
    Assert(std::all_of(points.begin(),
                       points.end(),
                       [](const auto &point) {
                         return point.material != nullptr;
                       }),
           ExcInternalError());

    // The start: the first Newton step, q_i = p_i Q (eq. 30).
    std::vector<FineStencil> fine(points.size());
    gather_stencils(points, fine);
    compute(points, fine, control);
    const double fictitious = fictitious_weight(points);

    // Q as a vector, for the fictitious material's K_ib Psi_b Q
    Vector<double> Q(dim * r);
    for (unsigned int I = 0; I < r; ++I)
      for (unsigned int c = 0; c < dim; ++c)
        Q(dim * I + c) = coarse_displacement[I][c];
    Vector<double> fictitious_load(dim * n_i);
    fictitious_R.vmult(fictitious_load, Q);
    fictitious_load *= fictitious;

    // Every fine node's displacement: boundary ones are q_b = Psi_b Q and
    // stay; interior ones are the unknowns.
    std::vector<Tensor<1, dim>> q(grid.n_fine());
    for (unsigned int k = 0; k < grid.n_fine(); ++k)
      if (grid.interior_index(k) < 0)
        for (const auto &[I, weight] : psi.row(k))
          q[k] += weight * coarse_displacement[I];
    // (the interior modes, columns r.., are not part of the start: the
    // local equilibrium has no body load)
    const unsigned int columns = grid.n_element_unknowns();
    Vector<double>     x(dim * n_i);
    for (unsigned int i = 0; i < n_i; ++i)
      for (unsigned int I = 0; I < r; ++I)
        {
          const Tensor<1, dim> qi =
            control[i * columns + I] * coarse_displacement[I];
          for (unsigned int a = 0; a < dim; ++a)
            x(dim * i + a) += qi[a];
        }

    // dF_p/dq_k = e_a (x) g_k, g_k = F_p^n^T grad B_k (BFEMP eq. 25), so
    // F_p(q) = F_p^n + sum_k q_k (x) g_k.
    struct PointStencil
    {
      unsigned int   node[n_stencil];
      Tensor<1, dim> g[n_stencil];
    };
    std::vector<PointStencil> stencils(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const Tensor<2, dim> F_T = transpose(points[p].deformation_gradient);
        for (unsigned int k = 0; k < n_stencil; ++k)
          {
            stencils[p].node[k] = fine[p].node[k];
            stencils[p].g[k]    = F_T * fine[p].gradient[k];
          }
      }
    auto set_interior = [&](const Vector<double> &values) {
      for (unsigned int i = 0; i < n_i; ++i)
        for (unsigned int a = 0; a < dim; ++a)
          q[grid.interior_fine_node(i)][a] = values(dim * i + a);
    };
    auto deformation_gradient = [&](const unsigned int p) {
      Tensor<2, dim> F = points[p].deformation_gradient;
      for (unsigned int k = 0; k < n_stencil; ++k)
        F += outer_product(q[stencils[p].node[k]], stencils[p].g[k]);
      return F;
    };
    // The local potential: the particles' strain energy and the fictitious
    // material's, 1/2 x K_f x + x K_f,ib q_b; +infinity where a particle
    // would invert (the det F filter of BFEMP's line search).
    auto energy = [&](const Vector<double> &values) {
      set_interior(values);
      double E = 0.;
      for (unsigned int p = 0; p < points.size(); ++p)
        {
          const Tensor<2, dim> F = deformation_gradient(p);
          if (!(determinant(F) > 0.))
            return std::numeric_limits<double>::infinity();
          E += points[p].weight * points[p].material->energy_density(F);
        }
      Vector<double> Kx(dim * n_i);
      fictitious_K_i.vmult(Kx, values);
      return E + fictitious * (0.5 * (Kx * values)) + fictitious_load * values;
    };

    LocalSolveStatistics statistics;
    statistics.first_step_energy = energy(x);
    if (!std::isfinite(statistics.first_step_energy))
      throw SimulationError("cmpm/local solve = full Newton: a particle "
                            "is inverted (det F <= 0) at the first "
                            "Newton step's state of its coarse element");
    // Converged when the Newton step moves no fine node farther than
    // 1e-10 knot spans (the length scale of the local problem).
    const double       tolerance      = 1e-10 * grid.knot_span();
    const unsigned int max_iterations = 50;
    double             E              = statistics.first_step_energy;
    for (;; ++statistics.iterations)
      {
        if (statistics.iterations == max_iterations)
          throw SimulationError(
            "cmpm/local solve = full Newton: the local equilibrium "
            "of a coarse element did not converge in " +
            std::to_string(max_iterations) +
            " Newton iterations; use 'first Newton step' or "
            "smaller time steps");
        // gradient f_i and tangent K_i at the current state
        set_interior(x);
        FullMatrix<double> K_i(dim * n_i, dim * n_i), R(dim * n_i, dim * r);
        Vector<double>     gradient(dim * n_i);
        for (unsigned int p = 0; p < points.size(); ++p)
          {
            const Tensor<2, dim>      F       = deformation_gradient(p);
            LocalQuadraturePoint<dim> current = points[p];
            current.tangent = points[p].material->tangent(F, true);
            add_point(current, fine[p], K_i, R);
            const Tensor<2, dim> P =
              points[p].material->first_piola_kirchhoff(F);
            for (unsigned int k = 0; k < n_stencil; ++k)
              {
                const int i = grid.interior_index(stencils[p].node[k]);
                if (i < 0)
                  continue;
                const Tensor<1, dim> f =
                  points[p].weight * (P * stencils[p].g[k]);
                for (unsigned int a = 0; a < dim; ++a)
                  gradient(dim * i + a) += f[a];
              }
          }
        mirror_lower_triangle(K_i);
        {
          Vector<double> Kx(dim * n_i);
          fictitious_K_i.vmult(Kx, x);
          gradient.add(fictitious, Kx);
        }
        gradient += fictitious_load;
        K_i.add(fictitious, fictitious_K_i);
        R.add(fictitious, fictitious_R);
        statistics.residual = gradient.linfty_norm();

        LAPACKFullMatrix<double> K(dim * n_i, dim * n_i);
        K = K_i;
        K.set_property(LAPACKSupport::symmetric);
        K.compute_cholesky_factorization();
        Vector<double> step(gradient);
        K.solve(step);
        step *= -1.;
        if (step.linfty_norm() <= tolerance)
          {
            // eq. 30 with the tangent at the equilibrium
            condense(K_i, R, points, fine, control);
            statistics.energy = E;
            return statistics;
          }
        // backtracking on the local energy, det F > 0 kept
        double         alpha = 1.;
        Vector<double> trial(x);
        for (unsigned int halvings = 0;; ++halvings)
          {
            trial = x;
            trial.add(alpha, step);
            const double E_trial = energy(trial);
            if (E_trial <= E + 1e-14 * std::abs(E) ||
                (std::isfinite(E_trial) &&
                 alpha * step.linfty_norm() <= tolerance))
              {
                x = trial;
                E = E_trial;
                break;
              }
            if (halvings == 60)
              throw SimulationError(
                "cmpm/local solve = full Newton: the line search "
                "of a coarse element's local equilibrium found no "
                "decrease of its strain energy");
            alpha *= 0.5;
          }
      }
  }



  template class BoundaryInteriorMap<2>;
  template class BoundaryInteriorMap<3>;
} // namespace bfemp
