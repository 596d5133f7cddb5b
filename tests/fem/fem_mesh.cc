// Checks FemMesh (linear simplex meshes of FEM bodies) for every source in 2D
// and 3D: rectangle/box (exact volume, colorized boundary ids), disk/ball,
// ring/spherical shell and semi-ring/half shell meshed by gmsh (volume
// within O((h/R)^2) of the exact one and converging, ids of the outer, inner
// and cut surfaces), a hand-written gmsh .msh file with physical lines and
// one clockwise triangle, and a .geo file meshed through gmsh. For every mesh:
// elements positively oriented, lumped masses summing to density * volume,
// boundary facets closed and outward (divergence theorem gives the volume),
// the Euler characteristic of the shape, DoF dim*n + c for component c of
// node n, and DataOut output. Finally bad input: a missing file, a wrong
// extension, a quadrilateral mesh, a broken .geo, bad radii, an absurdly
// small edge length.

#include <bfemp/base/input_error.h>
#include <bfemp/fem/fem_mesh.h>
#include <bfemp/fem/fem_mesh_parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>

#include "tests.h"

using namespace dealii;
using bfemp_tests::check;

namespace
{
  const std::string where = "fem body 0/mesh";

  template <int dim>
  bfemp::FemMeshParameters<dim>
  parameters(const std::string &entries, const std::string &prm_directory = ".")
  {
    ParameterHandler prm;
    prm.enter_subsection("mesh");
    bfemp::FemMeshParameters<dim>::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection mesh\n" + entries + "\nend\n");
    bfemp::FemMeshParameters<dim> result;
    prm.enter_subsection("mesh");
    result.parse_parameters(prm, where, prm_directory);
    prm.leave_subsection();
    return result;
  }

