// The coarsened shape functions Phi_I = B M Psi of cMPM (seed 002 Section 6)
// on blocks of coarse elements filled with particles, homogeneous and
// heterogeneous (a 1000 times stiffer ball and a particle-free slab, so that
// some knot spans are empty), for both element types and both node spans
// (and the boundary B-spline element with L = H/3), in 2D and 3D:
// - partition of unity (eq. 34): sum_I Phi_I(x) = identity and
//   sum_I grad Phi_I(x) = 0 at random points, to round-off;
// - C1 continuity across coarse element faces (Theorem 3): Phi_I and
//   grad Phi_I of every coarse node agree from both sides at random points on
//   shared faces (edges and corners included), to round-off;
// - no gradient jump across the knot lines inside an element;
// - the C0 comparison element (element-local multilinear interpolation)
//   fails the face test: its values agree, its gradients jump (printed);
// - the shape functions are matrix-valued (largest off-diagonal entry
//   printed): the local equilibrium couples the displacement components;
// - `shape function form = diagonal` (the seed's "Diagonal" baseline with
//   the multilinear element, and with the boundary B-spline one): every
//   off-diagonal entry of Phi_I and grad Phi_I is zero, the partition of
//   unity holds;
// - `interior modes = body load` in an element with a soft ball in a stiff
//   matrix: the lattice nodes' Phi_I are unchanged to the last bit; the
//   mode and its gradient vanish on every face between elements (so Phi
//   stays C1); its largest entry at the particles is 1; its mean size in
//   the soft ball is much larger than in the stiff matrix (printed).

