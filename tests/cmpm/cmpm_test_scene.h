#ifndef bfemp_tests_cmpm_test_scene_h
#define bfemp_tests_cmpm_test_scene_h

// A block of coarse elements filled with particles for the cMPM shape
// function tests: particles at the regular sub-cell positions of the fine
// knot spans (ppc per span and direction), optionally jittered; the material
// of each particle from a function of its position (nullptr = void, no
// particle), so that homogeneous, heterogeneous (stiff inclusion) and
// partly empty elements can be built.

#include <bfemp/cmpm/coarsened_shape_functions.h>
#include <bfemp/material/material.h>

#include <functional>
#include <memory>
#include <vector>

#include "tests.h"

namespace bfemp_tests
{
  using namespace dealii;
  using namespace bfemp;

  template <int dim>
  struct CmpmTestScene
  {
    using MaterialAt = std::function<const Material<dim> *(const Point<dim> &)>;

    CmpmTestScene(const CmpmParameters &parameters,
                  const unsigned int    n_elements_1d,
                  const double          H = 0.5)
      : grid(Point<dim>(), H, uniform<unsigned int>(n_elements_1d), parameters)
      , shape_functions(grid)
    {}

    template <typename T>
    static std::array<T, dim>
    uniform(const T value)
    {
      std::array<T, dim> a;
      a.fill(value);
      return a;
    }

    /**
     * Samples every element with ppc^dim particles per knot span, each at
     * its sub-cell centre moved by up to jitter sub-cells, with deformation
     * gradient F, and rebuilds the shape functions of every element.
     */
    void
    build(const MaterialAt     &material_at,
          const unsigned int    ppc,
          const double          jitter = 0.,
          const Tensor<2, dim> &F      = unit_symmetric_tensor<dim>())
    {
      RandomNumbers      random(77);
      const double       s      = grid.knot_span();
      const unsigned int spans  = grid.n_fine_1d() - 2;
      const unsigned int per_1d = spans * ppc;
      const double       h      = s / ppc;
      unsigned int       total  = 1;
      for (unsigned int d = 0; d < dim; ++d)
        total *= per_1d;

      std::vector<std::size_t>                            elements;
      std::vector<std::vector<LocalQuadraturePoint<dim>>> points;
      for (std::size_t e = 0; e < grid.n_elements_total(); ++e)
        {
          const Point<dim> corner =
            grid.element_origin(grid.element_multi_index(e));
          std::vector<LocalQuadraturePoint<dim>> element_points;
          for (unsigned int flat = 0; flat < total; ++flat)
            {
              Point<dim>   x;
              unsigned int rest = flat;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  x[d] =
                    (rest % per_1d + 0.5 + random.uniform(-jitter, jitter)) * h;
                  rest /= per_1d;
                }
              const Material<dim> *material = material_at(corner + x);
              if (material == nullptr)
                continue;
              LocalQuadraturePoint<dim> point;
              point.position             = x;
              point.weight               = std::pow(h, dim);
              point.mass                 = density * point.weight;
              point.deformation_gradient = F;
              point.tangent              = material->tangent(F, true);
              element_points.push_back(point);
              particle_positions.push_back(corner + x);
            }
          elements.push_back(e);
          points.push_back(element_points);
        }
      shape_functions.reinit(elements, points);
    }

    /** u(x) = sum_I Phi_I(x) Q(X_I) and grad u for a nodal field Q. */
    template <typename Field>
    std::pair<Tensor<1, dim>, Tensor<2, dim>>
    interpolate(const std::array<int, dim> &element,
                const Point<dim>           &x,
                const Field                &Q) const
    {
      std::vector<CoarseShapeValue<dim>> values;
      shape_functions.evaluate(element, x, values);
      Tensor<1, dim> u;
      Tensor<2, dim> grad_u;
      for (const auto &v : values)
        {
          const Tensor<1, dim> Q_I =
            Q(grid.node_lattice().node_position(v.node));
          u += v.value * Q_I;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int c = 0; c < dim; ++c)
              grad_u[a] += Q_I[c] * v.gradient[a][c];
        }
      return {u, grad_u};
    }

    /** The particles' density [kg/m^3] (the interior modes' body load). */
    double                       density = 1000.;
    CoarseGrid<dim>              grid;
    CoarsenedShapeFunctions<dim> shape_functions;
    std::vector<Point<dim>>      particle_positions;
  };

  /** The element types and node spans of seed 002 Section 5.1, and the
   *  boundary B-spline element with L = H/3 (its Section 8.2.1). */
  inline std::vector<CmpmParameters>
  cmpm_variants(const unsigned int n = 7)
  {
    std::vector<CmpmParameters> variants;
    const auto add = [&](const CmpmParameters::ElementType type,
                         const unsigned int                l) {
      CmpmParameters p;
      p.element_type   = type;
      p.nodes_per_span = l;
      p.n_fine         = n;
      variants.push_back(p);
    };
    for (const auto type : {CmpmParameters::ElementType::bspline,
                            CmpmParameters::ElementType::boundary_bspline})
      for (const unsigned int l : {1u, 2u})
        add(type, l);
    add(CmpmParameters::ElementType::boundary_bspline, 3);
    return variants;
  }

  inline std::string
  variant_name(const CmpmParameters &p)
  {
    return CmpmParameters::to_string(p.element_type) +
           ", L = " + CmpmParameters::node_span_to_string(p.nodes_per_span) +
           ", n = " + std::to_string(p.n_fine);
  }
} // namespace bfemp_tests

#endif
