// Body sampling (BodySampler, Shape, ShapePrimitive): the sampled volume
// N V_p of every primitive converges to its exact area/volume under
// refinement; the CSG operations produce what they promise (a disk minus a
// smaller disk samples exactly like the ring primitive, a union of
// overlapping boxes has no duplicate particles, a semi-ring is half a ring);
// jittered sampling puts exactly one particle in each sub-cell of a box.

#include <bfemp/grid/lattice.h>
#include <bfemp/particles/body_sampler.h>

#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  template <int dim>
  ShapePrimitive<dim>
  primitive(const typename ShapePrimitive<dim>::Type type,
            const double                             inner,
            const double                             outer,
            const bool                               subtract = false)
  {
    ShapePrimitive<dim> p;
    p.type         = type;
    p.subtract     = subtract;
    p.inner_radius = inner;
    p.outer_radius = outer;
    for (unsigned int d = 0; d < dim; ++d)
      {
        p.center[d]       = 0.5;
        p.lower_corner[d] = 0.3;
        p.upper_corner[d] = 0.65;
      }
    p.direction[1] = 1.;
    return p;
  }

  template <int dim>
  BodyParameters<dim>
  body(const std::vector<ShapePrimitive<dim>> &primitives,
       const bool                              jittered = false)
  {
    BodyParameters<dim> b;
    b.primitives              = primitives;
    b.particles_per_direction = 2;
    b.jittered                = jittered;
    return b;
  }

  template <int dim>
  Lattice<dim>
  lattice(const unsigned int n)
  {
    std::array<unsigned int, dim> cells;
    cells.fill(n);
    return Lattice<dim>(Point<dim>(), 1. / n, cells);
  }

  /** Relative error of N V_p against @p exact on grids of 32 and 128 cells
   *  (0.3 .. 0.65 boxes are deliberately not aligned with the sub-cells). */
  template <int dim>
  void
  check_volume(const std::string                      &name,
               const std::vector<ShapePrimitive<dim>> &primitives,
               const double                            exact)
  {
    double errors[2];
    for (unsigned int k = 0; k < 2; ++k)
      {
        const Lattice<dim>     grid = lattice<dim>(k == 0 ? 32 : 128);
        const BodySampler<dim> sampler(body(primitives), grid);
        errors[k] =
          std::abs(sampler.sample().size() * sampler.particle_volume() -
                   exact) /
          exact;
      }
    // Sampling is first order in the sub-cell size at curved or unaligned
    // surfaces (at most about dim * sub-cell / size = 2e-2 here): a 4x finer
    // grid must at least halve the error.
    bfemp_tests::check(errors[1] < 0.5 * errors[0] && errors[1] < 3e-2,
                       std::to_string(dim) + "D " + name +
                         ": sampled volume converges to the exact one: "
                         "relative error " +
                         bfemp_tests::format("%.1e", errors[0]) +
                         " on 32 cells, " +
                         bfemp_tests::measured(errors[1], 3e-2) +
                         " on 128 cells, ratio " +
                         bfemp_tests::measured(errors[1] / errors[0], 0.5));
  }

  template <int dim>
  void
  run()
  {
    using Type      = typename ShapePrimitive<dim>::Type;
    const double pi = numbers::PI;
    const double r = 0.3, inner = 0.2;
    const double ball = dim == 2 ? pi * r * r : 4. / 3. * pi * r * r * r;
    const double hole =
      dim == 2 ? pi * inner * inner : 4. / 3. * pi * inner * inner * inner;
    check_volume<dim>("box",
                      {primitive<dim>(Type::box, 0, 0)},
                      std::pow(0.35, dim));
    check_volume<dim>("ball", {primitive<dim>(Type::ball, 0, r)}, ball);
    check_volume<dim>("shell",
                      {primitive<dim>(Type::shell, inner, r)},
                      ball - hole);
    check_volume<dim>("semi-shell",
                      {primitive<dim>(Type::semi_shell, inner, r)},
                      0.5 * (ball - hole));

    // Ball minus ball = shell, particle for particle.
    const Lattice<dim> grid = lattice<dim>(64);
    const auto         shell =
      BodySampler<dim>(body<dim>({primitive<dim>(Type::shell, inner, r)}), grid)
        .sample();
    const auto difference =
      BodySampler<dim>(body<dim>({primitive<dim>(Type::ball, 0, r),
                                  primitive<dim>(Type::ball, 0, inner, true)}),
                       grid)
        .sample();
    unsigned int n_differing = 0;
    for (unsigned int i = 0; i < std::min(shell.size(), difference.size()); ++i)
      n_differing += (shell[i] != difference[i]);
    bfemp_tests::check(shell == difference,
                       std::to_string(dim) +
                         "D ball minus ball samples exactly like the shell: " +
                         std::to_string(difference.size()) + " particles (" +
                         std::to_string(shell.size()) + " in the shell), " +
                         std::to_string(n_differing) + " at other positions");

    // A union of overlapping boxes: no sample twice, and the count is the
    // union's volume / V_p exactly (boxes aligned with sub-cells).
    auto second = primitive<dim>(Type::box, 0, 0);
    for (unsigned int d = 0; d < dim; ++d)
      {
        second.lower_corner[d] = 0.5;
        second.upper_corner[d] = 0.8;
      }
    const auto union_samples =
      BodySampler<dim>(body<dim>({primitive<dim>(Type::box, 0, 0), second}),
                       lattice<dim>(40))
        .sample();
    std::set<std::vector<double>> distinct;
    for (const auto &x : union_samples)
      distinct.insert(std::vector<double>(x.begin_raw(), x.end_raw()));
    const double union_volume =
      std::pow(0.35, dim) + std::pow(0.3, dim) - std::pow(0.15, dim);
    const double sub_volume = std::pow(1. / 80., dim);
    bfemp_tests::check(distinct.size() == union_samples.size(),
                       std::to_string(dim) + "D union has no duplicates: " +
                         std::to_string(union_samples.size() -
                                        distinct.size()) +
                         " duplicates among " +
                         std::to_string(union_samples.size()) + " particles");
    bfemp_tests::check(
      std::abs(union_samples.size() * sub_volume - union_volume) < 1e-9,
      std::to_string(dim) + "D union count = union volume / V_p: " +
        std::to_string(union_samples.size()) + " particles, |N V_p - V| " +
        bfemp_tests::measured(std::abs(union_samples.size() * sub_volume -
                                       union_volume),
                              1e-9));

    // Jittered: one particle per sub-cell of an aligned box, inside it.
    const Lattice<dim> jitter_grid = lattice<dim>(40);
    const auto         regular =
      BodySampler<dim>(body<dim>({primitive<dim>(Type::box, 0, 0)}),
                       jitter_grid)
        .sample();
    const auto jittered =
      BodySampler<dim>(body<dim>({primitive<dim>(Type::box, 0, 0)}, true),
                       jitter_grid)
        .sample();
    bool one_per_subcell = regular.size() == jittered.size();
    std::set<std::vector<long>> subcells;
    for (const auto &x : jittered)
      {
        std::vector<long> index;
        for (unsigned int d = 0; d < dim; ++d)
          index.push_back(static_cast<long>(std::floor(x[d] * 80.)));
        subcells.insert(index);
      }
    one_per_subcell = one_per_subcell && subcells.size() == jittered.size();
    unsigned int n_moved = 0;
    for (unsigned int i = 0; i < std::min(regular.size(), jittered.size()); ++i)
      n_moved += (jittered[i] != regular[i]);
    bfemp_tests::check(
      one_per_subcell && jittered != regular,
      std::to_string(dim) +
        "D jittered sampling: one random point per sub-cell: " +
        std::to_string(jittered.size()) + " particles (" +
        std::to_string(regular.size()) + " regular) in " +
        std::to_string(subcells.size()) + " sub-cells, " +
        std::to_string(n_moved) +
        " moved off the regular "
        "points");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  run<2>();
  run<3>();
}
