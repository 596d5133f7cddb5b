#include <bfemp/base/input_error.h>
#include <bfemp/io/checkpoint_file.h>
#include <bfemp/particles/particle_layout.h>

#include <deal.II/base/hdf5.h>

#include <filesystem>
#include <hdf5.h>

namespace bfemp
{
  namespace
  {
    const std::string format_name = "bfemp checkpoint 1";

    /** Points as rows of an n x dim array. */
    template <int dim>
    std::vector<double>
    flatten(const std::vector<Point<dim>> &points)
    {
      std::vector<double> values;
      values.reserve(points.size() * dim);
      for (const Point<dim> &x : points)
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(x[d]);
      return values;
    }

    template <int dim>
    std::vector<double>
    flatten(const std::vector<Tensor<1, dim>> &vectors)
    {
      std::vector<double> values;
      values.reserve(vectors.size() * dim);
      for (const Tensor<1, dim> &v : vectors)
        for (unsigned int d = 0; d < dim; ++d)
          values.push_back(v[d]);
      return values;
    }

    /** An n x columns dataset of doubles (nothing for n = 0). */
    void
    write_array(HDF5::Group               &group,
                const std::string         &name,
                const std::vector<double> &values,
                const std::size_t          columns)
    {
      if (values.empty())
        return;
      auto dataset = group.create_dataset<double>(
        name,
        {static_cast<hsize_t>(values.size() / columns), columns});
      dataset.write(values);
    }

    /** HDF5 quietly, so that probing a bad file prints no error stack. */
    class QuietHdf5
    {
    public:
      QuietHdf5()
      {
        H5Eget_auto2(H5E_DEFAULT, &function, &data);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
      }

      ~QuietHdf5()
      {
        H5Eset_auto2(H5E_DEFAULT, function, data);
      }

    private:
      H5E_auto2_t function = nullptr;
      void       *data     = nullptr;
    };

    /** What a checkpoint of a scene must hold. */
    struct RequiredContents
    {
      RequiredContents(const bool with_particles, const unsigned int n_fem)
      {
        for (const char *name : {"format",
                                 "dimension",
                                 "step",
                                 "time",
                                 "snapshot",
                                 "next output",
                                 "wall time",
                                 "friction dissipation"})
          attributes.emplace_back(".", name);
        links.emplace_back("particles");
        attributes.emplace_back("particles", "count");
        attributes.emplace_back("particles", "properties");
        if (with_particles)
          for (const char *name : {"ids", "locations", "properties"})
            links.push_back(std::string("particles/") + name);
        for (unsigned int b = 0; b < n_fem; ++b)
          {
            const std::string group = "fem body " + std::to_string(b);
            links.push_back(group);
            attributes.emplace_back(group, "nodes");
            for (const char *name :
                 {"rest positions", "positions", "velocities"})
              links.push_back(group + "/" + name);
          }
      }

      std::vector<std::string>                         links;
      std::vector<std::pair<std::string, std::string>> attributes;
    };

    /**
     * Empty if @p path is an HDF5 file whose writing completed (the
     * attribute 'complete' is written last) and that holds @p required;
     * otherwise what is wrong. Checked with HDF5's C interface before
     * deal.II's wrappers open the file: those abort the program if an
     * exception passes while a file is open.
     */
    std::string
    problem_with(const std::string &path, const RequiredContents &required)
    {
      const QuietHdf5 quiet;
      if (H5Fis_hdf5(path.c_str()) <= 0)
        return "is not an HDF5 file";
      const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      if (file < 0)
        return "cannot be opened";
      std::string problem;
      if (H5Aexists(file, "complete") <= 0)
        problem = "is not a complete bfemp checkpoint (its writing did not "
                  "finish, or another program wrote it)";
      for (const std::string &link : required.links)
        if (problem.empty() && H5Lexists(file, link.c_str(), H5P_DEFAULT) <= 0)
          problem = "lacks '" + link + "'";
      for (const auto &[object, name] : required.attributes)
        if (problem.empty() && H5Aexists_by_name(file,
                                                 object.c_str(),
                                                 name.c_str(),
                                                 H5P_DEFAULT) <= 0)
          problem = "lacks the attribute '" + name + "' of '" + object + "'";
      H5Fclose(file);
      return problem;
    }

    /** An n x columns dataset as read, with its shape. */
    struct Array
    {
      std::vector<hsize_t> shape;
      std::vector<double>  values;

      Array() = default;

      Array(const HDF5::Group &group, const std::string &name)
      {
        auto dataset = group.open_dataset(name);
        shape        = dataset.get_dimensions();
        values       = dataset.read<std::vector<double>>();
      }

