#include <deal.II/base/config.h>

#include <bfemp/base/input_error.h>
#include <bfemp/base/rotation.h>
#include <bfemp/fem/fem_mesh.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <sys/wait.h>

namespace bfemp
{
  namespace
  {
    /**
     * The gmsh binary: the one deal.II was configured with if it is still
     * there, otherwise whatever "gmsh" the shell finds.
     */
    std::string
    gmsh_executable()
    {
#ifdef DEAL_II_GMSH_EXECUTABLE_PATH
      if (std::filesystem::exists(DEAL_II_GMSH_EXECUTABLE_PATH))
        return DEAL_II_GMSH_EXECUTABLE_PATH;
#endif
      return "gmsh";
    }



    /** @p text in single quotes for /bin/sh, so any path survives. */
    std::string
    shell_quoted(const std::string &text)
    {
      std::string result = "'";
      for (const char c : text)
        result += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      return result + "'";
    }



    /**
     * A fresh directory under the system's temporary directory, removed
     * with everything in it when the object goes out of scope (also when
     * meshing throws), so no gmsh files are left behind.
     */
    class TemporaryDirectory
    {
    public:
      TemporaryDirectory()
      {
        std::string pattern =
          (std::filesystem::temp_directory_path() / "bfemp-gmsh-XXXXXX")
            .string();
        if (mkdtemp(pattern.data()) == nullptr)
          throw SimulationError("cannot create a temporary directory '" +
                                pattern + "' for gmsh");
        path = pattern;
      }

      ~TemporaryDirectory()
      {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
      }

      std::filesystem::path path;
    };



    /**
     * The informative part of a deal.II exception's long text (what follows
     * "Additional information:"), on one line.
     */
    std::string
    brief_message(const std::exception &error)
    {
      std::string       text = error.what();
      const std::string key  = "Additional information:";
      const auto        at   = text.find(key);
      if (at != std::string::npos)
        text = text.substr(at + key.size());
      const auto stack = text.find("Stacktrace:");
      if (stack != std::string::npos)
        text = text.substr(0, stack);
      std::string result;
      for (const char c : text)
        if (!std::isspace(static_cast<unsigned char>(c)))
          result += c;
        else if (!result.empty() && result.back() != ' ')
          result += ' ';
      while (!result.empty() && (result.back() == ' ' || result.back() == '-'))
        result.pop_back();
      return result;
    }



    /**
     * Reads an ASCII gmsh mesh (format 2 or 4) with GridIn::read_msh and
     * checks that it holds only triangles (2D) or tetrahedra (3D). @p name
     * is the file as the user knows it, for messages.
     */
    template <int dim>
    void
    read_msh_file(const std::string  &path,
                  const std::string  &name,
                  const std::string  &where,
                  Triangulation<dim> &tria)
    {
      std::ifstream in(path);
      if (!in)
        throw InputError(where + ": cannot open the mesh file '" + name + "'");
      try
        {
          GridIn<dim> grid_in;
          grid_in.attach_triangulation(tria);
          grid_in.read_msh(in);
        }
      catch (const std::exception &error)
        {
          throw InputError(where + ": cannot read the gmsh mesh file '" + name +
                           "' as a " + std::to_string(dim) +
                           "D mesh: " + brief_message(error));
        }

      const std::string wanted = dim == 2 ? "triangles" : "tetrahedra";
      if (tria.n_active_cells() == 0)
        throw InputError(where + ": the mesh file '" + name + "' has no " +
                         std::to_string(dim) +
                         "D cells (if its .geo defines "
                         "physical groups, gmsh saves only elements in them: "
                         "add a Physical " +
                         (dim == 2 ? "Surface" : "Volume") + ")");
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->reference_cell() != ReferenceCells::get_simplex<dim>())
          throw InputError(
            where + ": the mesh file '" + name + "' contains a cell of type " +
            cell->reference_cell().to_string() + "; FEM bodies need " + wanted +
            " only (linear simplices)");
    }



