#ifndef bfemp_io_grid_output_h
#define bfemp_io_grid_output_h

#include <bfemp/grid/background_grid.h>
#include <bfemp/grid/grid_state.h>
#include <bfemp/io/pvd_series.h>

#include <string>

namespace bfemp
{
  /**
   * Snapshots of the active background grid (cells with at least one node
   * that carries mass): grid_NNNNN.vtu with nodal mass and velocity v~^{n+1},
   * listed in grid.pvd.
   */
  template <int dim>
  class GridOutput
  {
  public:
    GridOutput(const std::string &folder, const BackgroundGrid<dim> &grid);

    void
    write(const GridState<dim> &state,
          const double          time,
          const unsigned int    snapshot);

    /** Continues the series of a checkpointed run (PvdSeries::resume()). */
    void
    resume(const unsigned int next_snapshot);

  private:
    std::string                folder;
    const BackgroundGrid<dim> &grid;
    PvdSeries                  series;
  };
} // namespace bfemp

#endif