      bool
      has_shape(const std::size_t rows, const std::size_t columns) const
      {
        return shape.size() == 2 && shape[0] == rows && shape[1] == columns &&
               values.size() == rows * columns;
      }
    };

    /** Everything a checkpoint file holds, read in one go. */
    template <int dim>
    struct CheckpointContents
    {
      std::string                            format;
      unsigned int                           dimension = 0;
      typename CheckpointFile<dim>::Progress progress;
      unsigned int                           n_particles  = 0;
      unsigned int                           n_properties = 0;
      std::vector<unsigned int>              ids;
      Array                                  locations, properties;
      std::vector<unsigned int>              fem_nodes;
      std::vector<std::array<Array, 3>>      fem_arrays;

      /** Reads the file that problem_with() found complete. */
      CheckpointContents(const std::string &path,
                         const bool         with_particles,
                         const unsigned int n_fem)
      {
        HDF5::File file(path, HDF5::File::FileAccessMode::open);
        format               = file.get_attribute<std::string>("format");
        dimension            = file.get_attribute<unsigned int>("dimension");
        progress.step        = file.get_attribute<unsigned int>("step");
        progress.time        = file.get_attribute<double>("time");
        progress.snapshot    = file.get_attribute<unsigned int>("snapshot");
        progress.next_output = file.get_attribute<double>("next output");
        progress.wall_time   = file.get_attribute<double>("wall time");
        progress.friction_dissipation =
          file.get_attribute<double>("friction dissipation");
        const auto particles = file.open_group("particles");
        n_particles          = particles.get_attribute<unsigned int>("count");
        n_properties = particles.get_attribute<unsigned int>("properties");
        if (with_particles)
          {
            ids =
              particles.open_dataset("ids").read<std::vector<unsigned int>>();
            locations  = Array(particles, "locations");
            properties = Array(particles, "properties");
          }
        for (unsigned int b = 0; b < n_fem; ++b)
          {
            const auto body = file.open_group("fem body " + std::to_string(b));
            fem_nodes.push_back(body.get_attribute<unsigned int>("nodes"));
            fem_arrays.push_back({{Array(body, "rest positions"),
                                   Array(body, "positions"),
                                   Array(body, "velocities")}});
          }
      }
    };
  } // namespace



  template <int dim>
  CheckpointFile<dim>::CheckpointFile(const std::string &path)
    : file_path(path)
  {}



  template <int dim>
  const std::string &
  CheckpointFile<dim>::path() const
  {
    return file_path;
  }



  template <int dim>
  bool
  CheckpointFile<dim>::exists() const
  {
    return std::filesystem::exists(file_path);
  }



  template <int dim>
  void
  CheckpointFile<dim>::write(
    const Progress                                   &progress,
    const ParticleSystem<dim>                        &particles,
    const std::vector<std::unique_ptr<FemBody<dim>>> &fem_bodies) const
  {
    using Layout                     = ParticleLayout<dim>;
    const std::string temporary      = file_path + ".part";
    const auto        records        = particles.gather_in_loop_order();
    const bool        with_particles = !records.ids.empty();
    {
      HDF5::File file(temporary, HDF5::File::FileAccessMode::create);
      file.set_attribute("format", format_name);
      file.set_attribute("dimension", static_cast<unsigned int>(dim));
      file.set_attribute("step", progress.step);
      file.set_attribute("time", progress.time);
      file.set_attribute("snapshot", progress.snapshot);
      file.set_attribute("next output", progress.next_output);
      file.set_attribute("wall time", progress.wall_time);
      file.set_attribute("friction dissipation", progress.friction_dissipation);

      auto group = file.create_group("particles");
      group.set_attribute("count",
                          static_cast<unsigned int>(records.ids.size()));
      group.set_attribute("properties", Layout::n_properties);
      if (with_particles)
        {
          const std::vector<unsigned int> ids(records.ids.begin(),
                                              records.ids.end());
          auto dataset = group.create_dataset<unsigned int>(
            "ids",
            {static_cast<hsize_t>(ids.size())});
          dataset.write(ids);
          write_array(group, "locations", flatten<dim>(records.locations), dim);
          write_array(group,
                      "properties",
                      records.properties,
                      Layout::n_properties);
        }
      for (unsigned int b = 0; b < fem_bodies.size(); ++b)
        {
          const FemBody<dim> &body = *fem_bodies[b];
          auto body_group = file.create_group("fem body " + std::to_string(b));
          body_group.set_attribute("nodes", body.n_nodes());
          write_array(body_group,
                      "rest positions",
                      flatten<dim>(body.mesh().rest_positions()),
                      dim);
          write_array(body_group,
                      "positions",
                      flatten<dim>(body.positions()),
                      dim);
          write_array(body_group,
                      "velocities",
                      flatten<dim>(body.velocities()),
                      dim);
        }
      file.set_attribute("complete", 1u);
    }
    const std::string problem =
      problem_with(temporary,
                   RequiredContents(with_particles, fem_bodies.size()));
    if (!problem.empty())
      throw SimulationError("the checkpoint " + temporary + " " + problem +
                            " after writing it (disk full?); the previous "
                            "checkpoint is kept");
    std::filesystem::rename(temporary, file_path);
  }



