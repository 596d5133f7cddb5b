#include <bfemp/base/input_error.h>
#include <bfemp/particles/particle_system.h>

#include <cmath>
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
    n_particles_total = particle_handler.n_locally_owned_particles();
    rebuild_stripes();
    store_in_loop_order();
  }



  template <int dim>
  typename ParticleSystem<dim>::Records
  ParticleSystem<dim>::gather_in_loop_order() const
  {
    Records records;
    records.properties.reserve(n_particles_total * Layout::n_properties);
    records.ids.reserve(n_particles_total);
    records.locations.reserve(n_particles_total);
    for (const auto &stripe : stripes)
      for (const auto &cell : stripe)
        for (const auto &particle : particle_handler.particles_in_cell(cell))
          {
            const auto properties = particle.get_properties();
            records.properties.insert(records.properties.end(),
                                      properties.begin(),
                                      properties.end());
            records.ids.push_back(particle.get_id());
            records.locations.push_back(particle.get_location());
          }
    return records;
  }



  template <int dim>
  void
  ParticleSystem<dim>::insert_records(const Records &records)
  {
    const unsigned int  n_properties = Layout::n_properties;
    const Lattice<dim> &lattice      = grid.lattice();
    particle_handler.clear_particles();
    for (std::size_t k = 0; k < records.ids.size(); ++k)
      {
        const Point<dim> &x    = records.locations[k];
        const auto        cell = lattice.cell_of(x);
        particle_handler.insert_particle(
          x,
          reference_location<dim>(lattice, cell, x),
          records.ids[k],
          grid.cell(cell),
          ArrayView<const double>(records.properties.data() + k * n_properties,
                                  n_properties));
      }
  }



  template <int dim>
  void
  ParticleSystem<dim>::replace_all(const Records &records)
  {
    AssertThrow(records.locations.size() == records.ids.size() &&
                  records.properties.size() ==
                    records.ids.size() * Layout::n_properties,
                ExcMessage("inconsistent particle records"));
    for (std::size_t k = 0; k < records.ids.size(); ++k)
      if (!grid.stencil_inside(records.locations[k]))
        throw SimulationError("particle " + std::to_string(records.ids[k]) +
                              " at (" + to_input_string(records.locations[k]) +
                              ") lies outside the usable grid");
    insert_records(records);
    next_id = 0;
    for (const auto id : records.ids)
      next_id = std::max(next_id, id + 1);
    finish_insertion();
  }



  template <int dim>
  void
  ParticleSystem<dim>::store_in_loop_order()
  {
    // Particle data lives in deal.II's PropertyPool in the order particles
    // were inserted; after many cell changes a loop over cells jumps around
    // memory and is bound by cache misses. Re-inserting every particle in
    // loop order makes the loops stream through memory again.
    insert_records(gather_in_loop_order());
    // The number of particles is unchanged, so deal.II's cached counts (a
    // full pass over the particles to refresh) are not needed here.
    moved_since_ordering = 0;
  }



  template <int dim>
  types::particle_index
  ParticleSystem<dim>::n_particles() const
  {
    return n_particles_total;
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
    for (unsigned int s = 0; s < stripes.size(); ++s)
      rebuild_stripe(s);
  }



  template <int dim>
  void
  ParticleSystem<dim>::rebuild_stripe(const unsigned int s)
  {
    // Cells in lattice order (x fastest), so every loop visits particles in
    // the same order whatever the history of insertions.
    const Lattice<dim> &lattice = grid.lattice();
    const int           first   = s * stripe_width;
    const int last = std::min<int>(first + stripe_width, lattice.n_cells[0]);
    const int n_z  = dim == 3 ? lattice.n_cells[dim - 1] : 1;
    stripes[s].clear();
    std::array<int, dim> index{};
    for (int z = 0; z < n_z; ++z)
      for (int y = 0; y < static_cast<int>(lattice.n_cells[1]); ++y)
        for (int x = first; x < last; ++x)
          {
            index[0] = x;
            index[1] = y;
            if constexpr (dim == 3)
              index[2] = z;
            const auto &cell = grid.cell(index);
            if (particle_handler.n_particles_in_cell(cell) > 0)
              stripes[s].push_back(cell);
          }
  }



  template <int dim>
  void
  ParticleSystem<dim>::update_cells()
  {
    using particle_iterator     = Particles::ParticleIterator<dim>;
    const Lattice<dim> &lattice = grid.lattice();

    // Find, in parallel, the particles whose cell changed. Reference
    // locations are not refreshed: bfemp evaluates kernels by lattice
    // arithmetic and never reads them.
    std::vector<std::vector<particle_iterator>> movers(stripes.size());
    std::vector<std::string>                    escaped(stripes.size());
    parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(stripes.size()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int s = begin; s < end; ++s)
          for (const auto &cell : stripes[s])
            {
              const std::size_t here =
                lattice.cell_index(grid.lattice_cell(cell));
              auto range = particle_handler.particles_in_cell(cell);
              for (auto it = range.begin(); it != range.end(); ++it)
                {
                  const Point<dim> x = it->get_location();
                  if (!std::isfinite(x.norm_square()))
                    {
                      if (escaped[s].empty())
                        escaped[s] =
                          "particle " + std::to_string(it->get_id()) +
                          " has a non-finite position: the state became NaN "
                          "or inf (an explicit step beyond its stability "
                          "limit, e.g. a CFL number too close to 1 for a "
                          "stiffening material); reduce the time step or the "
                          "CFL number";
                    }
                  else if (!grid.stencil_inside(x))
                    {
                      if (escaped[s].empty())
                        escaped[s] = "particle " +
                                     std::to_string(it->get_id()) + " at (" +
                                     to_input_string(x) +
                                     ") left the usable grid (its kernel "
                                     "stencil must stay inside the grid)";
                    }
                  else if (lattice.cell_index(lattice.cell_of(x)) != here)
                    movers[s].push_back(it);
                }
            }
      },
      1);
    for (const std::string &message : escaped)
      if (!message.empty())
        throw SimulationError(message);

    // Move them one at a time: remove, then re-insert into the new cell.
    // deal.II's PropertyPool hands the slot just freed to the next insert,
    // so each particle keeps its memory slot and the data stays in (nearly)
    // loop order. Removing a particle may shift later particles of the same
    // cell, so each cell's movers go from the last to the first.
    const unsigned int  n_properties = Layout::n_properties;
    std::vector<double> properties(n_properties);
    std::vector<bool>   occupancy_changed(stripes.size(), false);
    std::size_t         n_moved = 0;
    for (auto list = movers.rbegin(); list != movers.rend(); ++list)
      for (auto it = list->rbegin(); it != list->rend(); ++it, ++n_moved)
        {
          const auto      &particle = *it;
          const auto       p        = particle->get_properties();
          const Point<dim> x        = particle->get_location();
          const auto       id       = particle->get_id();
          const auto       source   = particle->get_surrounding_cell();
          std::copy(p.begin(), p.end(), properties.begin());
          particle_handler.remove_particle(particle);

          // The stripes list the cells that hold particles: a stripe needs a
          // rebuild only if one of its cells was emptied or filled.
          const auto  index = lattice.cell_of(x);
          const auto &cell  = grid.cell(index);
          if (particle_handler.n_particles_in_cell(source) == 0)
            occupancy_changed[grid.lattice_cell(source)[0] / stripe_width] =
              true;
          if (particle_handler.n_particles_in_cell(cell) == 0)
            occupancy_changed[index[0] / stripe_width] = true;
          particle_handler.insert_particle(x,
                                           reference_location<dim>(lattice,
                                                                   index,
                                                                   x),
                                           id,
                                           cell,
                                           make_array_view(properties));
        }
    if (n_moved == 0)
      return;
    for (unsigned int stripe = 0; stripe < stripes.size(); ++stripe)
      if (occupancy_changed[stripe])
        rebuild_stripe(stripe);
    moved_since_ordering += n_moved;
    if (moved_since_ordering > n_particles() / 4)
      store_in_loop_order();
  }



  template class ParticleSystem<2>;
  template class ParticleSystem<3>;
} // namespace bfemp
