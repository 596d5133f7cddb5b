#include <bfemp/io/atomic_file.h>
#include <bfemp/io/particle_output.h>
#include <bfemp/io/vtu_flags.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <algorithm>

namespace bfemp
{
  template <int dim>
  ParticleOutput<dim>::ParticleOutput(
    const std::string                                 &folder,
    const std::vector<std::unique_ptr<Material<dim>>> &materials)
    : folder(folder)
    , materials(materials)
    , series(folder + "/particles.pvd")
  {}



  template <int dim>
  void
  ParticleOutput<dim>::write(const ParticleSystem<dim> &particles,
                             const double               time,
                             const unsigned int         snapshot)
  {
    using Layout = ParticleLayout<dim>;
    std::vector<std::string> names;
    auto add_names = [&](const std::string &name, const unsigned int n) {
      for (unsigned int i = 0; i < n; ++i)
        names.push_back(name);
    };
    add_names("velocity", dim);
    add_names("displacement", dim);
    add_names("cauchy_stress", dim * dim);
    for (const char *name :
         {"von_mises", "J", "mass", "volume", "material_id", "body_id"})
      names.push_back(name);

    using Range =
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>;
    const std::vector<Range> ranges = {
      Range(0,
            dim - 1,
            "velocity",
            DataComponentInterpretation::component_is_part_of_vector),
      Range(dim,
            2 * dim - 1,
            "displacement",
            DataComponentInterpretation::component_is_part_of_vector),
      Range(2 * dim,
            2 * dim + dim * dim - 1,
            "cauchy_stress",
            DataComponentInterpretation::component_is_part_of_tensor)};

    // Points in particle-id order: the handler's own order depends on the
    // history of cell changes (and differs after a restart), but a point's
    // index in every snapshot should name the same particle.
    std::vector<Particles::ParticleIterator<dim>> by_id;
    by_id.reserve(particles.n_particles());
    for (auto it = particles.handler().begin(); it != particles.handler().end();
         ++it)
      by_id.push_back(it);
    std::sort(by_id.begin(), by_id.end(), [](const auto &a, const auto &b) {
      return a->get_id() < b->get_id();
    });

    std::vector<DataOutBase::Patch<0, dim>> patches;
    patches.reserve(particles.n_particles());
    for (const auto &it : by_id)
      {
        const auto                &particle = *it;
        const auto                 p        = particle.get_properties();
        DataOutBase::Patch<0, dim> patch;
        patch.vertices[0]          = particle.get_location();
        patch.patch_index          = patches.size();
        patch.points_are_available = false;
        patch.data.reinit(names.size(), 1);

        const Tensor<2, dim> F =
          Layout::get_tensor(p, Layout::deformation_gradient);
        const Tensor<2, dim> sigma =
          materials[static_cast<unsigned int>(p[Layout::material_id])]
            ->cauchy_stress(F);
        unsigned int field = 0;
        for (unsigned int d = 0; d < dim; ++d)
          patch.data(field++, 0) = p[Layout::velocity + d];
        for (unsigned int d = 0; d < dim; ++d)
          patch.data(field++, 0) =
            particle.get_location()[d] - p[Layout::initial_position + d];
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            patch.data(field++, 0) = sigma[i][j];
        patch.data(field++, 0) = von_mises_stress(sigma);
        patch.data(field++, 0) = determinant(F);
        patch.data(field++, 0) = p[Layout::mass];
        patch.data(field++, 0) = p[Layout::rest_volume];
        patch.data(field++, 0) = p[Layout::material_id];
        patch.data(field++, 0) = p[Layout::body_id];
        patches.push_back(std::move(patch));
      }

    const std::string name =
      "particles_" + Utilities::int_to_string(snapshot, 5) + ".vtu";
    const DataOutBase::VtkFlags flags = vtu_flags(time);
    write_file_atomically(folder + "/" + name, [&](std::ostream &out) {
      DataOutBase::write_vtu(patches, names, ranges, flags, out);
    });
    series.add(time, name);
  }



  template class ParticleOutput<2>;
  template <int dim>
  void
  ParticleOutput<dim>::resume(const unsigned int next_snapshot)
  {
    series.resume(next_snapshot);
  }



  template class ParticleOutput<3>;
} // namespace bfemp