  template <int dim>
  double
  orientation(const bfemp::FemMesh<dim>                   &mesh,
              const typename bfemp::FemMesh<dim>::Element &element)
  {
    Tensor<2, dim> B;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int r = 0; r < dim; ++r)
        B[r][c] = mesh.rest_position(element[c + 1])[r] -
                  mesh.rest_position(element[0])[r];
    return determinant(B);
  }

  /** The facet's area-weighted outward normal as documented. */
  template <int dim>
  Tensor<1, dim>
  facet_normal(const bfemp::FemMesh<dim>                 &mesh,
               const typename bfemp::FemMesh<dim>::Facet &facet)
  {
    const Point<dim> &a = mesh.rest_position(facet[0]);
    Tensor<1, dim>    n;
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> edge = mesh.rest_position(facet[1]) - a;
        n[0]                      = edge[1];
        n[1]                      = -edge[0];
      }
    else
      n = 0.5 * cross_product_3d(mesh.rest_position(facet[1]) - a,
                                 mesh.rest_position(facet[2]) - a);
    return n;
  }

  /** V - E + F (- T in 3D) of the simplicial complex of the elements. */
  template <int dim>
  int
  euler_characteristic(const bfemp::FemMesh<dim> &mesh)
  {
    std::set<std::array<unsigned int, 2>> edges;
    std::set<std::array<unsigned int, 3>> triangles;
    for (auto element : mesh.elements())
      {
        std::sort(element.begin(), element.end());
        for (unsigned int a = 0; a < dim + 1; ++a)
          for (unsigned int b = a + 1; b < dim + 1; ++b)
            {
              edges.insert(
                std::array<unsigned int, 2>{{element[a], element[b]}});
              if constexpr (dim == 3)
                for (unsigned int c = b + 1; c < dim + 1; ++c)
                  triangles.insert(std::array<unsigned int, 3>{
                    {element[a], element[b], element[c]}});
            }
      }
    if constexpr (dim == 2)
      return int(mesh.n_nodes()) - int(edges.size()) + int(mesh.n_elements());
    else
      return int(mesh.n_nodes()) - int(edges.size()) + int(triangles.size()) -
             int(mesh.n_elements());
  }

  /**
   * 2D: the number of closed boundary loops (every boundary node starts one
   * edge and ends one). 3D: the Euler characteristic of the boundary surface
   * after checking that every directed boundary edge is met exactly once in
   * each direction (closed, consistently oriented). -1 if not closed.
   */
  template <int dim>
  int
  boundary_topology(const bfemp::FemMesh<dim> &mesh)
  {
    const auto &facets = mesh.boundary_facets();
    if constexpr (dim == 2)
      {
        std::map<unsigned int, unsigned int> next;
        std::map<unsigned int, unsigned int> in_degree;
        for (const auto &f : facets)
          {
            if (next.count(f[0]) > 0)
              return -1;
            next[f[0]] = f[1];
            ++in_degree[f[1]];
          }
        for (const auto &[node, degree] : in_degree)
          if (degree != 1 || next.count(node) == 0)
            return -1;
        if (next.size() != mesh.boundary_nodes().size())
          return -1;
        std::set<unsigned int> visited;
        int                    loops = 0;
        for (const auto &[start, ignored] : next)
          if (visited.count(start) == 0)
            {
              ++loops;
              for (unsigned int n = start; visited.insert(n).second;)
                n = next[n];
            }
        return loops;
      }
    else
      {
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> directed;
        for (const auto &f : facets)
          for (unsigned int i = 0; i < 3; ++i)
            ++directed[{f[i], f[(i + 1) % 3]}];
        for (const auto &[edge, count] : directed)
          {
            const auto reverse = directed.find({edge.second, edge.first});
            if (count != 1 || reverse == directed.end() || reverse->second != 1)
              return -1;
          }
        return int(mesh.boundary_nodes().size()) - int(directed.size() / 2) +
               int(facets.size());
      }
  }

  /** The checks every mesh must pass; @p name prefixes the output. */
  template <int dim>
  void
  check_mesh(const bfemp::FemMesh<dim> &mesh,
             const std::string         &name,
             const int                  expected_euler,
             const int                  expected_boundary)
  {
    bool positive = true;
    for (const auto &element : mesh.elements())
      positive = positive && orientation<dim>(mesh, element) > 0.;
    check(positive, name + ": every element positively oriented");

    double element_sum = 0.;
    for (unsigned int e = 0; e < mesh.n_elements(); ++e)
      element_sum += std::abs(orientation<dim>(mesh, mesh.elements()[e])) /
                     (dim == 2 ? 2. : 6.);
    const double volume = mesh.total_volume();
    check(std::abs(element_sum - volume) <= 1e-12 * volume,
          name + ": total volume = sum of element volumes");

    const double              density      = 1234.5;
    const std::vector<double> masses       = mesh.lumped_masses(density);
    double                    mass         = 0.;
    bool                      all_positive = masses.size() == mesh.n_nodes();
    for (const double m : masses)
      {
        mass += m;
        all_positive = all_positive && m > 0.;
      }
    check(all_positive &&
            std::abs(mass - density * volume) <= 1e-12 * density * volume,
          name + ": lumped masses positive, sum = density * volume");

    // Divergence theorem with the documented outward normals:
    // V = 1/dim sum over facets of x_centroid . n A.
    double flux = 0.;
    for (const auto &facet : mesh.boundary_facets())
      {
        Point<dim> centroid;
        for (const unsigned int node : facet)
          centroid += mesh.rest_position(node) / double(dim);
        flux += centroid * facet_normal<dim>(mesh, facet);
      }
    check(std::abs(flux / dim - volume) <= 1e-10 * volume,
          name + ": boundary facets outward (divergence theorem)");
    check(mesh.boundary_facet_ids().size() == mesh.boundary_facets().size(),
          name + ": one boundary id per facet");

    check(euler_characteristic(mesh) == expected_euler,
          name + ": Euler characteristic " + std::to_string(expected_euler));
    if (dim == 2)
      check(boundary_topology(mesh) == expected_boundary &&
              mesh.boundary_facets().size() == mesh.boundary_nodes().size(),
            name + ": boundary edges = boundary nodes, " +
              std::to_string(expected_boundary) + " closed loop(s)");
    else
      check(boundary_topology(mesh) == expected_boundary,
            name + ": boundary surface closed, oriented, chi = " +
              std::to_string(expected_boundary));

    // DoF dim*n + c is component c of node n, at the node's position.
    const auto &fe      = mesh.finite_element();
    bool        matches = mesh.dof_handler().n_dofs() == dim * mesh.n_nodes();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : mesh.dof_handler().active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const auto [component, vertex] = fe.system_to_component_index(i);
            const unsigned int node        = dofs[i] / dim;
            matches =
              matches && dofs[i] % dim == component &&
              mesh.rest_position(node).distance(cell->vertex(vertex)) == 0.;
          }
      }
    check(matches, name + ": DoF dim*n + c is component c of node n");

    std::vector<unsigned int> sorted = mesh.boundary_nodes();
    std::sort(sorted.begin(), sorted.end());
    bool ids_consistent = sorted == mesh.boundary_nodes();
    for (const auto id : mesh.boundary_ids())
      for (const unsigned int node : mesh.nodes_with_boundary_id(id))
        {
          const auto &ids = mesh.node_boundary_ids(node);
          ids_consistent  = ids_consistent &&
                           std::find(ids.begin(), ids.end(), id) != ids.end();
        }
    check(ids_consistent, name + ": node boundary ids consistent");
  }

  template <int dim>
  std::string
  ids_string(const bfemp::FemMesh<dim> &mesh)
  {
    std::string result;
    for (const auto id : mesh.boundary_ids())
      result += (result.empty() ? "" : " ") + std::to_string(id);
    return result;
  }

  /** Do all nodes with boundary id @p id satisfy @p on_surface? */
  template <int dim, typename Predicate>
  bool
  nodes_on(const bfemp::FemMesh<dim> &mesh,
           const types::boundary_id   id,
           const Predicate           &on_surface)
  {
    const auto nodes = mesh.nodes_with_boundary_id(id);
    for (const unsigned int n : nodes)
      if (!on_surface(mesh.rest_position(n)))
        return false;
    return !nodes.empty();
  }

  template <int dim>
  void
  check_rectangle()
  {
    const std::string name = dim == 2 ? "2D rectangle" : "3D box";
    // A thin plate: 1 x 0.2 (x 0.5), h = 0.1 gives 10 x 2 (x 5).
    const auto p = parameters<dim>(
      "set source = rectangle\n"
      "set lower corner = " +
      std::string(dim == 2 ? "0, 0" : "0, 0, 0") + "\nset upper corner = " +
      (dim == 2 ? "1, 0.2" : "1, 0.2, 0.5") + "\nset target edge length = 0.1");
    const bfemp::FemMesh<dim> mesh(p, where);
    const double              exact = dim == 2 ? 0.2 : 0.1;
    deallog << name << ": " << mesh.n_nodes() << " nodes, " << mesh.n_elements()
            << " elements, " << mesh.boundary_facets().size()
            << " boundary facets, ids " << ids_string(mesh) << std::endl;
    check(std::abs(mesh.total_volume() - exact) <= 1e-14,
          name + ": volume exact");
    check_mesh(mesh, name, 1, dim == 2 ? 1 : 2);
    check(std::abs(mesh.min_edge_length() - 0.1) < 1e-12,
          name + ": min edge length 0.1");

    const Point<dim> upper = p.upper_corner;
    bool             faces = true;
    for (unsigned int d = 0; d < dim; ++d)
      {
        faces = faces && nodes_on(mesh, 2 * d, [&](const Point<dim> &x) {
                  return std::abs(x[d]) < 1e-14;
                });
        faces = faces && nodes_on(mesh, 2 * d + 1, [&](const Point<dim> &x) {
                  return std::abs(x[d] - upper[d]) < 1e-14;
                });
      }
    check(faces, name + ": id 2d on x_d = lower, 2d+1 on x_d = upper");

    // Rotated about the box centre and moved: same volume, centroid moved by
    // the translation, the lower corner where the rotation puts it.
    const double angle = M_PI / 3.;
    const auto   q     = parameters<dim>(
      "set source = rectangle\n"
            "set lower corner = " +
      std::string(dim == 2 ? "0, 0" : "0, 0, 0") +
      "\nset upper corner = " + (dim == 2 ? "1, 0.2" : "1, 0.2, 0.5") +
      "\nset center = " + (dim == 2 ? "0.5, 0.1" : "0.5, 0.1, 0.25") +
      "\nset rotation angle = " + std::to_string(angle) +
      "\nset translation = " + (dim == 2 ? "2, 1" : "2, 1, -1") +
      "\nset target edge length = 0.1");
    const bfemp::FemMesh<dim> moved(q, where);
    Point<dim>                centroid;
    for (unsigned int e = 0; e < moved.n_elements(); ++e)
      for (const unsigned int node : moved.elements()[e])
        centroid +=
          moved.rest_position(node) * moved.element_volumes()[e] / (dim + 1.);
    centroid /= moved.total_volume();
    Point<dim>   expected_centroid = q.center + q.translation;
    Point<dim>   corner            = q.center + q.translation;
    const double a                 = std::stod(std::to_string(angle));
    corner[0] += std::cos(a) * (-0.5) - std::sin(a) * (-0.1);
    corner[1] += std::sin(a) * (-0.5) + std::cos(a) * (-0.1);
    if (dim == 3)
      corner[dim - 1] -= 0.25;
    double corner_distance = 1.;
    for (const auto &x : moved.rest_positions())
      corner_distance = std::min(corner_distance, x.distance(corner));
    check(std::abs(moved.total_volume() - exact) <= 1e-13 &&
            centroid.distance(expected_centroid) < 1e-12 &&
            corner_distance < 1e-12,
          name + " rotated and translated: volume, centroid, corner");
    check_mesh(moved, name + " rotated", 1, dim == 2 ? 1 : 2);
  }

  template <int dim>
  void
  check_curved(const std::string &source,
               const double       h,
               const int          euler,
               const int          boundary,
               const std::string &expected_ids,
               double            &relative_error)
  {
    const double R = 0.5, r = 0.3;
    const auto   p =
      parameters<dim>("set source = " + source +
                      "\nset center = " + (dim == 2 ? "1, 2" : "1, 2, 3") +
                      "\nset outer radius = 0.5\nset inner radius = 0.3\n"
                      "set target edge length = " +
                      std::to_string(h));
    const bfemp::FemMesh<dim> mesh(p, where);
    const std::string name = std::to_string(dim) + "D " + p.source_name() +
                             " h = " + std::to_string(h);
    relative_error =
      std::abs(mesh.total_volume() - p.exact_measure()) / p.exact_measure();
    check(relative_error < std::pow(h / R, 2),
          name + ": relative volume error below (h/R)^2");
    check(mesh.min_edge_length() > 0.1 * h &&
            mesh.min_edge_length() <= 1.01 * h,
          name + ": min edge length in (0.1 h, h]");
    check(ids_string(mesh) == expected_ids,
          name + ": boundary ids " + expected_ids);
    const Point<dim> c = p.center;
    check(nodes_on(mesh,
                   0,
                   [&](const Point<dim> &x) {
                     return std::abs(x.distance(c) - R) < 1e-9;
                   }) &&
            (expected_ids.find('1') == std::string::npos ||
             nodes_on(mesh,
                      1,
                      [&](const Point<dim> &x) {
                        return std::abs(x.distance(c) - r) < 1e-9;
                      })) &&
            (expected_ids.find('2') == std::string::npos ||
             nodes_on(mesh,
                      2,
                      [&](const Point<dim> &x) {
                        return std::abs(x[1] - c[1]) < 1e-9;
                      })),
          name + ": id 0 on the outer, 1 on the inner surface, 2 on the cut");
    check_mesh(mesh, name, euler, boundary);
  }

  template <int dim>
  void
  check_generated()
  {
    // Coarse 3D meshes keep the test fast.
    const double h_coarse = dim == 2 ? 0.1 : 0.2;
    const double h_fine   = dim == 2 ? 0.05 : 0.12;
    double       coarse, fine, ignored;
    check_curved<dim>("disk", h_coarse, 1, dim == 2 ? 1 : 2, "0", coarse);
    check_curved<dim>("disk", h_fine, 1, dim == 2 ? 1 : 2, "0", fine);
    check(fine < coarse,
          std::to_string(dim) + "D disk: volume error decreases with h");
    // The shell is homotopic to a sphere (chi 2), its boundary is two
    // spheres (chi 4); the half shell is a thickened disk.
    check_curved<dim>("ring",
                      h_coarse,
                      dim == 2 ? 0 : 2,
                      dim == 2 ? 2 : 4,
                      "0 1",
                      ignored);
    check_curved<dim>("semi-ring",
                      h_coarse,
                      1,
                      dim == 2 ? 1 : 2,
                      "0 1 2",
                      ignored);
  }

  void
  check_msh_file()
  {
    const std::string directory =
      std::filesystem::path(__FILE__).parent_path().string();
    const auto p =
      parameters<2>("set source = file\nset file = square.msh", directory);
    const bfemp::FemMesh<2> mesh(p, where);
    deallog << "square.msh: " << mesh.n_nodes() << " nodes, "
            << mesh.n_elements() << " elements, ids " << ids_string(mesh)
            << std::endl;
    check(std::abs(mesh.total_volume() - 1.) < 1e-14, "square.msh: area 1");
    check_mesh(mesh, "square.msh", 1, 1);
    const auto bottom = mesh.nodes_with_boundary_id(1);
    const auto top    = mesh.nodes_with_boundary_id(3);
    check(bottom.size() == 2 && top.size() == 2 &&
            mesh.rest_position(bottom[0])[1] == 0. &&
            mesh.rest_position(bottom[1])[1] == 0. &&
            mesh.rest_position(top[0])[1] == 1. &&
            mesh.rest_position(top[1])[1] == 1.,
          "square.msh: physical lines 1 (bottom) and 3 (top) are boundary "
          "ids");
    check(mesh.node_boundary_ids(4).empty() &&
            mesh.boundary_nodes().size() == 4,
          "square.msh: centre node interior");
  }

  void
  check_geo_file()
  {
    // A unit square with a square hole of side 0.5, built-in kernel, with
    // physical groups: outer lines 5, hole 7.
    std::ofstream geo("hole.geo");
    geo << "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};\n"
           "Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
           "Point(5) = {0.25, 0.25, 0}; Point(6) = {0.75, 0.25, 0};\n"
           "Point(7) = {0.75, 0.75, 0}; Point(8) = {0.25, 0.75, 0};\n"
           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};\n"
           "Line(4) = {4, 1}; Line(5) = {5, 6}; Line(6) = {6, 7};\n"
           "Line(7) = {7, 8}; Line(8) = {8, 5};\n"
           "Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8};\n"
           "Plane Surface(1) = {1, 2};\n"
           "Physical Curve(5) = {1, 2, 3, 4};\n"
           "Physical Curve(7) = {5, 6, 7, 8};\n"
           "Physical Surface(1) = {1};\n";
    geo.close();
    const auto p = parameters<2>("set source = file\nset file = hole.geo\n"
                                 "set target edge length = 0.2\n"
                                 "set translation = 1, 0");
    const bfemp::FemMesh<2> mesh(p, where);
    check(std::abs(mesh.total_volume() - 0.75) < 1e-13, "hole.geo: area 0.75");
    check(ids_string(mesh) == "5 7", "hole.geo: physical curves 5, 7 are ids");
    check(nodes_on(mesh,
                   7,
                   [](const Point<2> &x) {
                     return std::abs(std::max(std::abs(x[0] - 1.5),
                                              std::abs(x[1] - 0.5)) -
                                     0.25) < 1e-12;
                   }),
          "hole.geo: id 7 on the translated hole");
    check_mesh(mesh, "hole.geo", 0, 2);
  }

  template <int dim>
  void
  check_data_out()
  {
    const auto p = parameters<dim>("set target edge length = 0.5");
    const bfemp::FemMesh<dim> mesh(p, where);
    Vector<double>            displacement(mesh.dof_handler().n_dofs());
    for (unsigned int n = 0; n < mesh.n_nodes(); ++n)
      displacement[dim * n] = mesh.rest_position(n)[1];
    DataOut<dim> data_out;
    data_out.attach_dof_handler(mesh.dof_handler());
    data_out.add_data_vector(
      displacement,
      std::vector<std::string>(dim, "displacement"),
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim,
        DataComponentInterpretation::component_is_part_of_vector));
    data_out.build_patches(mesh.mapping());
    std::ostringstream vtu;
    data_out.write_vtu(vtu);
    check(vtu.str().find("displacement") != std::string::npos,
          std::to_string(dim) + "D: DataOut writes the displacement");
  }

  /** The InputError message of building a mesh from @p entries. */
  template <int dim>
  std::string
  error_of(const std::string &entries, const std::string &prm_directory = ".")
  {
    try
      {
        const bfemp::FemMesh<dim> mesh(parameters<dim>(entries, prm_directory),
                                       where);
      }
    catch (const bfemp::InputError &error)
      {
        return error.what();
      }
    return "no error";
  }

  void
  check_bad_input()
  {
    deallog << error_of<2>("set source = file\nset file = missing.msh",
                           "no/such/directory")
            << std::endl;
    deallog << error_of<2>("set source = file\nset file = mesh.stl")
            << std::endl;

    std::ofstream quads("quads.msh");
    quads << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
             "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
             "$Elements\n1\n1 3 2 1 1 1 2 3 4\n$EndElements\n";
    quads.close();
    deallog << error_of<2>("set source = file\nset file = quads.msh")
            << std::endl;

    std::ofstream broken("broken.geo");
    broken << "Point(1) = {0, 0, 0;\n";
    broken.close();
    const std::string message =
      error_of<2>("set source = file\nset file = broken.geo");
    deallog << message.substr(0, message.find(" (exit status")) << std::endl;

    deallog << error_of<2>("set source = ring\nset inner radius = 0.3\n"
                           "set outer radius = 0.2")
            << std::endl;
    deallog << error_of<3>("set target edge length = 1e-3") << std::endl;
    deallog << error_of<3>("set target edge length = 0") << std::endl;
    deallog << error_of<2>("set upper corner = 1, -1") << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bfemp_tests::initlog();

  check_rectangle<2>();
  check_rectangle<3>();
  check_generated<2>();
  check_generated<3>();
  check_msh_file();
  check_geo_file();
  check_data_out<2>();
  check_data_out<3>();
  check_bad_input();
}
