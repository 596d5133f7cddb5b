// LinearElasticReference (the static FE_Q(2) benchmark of seed 002 Section
// 8.2) on problems whose solution is quadratic, so that FE_Q(2) must
// reproduce it to round-off: a bar along x, held at x = 0 and on its sides
// by slip walls (u_x(0) = 0, u_y = u_z = 0 on the sides: uniaxial strain),
// loaded by gravity g along x and a traction t on its end face x = L, with
// two materials (x < L/2 and x > L/2, P-wave moduli M_1 and M_2). Statics
// gives sigma_xx(x) = t + rho g (L - x), so
//   du_x/dx = sigma_xx(x) / M(x),   u_x(x) = int_0^x sigma_xx / M,
// piecewise quadratic with the kink on a mesh plane. Checked in 2D (plane
// strain) and 3D at random points, values and gradients, and the refusals
// of scenes the reference does not solve.

#include <bfemp/base/input_error.h>
#include <bfemp/grid/background_grid.h>
#include <bfemp/reference/linear_elastic_reference.h>
#include <bfemp/scene/scene_parameters.h>

#include <fstream>

#include "../format.h"
#include "../tests.h"

using namespace dealii;
using namespace bfemp;

namespace
{
  constexpr double L = 1., rho = 800., g = 3., t = 2000.;
  constexpr double E1 = 1e5, E2 = 4e5, nu = 0.3;

  /** The P-wave modulus lambda + 2 mu (uniaxial strain). */
  double
  p_wave_modulus(const double E)
  {
    return E * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
  }

  double
  sigma_xx(const double x)
  {
    return t + rho * g * (L - x);
  }

  /** u_x(x) = int_0^x sigma_xx / M. */
  double
  u_x(const double x)
  {
    const auto integral = [](const double a, const double b) {
      return t * (b - a) + rho * g * (L * (b - a) - (b * b - a * a) / 2.);
    };
    const double M1 = p_wave_modulus(E1), M2 = p_wave_modulus(E2);
    return x <= L / 2 ? integral(0., x) / M1
                      : integral(0., L / 2) / M1 + integral(L / 2, x) / M2;
  }

  template <int dim>
  std::string
  scene(const std::string &primitive_extra = "")
  {
    const std::string zeros    = dim == 2 ? "0, 0" : "0, 0, 0";
    const std::string upper    = dim == 2 ? "1, 0.5" : "1, 0.5, 0.5";
    const std::string walls    = dim == 2 ? "x-, y-, y+" : "x-, y-, y+, z-, z+";
    const std::string traction = dim == 2 ? "2000, 0" : "2000, 0, 0";
    const std::string gravity  = dim == 2 ? "3, 0" : "3, 0, 0";
    const std::string region_lower = dim == 2 ? "0.5, 0" : "0.5, 0, 0";
    return "set dimension = " + std::to_string(dim) +
           "\nsubsection grid\n  set lower corner = " +
           (dim == 2 ? "-0.25, -0.25" : "-0.25, -0.25, -0.25") +
           "\n  set upper corner = " +
           (dim == 2 ? "1.5, 0.75" : "1.5, 0.75, 0.75") +
           "\n  set cell size = 0.25\nend\n"
           "subsection time\n  set integrator = implicit backward Euler\n"
           "end\n"
           "subsection gravity\n  set acceleration = " +
           gravity +
           "\nend\n"
           "subsection boundaries\n  set walls = " +
           walls +
           "\n  set wall condition = slip\n  set wall layers = 1\nend\n"
           "subsection body 0\n"
           "  set number of material regions = 1\n"
           "  set number of surface loads = 1\n"
           "  subsection primitive 0\n    set type = box\n"
           "    set lower corner = " +
           zeros + "\n    set upper corner = " + upper + "\n" +
           primitive_extra +
           "  end\n"
           "  subsection surface load 0\n    set face = x+\n"
           "    set traction = " +
           traction +
           "\n  end\n"
           "  subsection material\n    set model = linear elastic\n"
           "    set Young's modulus = 1e5\n    set Poisson's ratio = 0.3\n"
           "    set density = 800\n  end\n"
           "  subsection material region 0\n    set type = box\n"
           "    set lower corner = " +
           region_lower + "\n    set upper corner = " + upper +
           "\n    subsection material\n      set model = linear elastic\n"
           "      set Young's modulus = 4e5\n"
           "      set Poisson's ratio = 0.3\n      set density = 800\n"
           "    end\n  end\nend\n";
  }