  template <int dim>
  typename CheckpointFile<dim>::Progress
  CheckpointFile<dim>::read(
    ParticleSystem<dim>                        &particles,
    std::vector<std::unique_ptr<FemBody<dim>>> &fem_bodies) const
  {
    using Layout                      = ParticleLayout<dim>;
    const std::string  where          = "checkpoint " + file_path;
    const unsigned int n_fem          = fem_bodies.size();
    const bool         with_particles = particles.n_particles() > 0;
    const std::string  other_scene =
      ": the checkpoint belongs to another scene (bodies, grid and meshes "
      "must not change between a run and its continuation)";
    if (!exists())
      throw InputError(where + " does not exist");
    const std::string problem =
      problem_with(file_path, RequiredContents(with_particles, n_fem));
    if (!problem.empty())
      throw InputError(where + " " + problem);
    const CheckpointContents<dim> saved(file_path, with_particles, n_fem);

    if (saved.format != format_name)
      throw InputError(where + " has the format '" + saved.format +
                       "', this bfemp reads '" + format_name + "'");
    if (saved.dimension != dim)
      throw InputError(where + " holds a " + std::to_string(saved.dimension) +
                       "D run; this scene is " + std::to_string(dim) + "D");
    if (saved.n_particles != particles.n_particles())
      throw InputError(where + " has " + std::to_string(saved.n_particles) +
                       " particles, the scene samples " +
                       std::to_string(particles.n_particles()) + other_scene);
    if (saved.n_properties != Layout::n_properties)
      throw InputError(where + " stores another set of particle properties "
                               "(written by another bfemp version)");
    const unsigned int n = saved.n_particles;
    if (with_particles &&
        (saved.ids.size() != n || !saved.locations.has_shape(n, dim) ||
         !saved.properties.has_shape(n, Layout::n_properties)))
      throw InputError(where + ": the particle arrays do not have " +
                       std::to_string(n) + " rows");
    for (unsigned int b = 0; b < n_fem; ++b)
      {
        const FemBody<dim> &body  = *fem_bodies[b];
        const std::string   name  = "'fem body " + std::to_string(b) + "'";
        const unsigned int  nodes = body.n_nodes();
        if (saved.fem_nodes[b] != nodes)
          throw InputError(
            where + ": " + name + " has " + std::to_string(saved.fem_nodes[b]) +
            " nodes, the scene's mesh " + std::to_string(nodes) + other_scene);
        for (const Array &array : saved.fem_arrays[b])
          if (!array.has_shape(nodes, dim))
            throw InputError(where + ": the arrays of " + name +
                             " do not have " + std::to_string(nodes) + " rows");
        const std::vector<double> &rest = saved.fem_arrays[b][0].values;
        for (unsigned int a = 0; a < nodes; ++a)
          for (unsigned int d = 0; d < dim; ++d)
            if (std::abs(rest[a * dim + d] - body.mesh().rest_position(a)[d]) >
                1e-12 * (1. + std::abs(rest[a * dim + d])))
              throw InputError(where + ": node " + std::to_string(a) + " of " +
                               name + " has another rest position" +
                               other_scene);
      }

    if (with_particles)
      {
        typename ParticleSystem<dim>::Records records;
        records.ids.assign(saved.ids.begin(), saved.ids.end());
        records.locations.resize(n);
        for (unsigned int k = 0; k < n; ++k)
          for (unsigned int d = 0; d < dim; ++d)
            records.locations[k][d] = saved.locations.values[k * dim + d];
        records.properties = saved.properties.values;
        particles.replace_all(records);
      }
    for (unsigned int b = 0; b < n_fem; ++b)
      for (unsigned int a = 0; a < fem_bodies[b]->n_nodes(); ++a)
        for (unsigned int d = 0; d < dim; ++d)
          {
            fem_bodies[b]->positions()[a][d] =
              saved.fem_arrays[b][1].values[a * dim + d];
            fem_bodies[b]->velocities()[a][d] =
              saved.fem_arrays[b][2].values[a * dim + d];
          }
    return saved.progress;
  }



  template class CheckpointFile<2>;
  template class CheckpointFile<3>;
} // namespace bfemp