#include <bfemp/cmpm/coarsened_shape_functions.h>
#include <bfemp/material/material.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "cmpm/cmpm_test_scene.h"
#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  bfemp_tests::RandomNumbers random_numbers(2024);

  template <int dim>
  using Values =
    std::map<std::size_t, std::pair<Tensor<2, dim>, Tensor<3, dim>>>;

  template <int dim>
  Values<dim>
  evaluate(const CoarsenedShapeFunctions<dim> &phi,
           const std::array<int, dim>         &element,
           const Point<dim>                   &x)
  {
    std::vector<CoarseShapeValue<dim>> values;
    phi.evaluate(element, x, values);
    Values<dim> result;
    for (const auto &v : values)
      {
        result[v.node].first += v.value;
        result[v.node].second += v.gradient;
      }
    return result;
  }

  /** Largest value and gradient difference (gradient times H) over nodes. */
  template <int dim>
  std::pair<double, double>
  difference(Values<dim> a, const Values<dim> &b, const double H)
  {
    for (const auto &[node, v] : b)
      {
        a[node].first -= v.first;
        a[node].second -= v.second;
      }
    double value = 0., gradient = 0.;
    for (const auto &[node, v] : a)
      {
        value    = std::max(value, v.first.norm());
        gradient = std::max(gradient, v.second.norm() * H);
      }
    return {value, gradient};
  }

  template <int dim>
  Point<dim>
  random_point_in(const CoarseGrid<dim> &grid, const std::array<int, dim> &e)
  {
    Point<dim> x = grid.element_origin(e);
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += random_numbers.uniform(0., grid.element_size());
    return x;
  }

  /**
   * Calls @p f(element, neighbour, x) at 12 random points x on every face
   * between two elements of a block of n_1d^dim, a quarter of them moved
   * onto an edge or a corner of the face.
   */
  template <int dim, typename Function>
  void
  for_each_face_point(const CoarseGrid<dim> &grid,
                      const unsigned int     n_1d,
                      const Function        &f)
  {
    for (std::size_t e = 0; e < grid.n_elements_total(); ++e)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto element = grid.element_multi_index(e);
          if (element[d] + 1 >= static_cast<int>(n_1d))
            continue;
          auto neighbour = element;
          ++neighbour[d];
          for (unsigned int q = 0; q < 12; ++q)
            {
              Point<dim> x = random_point_in<dim>(grid, element);
              x[d]         = grid.element_origin(neighbour)[d];
              if (q % 4 == 1) // on an edge / at a corner of the face
                for (unsigned int g = 0; g < dim; ++g)
                  if (g != d && (q / 4 + g) % 2 == 0)
                    x[g] = grid.element_origin(element)[g];
              f(element, neighbour, x);
            }
        }
  }

  template <int dim>
  void
  test(const CmpmParameters &prm, const bool heterogeneous)
  {
    const std::string name =
      std::to_string(dim) + "D " + bfemp_tests::variant_name(prm) +
      (heterogeneous ? ", heterogeneous" : ", homogeneous");
    const unsigned int              n_1d = dim == 2 ? 3 : 2;
    const double                    H    = 0.5;
    bfemp_tests::CmpmTestScene<dim> scene(prm, n_1d, H);

    const auto soft =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3));
    const auto stiff =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e8, 0.3));
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.45 * n_1d * H;
    const double extent = n_1d * H;
    scene.build(
      [&](const Point<dim> &x) -> const Material<dim> * {
        if (!heterogeneous)
          return soft.get();
        if (x[0] > 0.8 * extent)
          return nullptr; // void: empty knot spans
        return (x - centre).norm() < 0.22 * extent ? stiff.get() : soft.get();
      },
      2);
    const CoarsenedShapeFunctions<dim> &phi  = scene.shape_functions;
    const CoarseGrid<dim>              &grid = scene.grid;

    // partition of unity at random points of every element
    double max_unity = 0., max_gradient = 0., max_off_diagonal = 0.;
    for (std::size_t e = 0; e < grid.n_elements_total(); ++e)
      for (unsigned int q = 0; q < 20; ++q)
        {
          const auto element = grid.element_multi_index(e);
          const auto values =
            evaluate<dim>(phi, element, random_point_in<dim>(grid, element));
          Tensor<2, dim> sum;
          Tensor<3, dim> sum_gradient;
          for (const auto &[node, v] : values)
            {
              sum += v.first;
              sum_gradient += v.second;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int c = 0; c < dim; ++c)
                  if (a != c)
                    max_off_diagonal =
                      std::max(max_off_diagonal, std::abs(v.first[a][c]));
            }
          max_unity = std::max(
            max_unity,
            (sum - Tensor<2, dim>(unit_symmetric_tensor<dim>())).norm());
          max_gradient = std::max(max_gradient, sum_gradient.norm() * H);
        }
    bfemp_tests::check(max_unity < 1e-11,
                       name + ": sum_I Phi_I = I (eq. 34), to 1e-11");
    bfemp_tests::check(max_gradient < 1e-10,
                       name + ": sum_I grad Phi_I = 0, to 1e-10 / H");
    // The local equilibrium couples the components (Poisson effect), so
    // Phi_I has off-diagonal entries even in a homogeneous element.
    deallog << name
            << ": largest off-diagonal |(Phi_I)_ac| = " << std::setprecision(2)
            << max_off_diagonal << std::setprecision(8) << std::endl;
    bfemp_tests::check(max_off_diagonal > 1e-3,
                       name + ": matrix-valued (off-diagonal entries)");

    // the faces between neighbours: random points on the face, on its edges
    // and at its corners
    double max_value_jump = 0., max_gradient_jump = 0.;
    max_gradient = 0.;
    for_each_face_point<dim>(
      grid,
      n_1d,
      [&](const std::array<int, dim> &element,
          const std::array<int, dim> &neighbour,
          const Point<dim>           &x) {
        const auto here   = evaluate<dim>(phi, element, x);
        const auto there  = evaluate<dim>(phi, neighbour, x);
        const auto jump   = difference<dim>(here, there, H);
        max_value_jump    = std::max(max_value_jump, jump.first);
        max_gradient_jump = std::max(max_gradient_jump, jump.second);
        for (const auto &[node, v] : here)
          max_gradient = std::max(max_gradient, v.second.norm() * H);
      });
    bfemp_tests::check(max_value_jump < 1e-12,
                       name + ": Phi_I continuous across faces, to 1e-12");
    bfemp_tests::check(max_gradient_jump < 1e-11 * std::max(1., max_gradient),
                       name + ": grad Phi_I continuous across faces "
                              "(Theorem 3), to 1e-11 relative");

    // knot lines inside an element
    double       max_knot_jump = 0.;
    const double s             = grid.knot_span();
    for (unsigned int q = 0; q < 20; ++q)
      {
        const auto element =
          grid.element_multi_index(q % grid.n_elements_total());
        Point<dim>         x = random_point_in<dim>(grid, element);
        const unsigned int d = q % dim;
        x[d]                 = grid.element_origin(element)[d] +
               s * (1 + q % (grid.n_fine_1d() - 3));
        Point<dim> below = x, above = x;
        below[d] -= 1e-9 * s;
        above[d] += 1e-9 * s;
        max_knot_jump =
          std::max(max_knot_jump,
                   difference<dim>(evaluate<dim>(phi, element, below),
                                   evaluate<dim>(phi, element, above),
                                   H)
                     .second);
      }
    bfemp_tests::check(max_knot_jump < 1e-6 * std::max(1., max_gradient),
                       name + ": no gradient jump across the knot lines "
                              "inside an element");
  }

  /** The multilinear (C0) comparison element fails the face test. */
  template <int dim>
  void
  test_multilinear()
  {
    CmpmParameters prm;
    prm.element_type   = CmpmParameters::ElementType::multilinear;
    prm.nodes_per_span = 1;
    const double                    H = 0.5;
    bfemp_tests::CmpmTestScene<dim> scene(prm, 2, H);
    const auto                      material =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3));
    scene.build([&](const Point<dim> &) { return material.get(); }, 2);

    std::array<int, dim> element{}, neighbour{};
    neighbour[0]          = 1;
    double max_value_jump = 0., max_gradient_jump = 0., max_unity = 0.;
    for (unsigned int q = 0; q < 20; ++q)
      {
        Point<dim> x    = random_point_in<dim>(scene.grid, element);
        x[0]            = H;
        const auto here = evaluate<dim>(scene.shape_functions, element, x);
        const auto jump =
          difference<dim>(here,
                          evaluate<dim>(scene.shape_functions, neighbour, x),
                          H);
        max_value_jump    = std::max(max_value_jump, jump.first);
        max_gradient_jump = std::max(max_gradient_jump, jump.second);
        Tensor<2, dim> sum;
        for (const auto &[node, v] : here)
          sum += v.first;
        max_unity =
          std::max(max_unity,
                   (sum - Tensor<2, dim>(unit_symmetric_tensor<dim>())).norm());
      }
    const std::string name = std::to_string(dim) + "D multilinear (C0)";
    bfemp_tests::check(max_unity < 1e-12, name + ": partition of unity");
    bfemp_tests::check(max_value_jump < 1e-12,
                       name + ": Phi_I continuous across the face (C0)");
    deallog << name << ": largest gradient jump across the face, times H = "
            << std::setprecision(3) << max_gradient_jump << std::setprecision(8)
            << std::endl;
    bfemp_tests::check(max_gradient_jump > 1e-2,
                       name + ": grad Phi_I jumps across the face (not C1)");
  }

  /** The diagonal form: no off-diagonal entries, the partition of unity. */
  template <int dim>
  void
  test_diagonal(const CmpmParameters::ElementType type)
  {
    CmpmParameters prm;
    prm.element_type        = type;
    prm.nodes_per_span      = 1;
    prm.shape_function_form = CmpmParameters::ShapeFunctionForm::diagonal;
    const double                    H = 0.5;
    bfemp_tests::CmpmTestScene<dim> scene(prm, 2, H);
    const auto                      soft =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3));
    const auto stiff =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e8, 0.3));
    scene.build(
      [&](const Point<dim> &x) {
        return x[0] + 0.5 * x[1] < 0.6 ? stiff.get() : soft.get();
      },
      2);
    double max_off_diagonal = 0., max_unity = 0., max_diagonal = 0.;
    for (std::size_t e = 0; e < scene.grid.n_elements_total(); ++e)
      for (unsigned int q = 0; q < 20; ++q)
        {
          const auto element = scene.grid.element_multi_index(e);
          const auto values =
            evaluate<dim>(scene.shape_functions,
                          element,
                          random_point_in<dim>(scene.grid, element));
          Tensor<2, dim> sum;
          for (const auto &[node, v] : values)
            {
              sum += v.first;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    if (a == c)
                      max_diagonal =
                        std::max(max_diagonal, std::abs(v.first[a][a]));
                    else
                      max_off_diagonal = std::max({max_off_diagonal,
                                                   std::abs(v.first[a][c]),
                                                   v.second[a][c].norm()});
                  }
            }
          max_unity = std::max(
            max_unity,
            (sum - Tensor<2, dim>(unit_symmetric_tensor<dim>())).norm());
        }
    const std::string name = std::to_string(dim) + "D " +
                             CmpmParameters::to_string(type) +
                             ", diagonal form";
    bfemp_tests::check(max_off_diagonal == 0. && max_diagonal > 0.1,
                       name + ": every off-diagonal entry of Phi_I and "
                              "grad Phi_I is zero");
    bfemp_tests::check(max_unity < 1e-12, name + ": partition of unity");
  }

  /** The interior body-load modes of a heterogeneous block. */
  template <int dim>
  void
  test_interior_modes()
  {
    CmpmParameters prm;
    prm.interior_modes = CmpmParameters::InteriorModes::body_load;
    CmpmParameters                  plain_prm;
    const unsigned int              n_1d = 2;
    const double                    H    = 0.5;
    bfemp_tests::CmpmTestScene<dim> scene(prm, n_1d, H),
      plain(plain_prm, n_1d, H);
    const auto soft =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e2, 0.3));
    const auto stiff =
      create_material<dim>("neo-Hookean",
                           ElasticModuli::from_young_poisson(1e5, 0.3));
    // a soft ball inside each element, off centre
    const auto material_at = [&](const Point<dim> &x) {
      Point<dim> local;
      for (unsigned int d = 0; d < dim; ++d)
        local[d] = std::fmod(x[d], H) / H - 0.45;
      return local.norm() < 0.25 ? soft.get() : stiff.get();
    };
    scene.build(material_at, 2);
    plain.build(material_at, 2);
    const CoarseGrid<dim> &grid = scene.grid;
    const std::string      name = std::to_string(dim) + "D interior modes";
    bfemp_tests::check(grid.n_element_unknowns() ==
                           plain.grid.n_local_nodes() + 1 &&
                         grid.n_unknown_nodes() == grid.node_lattice().n_nodes +
                                                     grid.n_elements_total(),
                       name + ": one node per element after the lattice");

    // the lattice nodes unchanged; the mode's size in soft and stiff parts
    double       lattice_difference = 0., largest_at_particles = 0.;
    double       soft_sum = 0., stiff_sum = 0.;
    unsigned int n_soft = 0, n_stiff = 0;
    std::vector<CoarseShapeValue<dim>> with, without;
    for (const Point<dim> &x : scene.particle_positions)
      {
        const auto element = grid.element_of(x);
        scene.shape_functions.evaluate(element, x, with);
        plain.shape_functions.evaluate(element, x, without);
        for (unsigned int I = 0; I < without.size(); ++I)
          lattice_difference =
            std::max(lattice_difference,
                     (with[I].value - without[I].value).norm() +
                       (with[I].gradient - without[I].gradient).norm());
        const CoarseShapeValue<dim> &mode = with.back();
        double                       size = 0.;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int c = 0; c < dim; ++c)
            size = std::max(size, std::abs(mode.value[a][c]));
        largest_at_particles = std::max(largest_at_particles, size);
        if (material_at(x) == soft.get())
          {
            soft_sum += size;
            ++n_soft;
          }
        else
          {
            stiff_sum += size;
            ++n_stiff;
          }
      }
    bfemp_tests::check(lattice_difference == 0.,
                       name + ": the lattice nodes' Phi_I and grad Phi_I "
                              "unchanged");
    bfemp_tests::check(std::abs(largest_at_particles - 1.) < 1e-12,
                       name + ": the mode's largest entry at the particles "
                              "is 1");
    const double ratio = (soft_sum / n_soft) / (stiff_sum / n_stiff);
    deallog << name << ": mean |mode| in the soft balls / in the stiff matrix "
            << std::setprecision(3) << ratio << std::setprecision(8)
            << std::endl;
    bfemp_tests::check(ratio > 5.,
                       name + ": the mode sits in the soft balls (ratio > "
                              "5)");

    // on the faces between elements the mode and its gradient vanish
    double max_on_face = 0.;
    for_each_face_point<dim>(
      grid,
      n_1d,
      [&](const std::array<int, dim> &element,
          const std::array<int, dim> &neighbour,
          const Point<dim>           &x) {
        for (const auto &side : {element, neighbour})
          {
            scene.shape_functions.evaluate(side, x, with);
            max_on_face = std::max(max_on_face,
                                   with.back().value.norm() +
                                     H * with.back().gradient.norm());
          }
      });
    bfemp_tests::check(max_on_face < 1e-14,
                       name + ": the mode and its gradient vanish on the "
                              "faces between elements (Phi stays C1)");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  for (const CmpmParameters &prm : bfemp_tests::cmpm_variants())
    for (const bool heterogeneous : {false, true})
      test<2>(prm, heterogeneous);
  test_multilinear<2>();
  for (const CmpmParameters &prm : bfemp_tests::cmpm_variants())
    for (const bool heterogeneous : {false, true})
      test<3>(prm, heterogeneous);
  test_multilinear<3>();
  // (after the others: they share the random points)
  for (const auto type : {CmpmParameters::ElementType::multilinear,
                          CmpmParameters::ElementType::boundary_bspline})
    {
      test_diagonal<2>(type);
      test_diagonal<3>(type);
    }
  test_interior_modes<2>();
  test_interior_modes<3>();
}