  template <int dim>
  SceneParameters<dim>
  read(const std::string &text)
  {
    const std::string file = "scene_" + std::to_string(dim) + "d.prm";
    std::ofstream(file) << text;
    SceneParameters<dim> parameters;
    parameters.read(file);
    return parameters;
  }

  template <int dim>
  LinearElasticReference<dim>
  reference(const SceneParameters<dim> &parameters, const double cell_size)
  {
    static std::vector<std::unique_ptr<BackgroundGrid<dim>>> grids;
    grids.push_back(std::make_unique<BackgroundGrid<dim>>(parameters.grid));
    return LinearElasticReference<dim>(parameters.bodies[0],
                                       parameters.boundaries,
                                       grids.back()->lattice(),
                                       parameters.gravity,
                                       1.,
                                       cell_size,
                                       2,
                                       "subsection 'body 0'");
  }

  template <int dim>
  void
  check_bar(const typename LinearElasticReference<dim>::Solver solver)
  {
    const SceneParameters<dim>  parameters = read<dim>(scene<dim>());
    LinearElasticReference<dim> bar        = reference(parameters, 0.125);
    const auto                  statistics = bar.solve(solver);
    using bfemp_tests::format;
    deallog << dim << "D bar: " << statistics.n_cells << " cells, "
            << statistics.n_dofs << " unknowns, " << statistics.n_constrained
            << " held by the walls, " << statistics.solver << "; max |u_i| "
            << format("%.6e", statistics.max_displacement) << " (exact "
            << format("%.6e", u_x(L)) << ")" << std::endl;

    bfemp_tests::RandomNumbers random(7);
    std::vector<Point<dim>>    X;
    for (unsigned int i = 0; i < 200; ++i)
      {
        Point<dim> x;
        x[0] = random.uniform(0., L);
        for (unsigned int d = 1; d < dim; ++d)
          x[d] = random.uniform(0., 0.5);
        X.push_back(x);
      }
    // a point on the interface and corners of the box
    X.push_back(dim == 2 ? Point<dim>(0.5, 0.25) : Point<dim>(0.5, 0.25, 0.1));
    X.push_back(Point<dim>());
    const std::vector<Tensor<1, dim>> u       = bar.displacements(X);
    const std::vector<Tensor<2, dim>> grad    = bar.displacement_gradients(X);
    double                            u_error = 0., grad_error = 0.;
    for (unsigned int i = 0; i < X.size(); ++i)
      {
        Tensor<1, dim> u_exact;
        u_exact[0] = u_x(X[i][0]);
        u_error    = std::max(u_error, (u[i] - u_exact).norm() / u_x(L));
        if (std::abs(X[i][0] - L / 2) < 1e-12)
          continue; // the strain jumps there
        Tensor<2, dim> grad_exact;
        grad_exact[0][0] =
          sigma_xx(X[i][0]) / p_wave_modulus(X[i][0] < L / 2 ? E1 : E2);
        grad_error = std::max(grad_error,
                              (grad[i] - grad_exact).norm() /
                                (sigma_xx(0.) / p_wave_modulus(E1)));
      }
    // CG stops at a relative residual of 1e-10
    const bool   direct = statistics.iterations == 0;
    const double bound  = direct ? 1e-9 : 1e-7;
    bfemp_tests::check(u_error < bound,
                       std::to_string(dim) +
                         "D bar: u at 202 points exact to " +
                         format("%g", bound) + " (relative)");
    bfemp_tests::check(grad_error < 10 * bound,
                       std::to_string(dim) + "D bar: grad u exact to " +
                         format("%g", 10 * bound) + " (relative)");
  }

  template <int dim>
  void
  refused(const std::string &text,
          const double       cell_size,
          const std::string &what)
  {
    try
      {
        const SceneParameters<dim> parameters = read<dim>(text);
        reference(parameters, cell_size);
        bfemp_tests::check(false, "refused: " + what);
      }
    catch (const InputError &error)
      {
        deallog << error.what() << std::endl;
        bfemp_tests::check(true, "refused: " + what);
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();
  using Solver2 = LinearElasticReference<2>::Solver;
  using Solver3 = LinearElasticReference<3>::Solver;
  check_bar<2>(Solver2::automatic);
  check_bar<2>(Solver2::iterative);
  check_bar<3>(Solver3::automatic);
  check_bar<3>(Solver3::iterative);
  refused<2>(scene<2>(), 0.3, "a cell size that does not divide the box");
  refused<2>(scene<2>("    set rotation angle = 0.1\n"),
             0.125,
             "a rotated box");
  refused<3>(scene<3>(), 0.2, "a cell size that does not divide the box (3D)");
}