    /**
     * Meshes the gmsh geometry @p geo_path with the gmsh binary
     * ("gmsh -dim -nt 1 -format msh2 -clmax h", single-threaded so the mesh
     * is the same in every run) into a temporary file and reads it. @p name
     * is the geometry as the user knows it, for messages.
     */
    template <int dim>
    void
    mesh_with_gmsh(const std::string  &geo_path,
                   const std::string  &name,
                   const double        edge_length,
                   const std::string  &where,
                   Triangulation<dim> &tria)
    {
      const TemporaryDirectory    directory;
      const std::filesystem::path msh = directory.path / "mesh.msh";
      const std::filesystem::path log = directory.path / "gmsh.log";

      std::ostringstream command;
      command << std::setprecision(17) << shell_quoted(gmsh_executable())
              << " -" << dim << " -nt 1 -format msh2 -clmax " << edge_length
              << " -o " << shell_quoted(msh.string()) << ' '
              << shell_quoted(geo_path) << " > " << shell_quoted(log.string())
              << " 2>&1 < /dev/null";
      const int status = std::system(command.str().c_str());

      // gmsh's own error lines, or the end of its log, for the message.
      std::string   errors, tail;
      std::ifstream log_in(log);
      for (std::string line; std::getline(log_in, line);)
        {
          if (line.rfind("Error", 0) == 0)
            errors += "\n  " + line;
          tail = line;
        }

      if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) == 127)
        throw InputError(where + ": meshing " + name + " needs the gmsh " +
                         "binary, but '" + gmsh_executable() +
                         "' could not be run (install gmsh, e.g. apt-get "
                         "install gmsh, and put it on the PATH)");
      if (WEXITSTATUS(status) != 0 || !errors.empty() ||
          !std::filesystem::is_regular_file(msh))
        throw InputError(
          where + ": gmsh failed to mesh " + name + " (exit status " +
          std::to_string(WEXITSTATUS(status)) + ")" +
          (errors.empty() ? (tail.empty() ? "" : ":\n  " + tail) : errors));

      read_msh_file<dim>(msh.string(),
                         "mesh of " + name + " made by gmsh",
                         where,
                         tria);
    }



    /**
     * A gmsh script (OpenCASCADE kernel) of a disk, ring or semi-ring, or
     * of a ball, spherical shell or half spherical shell in 3D. Only the
     * body gets a physical group (tag 0), so gmsh writes its triangles or
     * tetrahedra and no boundary elements; boundary ids are set afterwards
     * from the geometry.
     */
    template <int dim>
    std::string
    gmsh_geometry(const FemMeshParameters<dim> &parameters)
    {
      using Source       = typename FemMeshParameters<dim>::Source;
      const Point<dim> c = parameters.center;
      const double     R = parameters.outer_radius;
      const double     r = parameters.inner_radius;
      const double     z = dim == 3 ? c[dim - 1] : 0.;
      // The cutting box reaches this far past the outer radius, so its
      // faces never touch the curved surfaces.
      const double pad = 0.5 * R;

      const std::string entity = dim == 2 ? "Surface" : "Volume";
      const std::string ball   = dim == 2 ? "Disk" : "Sphere";

      std::ostringstream geo;
      geo << std::setprecision(17) << "SetFactory(\"OpenCASCADE\");\n"
          << ball << "(1) = {" << c[0] << ", " << c[1] << ", " << z << ", " << R
          << "};\n"
          << "body() = {1};\n";
      if (parameters.source != Source::disk)
        geo << ball << "(2) = {" << c[0] << ", " << c[1] << ", " << z << ", "
            << r << "};\n"
            << "body() = BooleanDifference{ " << entity << "{1}; Delete; }{ "
            << entity << "{2}; Delete; };\n";
      if (parameters.source == Source::semi_ring)
        {
          if (dim == 2)
            geo << "Rectangle(3) = {" << c[0] - R - pad << ", " << c[1]
                << ", 0, " << 2. * (R + pad) << ", " << R + pad << "};\n";
          else
            geo << "Box(3) = {" << c[0] - R - pad << ", " << c[1] << ", "
                << z - R - pad << ", " << 2. * (R + pad) << ", " << R + pad
                << ", " << 2. * (R + pad) << "};\n";
          geo << "body() = BooleanIntersection{ " << entity
              << "{body()}; Delete; }{ " << entity << "{3}; Delete; };\n";
        }
      geo << "Physical " << entity << "(0) = {body()};\n";
      return geo.str();
    }



    /**
     * Boundary ids of a gmsh-generated disk, ring or semi-ring: 2 on the
     * flat cut y = center_y, 0 on the outer and 1 on the inner circle or
     * sphere. gmsh places boundary nodes on the exact geometry (to round-off),
     * so a face belongs to a surface if all its vertices do.
     */
    template <int dim>
    void
    set_generated_boundary_ids(const FemMeshParameters<dim> &parameters,
                               Triangulation<dim>           &tria)
    {
      const double tolerance = 1e-8 * parameters.outer_radius;
      const auto   on        = [&](const auto &face, const auto &predicate) {
        for (unsigned int v = 0; v < face->n_vertices(); ++v)
          if (!predicate(face->vertex(v)))
            return false;
        return true;
      };
      const Point<dim> &c = parameters.center;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto face = cell->face(f);
              if (parameters.source ==
                    FemMeshParameters<dim>::Source::semi_ring &&
                  on(face, [&](const Point<dim> &x) {
                    return std::abs(x[1] - c[1]) <= tolerance;
                  }))
                face->set_boundary_id(2);
              else if (on(face, [&](const Point<dim> &x) {
                         return std::abs(x.distance(c) -
                                         parameters.outer_radius) <= tolerance;
                       }))
                face->set_boundary_id(0);
              else if (on(face, [&](const Point<dim> &x) {
                         return std::abs(x.distance(c) -
                                         parameters.inner_radius) <= tolerance;
                       }))
                face->set_boundary_id(1);
              else
                throw SimulationError(
                  "FemMesh: a boundary face of the gmsh mesh of a " +
                  parameters.source_name() + " at " +
                  to_input_string(face->center()) +
                  " lies on none of its surfaces");
            }
    }



    /**
     * Boundary ids of a generated rectangle/box as deal.II's colorize would
     * give them (deal.II 9.4 does not implement colorize for
     * subdivided_hyper_rectangle_with_simplices): 2d on the face
     * x_d = lower corner, 2d+1 on x_d = upper corner.
     */
    template <int dim>
    void
    set_rectangle_boundary_ids(const FemMeshParameters<dim> &parameters,
                               Triangulation<dim>           &tria)
    {
      const Point<dim> &lower = parameters.lower_corner;
      const Point<dim> &upper = parameters.upper_corner;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto face = cell->face(f);
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double tolerance = 1e-10 * (upper[d] - lower[d]);
                  bool         on_lower = true, on_upper = true;
                  for (unsigned int v = 0; v < face->n_vertices(); ++v)
                    {
                      on_lower = on_lower && std::abs(face->vertex(v)[d] -
                                                      lower[d]) <= tolerance;
                      on_upper = on_upper && std::abs(face->vertex(v)[d] -
                                                      upper[d]) <= tolerance;
                    }
                  if (on_lower || on_upper)
                    {
                      face->set_boundary_id(2 * d + (on_upper ? 1 : 0));
                      break;
                    }
                }
            }
    }



    /** det[x_1 - x_0, ..., x_dim - x_0] of the simplex with nodes @p x. */
    template <int dim>
    double
    orientation(const std::array<Point<dim>, dim + 1> &x)
    {
      Tensor<2, dim> B;
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int r = 0; r < dim; ++r)
          B[r][c] = x[c + 1][r] - x[0][r];
      return determinant(B);
    }
  } // namespace



  template <int dim>
  FemMesh<dim>::FemMesh(const FemMeshParameters<dim> &parameters,
                        const std::string            &where)
    : fe(FE_SimplexP<dim>(1), dim)
    , linear_mapping(FE_SimplexP<dim>(1))
  {
    generate(parameters, where);

    // Rotation about 'rotation axis' through the centre (2D: the plane's own
    // rotation), then the translation. About the z axis the plane formula
    // is kept, so meshes of earlier scenes stay the same to the last bit.
    const double     cos_a = std::cos(parameters.rotation_angle);
    const double     sin_a = std::sin(parameters.rotation_angle);
    const Point<dim> c     = parameters.center;
    const auto       shift = parameters.translation;
    Tensor<1, dim>   z_axis;
    z_axis[dim - 1]    = 1.;
    const bool about_z = dim == 2 || parameters.rotation_axis == z_axis;
    const Tensor<2, dim> R =
      rotation_matrix<dim>(parameters.rotation_angle, parameters.rotation_axis);
    if (parameters.rotation_angle != 0. || shift.norm() != 0.)
      GridTools::transform(
        [&](const Point<dim> &x) {
          if (!about_z)
            return Point<dim>(c + R * (x - c) + shift);
          Point<dim> y = x;
          y[0]         = c[0] + cos_a * (x[0] - c[0]) - sin_a * (x[1] - c[1]);
          y[1]         = c[1] + sin_a * (x[0] - c[0]) + cos_a * (x[1] - c[1]);
          return y + shift;
        },
        tria);

    set_up_nodes_and_elements(where + ": the " + parameters.source_name());
    set_up_boundary();
    set_up_dofs();
  }



  template <int dim>
  void
  FemMesh<dim>::generate(const FemMeshParameters<dim> &parameters,
                         const std::string            &where)
  {
    using Source = typename FemMeshParameters<dim>::Source;
    switch (parameters.source)
      {
        case Source::rectangle:
          GridGenerator::subdivided_hyper_rectangle_with_simplices(
            tria,
            parameters.rectangle_subdivisions(),
            parameters.lower_corner,
            parameters.upper_corner);
          set_rectangle_boundary_ids(parameters, tria);
          break;
        case Source::disk:
        case Source::ring:
        case Source::semi_ring:
          {
            const TemporaryDirectory    directory;
            const std::filesystem::path geo = directory.path / "shape.geo";
            {
              std::ofstream out(geo);
              out << gmsh_geometry(parameters);
              if (!out)
                throw SimulationError("cannot write the gmsh geometry '" +
                                      geo.string() + "'");
            }
            mesh_with_gmsh<dim>(geo.string(),
                                "the " + parameters.source_name(),
                                parameters.target_edge_length,
                                where,
                                tria);
            set_generated_boundary_ids(parameters, tria);
            break;
          }
        case Source::file:
          {
            const std::string extension =
              std::filesystem::path(parameters.file).extension().string();
            if (extension == ".geo")
              mesh_with_gmsh<dim>(parameters.file,
                                  "'" + parameters.file + "'",
                                  parameters.target_edge_length,
                                  where,
                                  tria);
            else
              read_msh_file<dim>(parameters.file, parameters.file, where, tria);
            break;
          }
      }
  }



  template <int dim>
  void
  FemMesh<dim>::set_up_nodes_and_elements(const std::string &what)
  {
    vertex_to_node.assign(tria.n_vertices(), numbers::invalid_unsigned_int);
    const std::vector<bool> &used = tria.get_used_vertices();
    for (unsigned int v = 0; v < tria.n_vertices(); ++v)
      if (used[v])
        {
          vertex_to_node[v] = positions.size();
          positions.push_back(tria.get_vertices()[v]);
        }

    element_nodes.resize(tria.n_active_cells());
    volumes.resize(tria.n_active_cells());
    shortest_edge          = std::numeric_limits<double>::max();
    const double factorial = dim == 2 ? 2. : 6.;
    for (const auto &cell : tria.active_cell_iterators())
      {
        Element &nodes = element_nodes[cell->active_cell_index()];
        std::array<Point<dim>, dim + 1> x;
        double                          longest = 0.;
        for (unsigned int a = 0; a < dim + 1; ++a)
          {
            nodes[a] = vertex_to_node[cell->vertex_index(a)];
            x[a]     = positions[nodes[a]];
            for (unsigned int b = 0; b < a; ++b)
              {
                const double length = x[a].distance(x[b]);
                longest             = std::max(longest, length);
                shortest_edge       = std::min(shortest_edge, length);
              }
          }
        double det = orientation<dim>(x);
        if (det < 0.)
          {
            // An odd permutation flips the sign of the determinant.
            std::swap(nodes[1], nodes[2]);
            det = -det;
          }
        if (!(det > 1e-12 * std::pow(longest, dim)))
          throw InputError(what + " has a degenerate element (zero " +
                           (dim == 2 ? "area" : "volume") + ") at " +
                           to_input_string(cell->center()));
        volumes[cell->active_cell_index()] = det / factorial;
      }
    check_not_folded(what);
  }



  template <int dim>
  void
  FemMesh<dim>::check_not_folded(const std::string &what) const
  {
    // Each element was reoriented to a positive volume above, so a mesh
    // written with either node order is accepted. An element turned inside
    // out with respect to its neighbours (a folded mesh: the two overlap)
    // shows at their shared face: both remaining nodes lie on the same side
    // of it.
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          if (cell->at_boundary(f))
            continue;
          const auto neighbor = cell->neighbor(f);
          if (neighbor->active_cell_index() < cell->active_cell_index())
            continue;
          const auto                      face = cell->face(f);
          std::array<Point<dim>, dim + 1> x;
          for (unsigned int i = 0; i < dim; ++i)
            x[i] = positions[vertex_to_node[face->vertex_index(i)]];
          const auto side = [&](const auto &element) {
            for (const unsigned int v : element->vertex_indices())
              {
                bool on_face = false;
                for (unsigned int i = 0; i < dim; ++i)
                  on_face = on_face ||
                            element->vertex_index(v) == face->vertex_index(i);
                if (!on_face)
                  x[dim] = positions[vertex_to_node[element->vertex_index(v)]];
              }
            return orientation<dim>(x);
          };
          if (side(cell) * side(neighbor) > 0.)
            throw InputError(what + " folds over itself: the elements at " +
                             to_input_string(cell->center()) + " and " +
                             to_input_string(neighbor->center()) +
                             " lie on the same side of their shared face "
                             "(inverted elements); FEM meshes must not "
                             "overlap themselves");
        }
  }



  template <int dim>
  void
  FemMesh<dim>::set_up_boundary()
  {
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto     face    = cell->face(f);
            const Element &element = element_nodes[cell->active_cell_index()];
            Facet          facet;
            for (unsigned int i = 0; i < dim; ++i)
              facet[i] = vertex_to_node[face->vertex_index(i)];
            unsigned int opposite = element[0];
            for (const unsigned int node : element)
              if (std::find(facet.begin(), facet.end(), node) == facet.end())
                opposite = node;

            // The normal whose orientation the doc promises; it must point
            // away from the element's remaining node.
            const Point<dim> &a = positions[facet[0]];
            Tensor<1, dim>    normal;
            if constexpr (dim == 2)
              {
                const Tensor<1, dim> edge = positions[facet[1]] - a;
                normal[0]                 = edge[1];
                normal[1]                 = -edge[0];
              }
            else
              normal = cross_product_3d(positions[facet[1]] - a,
                                        positions[facet[2]] - a);
            if (normal * (positions[opposite] - a) > 0.)
              std::swap(facet[0], facet[1]);

            facets.push_back(facet);
            facet_ids.push_back(face->boundary_id());
          }

    ids_of_node.assign(positions.size(), {});
    for (unsigned int k = 0; k < facets.size(); ++k)
      for (const unsigned int node : facets[k])
        ids_of_node[node].push_back(facet_ids[k]);
    for (unsigned int n = 0; n < positions.size(); ++n)
      {
        auto &ids = ids_of_node[n];
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        if (!ids.empty())
          boundary_node_list.push_back(n);
      }
  }



  template <int dim>
  void
  FemMesh<dim>::set_up_dofs()
  {
    dofs.reinit(tria);
    dofs.distribute_dofs(fe);
    AssertThrow(dofs.n_dofs() == dim * positions.size(),
                ExcMessage("FemMesh: FE_SimplexP(1)^dim should have dim DoFs "
                           "per node"));

    // distribute_dofs() numbers vertices in the order the cells reach them,
    // each vertex's components together. Renumber to DoF dim*node + c.
    // The local DoF i of the system is component c of the base element's
    // DoF "vertex", and FE_SimplexP(1) numbers its DoFs like the vertices.
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> new_numbers(
      dofs.n_dofs(),
      numbers::invalid_dof_index);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const auto [component, vertex] = fe.system_to_component_index(i);
            new_numbers[local[i]] =
              dim * vertex_to_node[cell->vertex_index(vertex)] + component;
          }
      }
    dofs.renumber_dofs(new_numbers);

    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < local.size(); ++i)
          {
            const auto [component, vertex] = fe.system_to_component_index(i);
            AssertThrow(local[i] ==
                          dim * vertex_to_node[cell->vertex_index(vertex)] +
                            component,
                        ExcMessage("FemMesh: DoF numbering is not "
                                   "dim * node + component"));
          }
      }
  }



  template <int dim>
  unsigned int
  FemMesh<dim>::n_nodes() const
  {
    return positions.size();
  }



  template <int dim>
  unsigned int
  FemMesh<dim>::n_elements() const
  {
    return element_nodes.size();
  }



  template <int dim>
  const Point<dim> &
  FemMesh<dim>::rest_position(const unsigned int node) const
  {
    AssertIndexRange(node, positions.size());
    return positions[node];
  }



  template <int dim>
  const std::vector<Point<dim>> &
  FemMesh<dim>::rest_positions() const
  {
    return positions;
  }



  template <int dim>
  const std::vector<typename FemMesh<dim>::Element> &
  FemMesh<dim>::elements() const
  {
    return element_nodes;
  }



  template <int dim>
  const std::vector<double> &
  FemMesh<dim>::element_volumes() const
  {
    return volumes;
  }



  template <int dim>
  double
  FemMesh<dim>::total_volume() const
  {
    double sum = 0.;
    for (const double volume : volumes)
      sum += volume;
    return sum;
  }



  template <int dim>
  double
  FemMesh<dim>::min_edge_length() const
  {
    return shortest_edge;
  }



  template <int dim>
  std::vector<double>
  FemMesh<dim>::lumped_masses(const double density) const
  {
    std::vector<double> masses(positions.size(), 0.);
    for (unsigned int e = 0; e < element_nodes.size(); ++e)
      for (const unsigned int node : element_nodes[e])
        masses[node] += density * volumes[e] / (dim + 1);
    return masses;
  }



  template <int dim>
  const std::vector<typename FemMesh<dim>::Facet> &
  FemMesh<dim>::boundary_facets() const
  {
    return facets;
  }



  template <int dim>
  const std::vector<types::boundary_id> &
  FemMesh<dim>::boundary_facet_ids() const
  {
    return facet_ids;
  }



  template <int dim>
  const std::vector<unsigned int> &
  FemMesh<dim>::boundary_nodes() const
  {
    return boundary_node_list;
  }



  template <int dim>
  const std::vector<types::boundary_id> &
  FemMesh<dim>::node_boundary_ids(const unsigned int node) const
  {
    AssertIndexRange(node, ids_of_node.size());
    return ids_of_node[node];
  }



  template <int dim>
  std::vector<unsigned int>
  FemMesh<dim>::nodes_with_boundary_id(const types::boundary_id id) const
  {
    std::vector<unsigned int> nodes;
    for (const unsigned int n : boundary_node_list)
      if (std::binary_search(ids_of_node[n].begin(), ids_of_node[n].end(), id))
        nodes.push_back(n);
    return nodes;
  }



  template <int dim>
  std::vector<types::boundary_id>
  FemMesh<dim>::boundary_ids() const
  {
    std::vector<types::boundary_id> ids = facet_ids;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  }



  template <int dim>
  const Triangulation<dim> &
  FemMesh<dim>::triangulation() const
  {
    return tria;
  }



  template <int dim>
  const DoFHandler<dim> &
  FemMesh<dim>::dof_handler() const
  {
    return dofs;
  }



  template <int dim>
  const FESystem<dim> &
  FemMesh<dim>::finite_element() const
  {
    return fe;
  }



  template <int dim>
  const Mapping<dim> &
  FemMesh<dim>::mapping() const
  {
    return linear_mapping;
  }



  template class FemMesh<2>;
  template class FemMesh<3>;
} // namespace bfemp
