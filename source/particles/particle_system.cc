#include <bfemp/base/input_error.h>
#include <bfemp/particles/particle_system.h>

#include <sstream>

namespace bfemp
{
  template <int dim>
  ParticleSystem<dim>::ParticleSystem(const BackgroundGrid<dim> &grid)
    : grid(grid)
  {
    particle_handler.initialize(grid.triangulation(),
                                grid.mapping(),
                                Layout::n_properties);
  }



  namespace
  {
    template <int dim>
    Point<dim>
    reference_location(const Lattice<dim>         &lattice,
                       const std::array<int, dim> &cell,
                       const Point<dim>           &x)
    {
      Point<dim> reference;
      for (unsigned int d = 0; d < dim; ++d)
        reference[d] =
          (x[d] - lattice.node_coordinate(d, cell[d])) * lattice.inverse_dx;
      return reference;
    }
  } // namespace



  template <int dim>
  void
  ParticleSystem<dim>::insert(const Point<dim>              &x,
                              const ArrayView<const double> &properties)
  {
    const auto cell = grid.lattice().cell_of(x);
    particle_handler.insert_particle(x,
                                     reference_location<dim>(grid.lattice(),
                                                             cell,
                                                             x),
                                     next_id++,
                                     grid.cell(cell),
                                     properties);
  }



  template <int dim>
  void
  ParticleSystem<dim>::finish_insertion()
  {
    particle_handler.update_cached_numbers();
    rebuild_stripes();
    store_in_loop_order();
  }



  template <int dim>
  void
  ParticleSystem<dim>::store_in_loop_order()
  {
    // Particle data lives in deal.II's PropertyPool in the order particles
    // were inserted; after many cell changes a loop over cells jumps around
    // memory and is bound by cache misses. Re-inserting every particle in
    // loop order makes the loops stream through memory again.
    const unsigned int                 n_properties = Layout::n_properties;
    std::vector<double>                buffer;
    std::vector<types::particle_index> ids;
    std::vector<Point<dim>>            locations;
    buffer.reserve(particle_handler.n_locally_owned_particles() * n_properties);
    for (const auto &stripe : stripes)
      for (const auto &cell : stripe)
        for (const auto &particle : particle_handler.particles_in_cell(cell))
          {
            const auto properties = particle.get_properties();
            buffer.insert(buffer.end(), properties.begin(), properties.end());
            ids.push_back(particle.get_id());
            locations.push_back(particle.get_location());
          }
    particle_handler.clear_particles();
    const Lattice<dim> &lattice = grid.lattice();
    for (std::size_t k = 0; k < ids.size(); ++k)
      {
        const auto cell = lattice.cell_of(locations[k]);
        particle_handler.insert_particle(
          locations[k],
          reference_location<dim>(lattice, cell, locations[k]),
          ids[k],
          grid.cell(cell),
          ArrayView<const double>(buffer.data() + k * n_properties,
                                  n_properties));
      }
    particle_handler.update_cached_numbers();
    moved_since_ordering = 0;
  }



  template <int dim>
  types::particle_index
  ParticleSystem<dim>::n_particles() const
  {
    return particle_handler.n_locally_owned_particles();
  }



  template <int dim>
  Particles::ParticleHandler<dim> &
  ParticleSystem<dim>::handler()
  {
    return particle_handler;
  }



  template <int dim>
  const Particles::ParticleHandler<dim> &
  ParticleSystem<dim>::handler() const
  {
    return particle_handler;
  }



  template <int dim>
  void
  ParticleSystem<dim>::rebuild_stripes()
  {
    const Lattice<dim> &lattice = grid.lattice();
    stripes.assign((lattice.n_cells[0] + stripe_width - 1) / stripe_width, {});
    // Cells in lattice order, so every loop visits particles in the same
    // order whatever the history of insertions.
    std::array<int, dim> index{};
    for (std::size_t c = 0; c < lattice.n_cells_total(); ++c)
      {
        std::size_t rest = c;
        for (unsigned int d = 0; d < dim; ++d)
          {
            index[d] = rest % lattice.n_cells[d];
            rest /= lattice.n_cells[d];
          }
        const auto &cell = grid.cell(index);
        if (particle_handler.n_particles_in_cell(cell) > 0)
          stripes[index[0] / stripe_width].push_back(cell);
      }
  }



  template <int dim>
  void
  ParticleSystem<dim>::update_cells()
  {
    using particle_iterator     = Particles::ParticleIterator<dim>;
    const Lattice<dim> &lattice = grid.lattice();

    std::vector<std::vector<particle_iterator>> movers(stripes.size());
    std::vector<std::string>                    escaped(stripes.size());
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(stripes.size()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int s = begin; s < end; ++s)
          for (const auto &cell : stripes[s])
            {
              const auto here  = grid.lattice_cell(cell);
              auto       range = particle_handler.particles_in_cell(cell);
              for (auto it = range.begin(); it != range.end(); ++it)
                {
                  const Point<dim> x     = it->get_location();
                  const auto       there = lattice.cell_of(x);
                  if (!grid.stencil_inside(x) && escaped[s].empty())
                    {
                      std::ostringstream message;
                      message << "particle " << it->get_id() << " at ("
                              << to_input_string(x)
                              << ") left the usable grid (its kernel "
                                 "stencil must stay inside the grid)";
                      escaped[s] = message.str();
                    }
                  if (there == here)
                    it->set_reference_location(
                      reference_location<dim>(lattice, here, x));
                  else
                    movers[s].push_back(it);
                }
            }
      },
      1);
    for (const std::string &message : escaped)
      if (!message.empty())
        throw SimulationError(message);

    // Move the particles that changed cells: copy, remove, re-insert.
    struct Moved
    {
      Point<dim>            location;
      types::particle_index id;
      std::vector<double>   properties;
    };
    std::vector<Moved>             moved;
    std::vector<particle_iterator> removed;
    for (const auto &list : movers)
      for (const auto &it : list)
        {
          const auto properties = it->get_properties();
          moved.push_back(
            {it->get_location(),
             it->get_id(),
             std::vector<double>(properties.begin(), properties.end())});
          removed.push_back(it);
        }
    if (moved.empty())
      return;
    particle_handler.remove_particles(removed);
    for (const Moved &m : moved)
      {
        const auto cell = lattice.cell_of(m.location);
        particle_handler.insert_particle(m.location,
                                         reference_location<dim>(lattice,
                                                                 cell,
                                                                 m.location),
                                         m.id,
                                         grid.cell(cell),
                                         make_array_view(m.properties));
      }
    particle_handler.update_cached_numbers();
    rebuild_stripes();
    moved_since_ordering += moved.size();
    if (moved_since_ordering > n_particles() / 4)
      store_in_loop_order();
  }



  template class ParticleSystem<2>;
  template class ParticleSystem<3>;
} // namespace bfemp
