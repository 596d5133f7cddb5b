#ifndef bfemp_io_pvd_series_h
#define bfemp_io_pvd_series_h

#include <string>
#include <utility>
#include <vector>

namespace bfemp
{
  /**
   * A ParaView time series (.pvd) that lists one VTU file per snapshot. The
   * .pvd is rewritten atomically after each snapshot, so it only ever names
   * files that exist in full.
   */
  class PvdSeries
  {
  public:
    /** @p pvd_path: the .pvd file; VTU names are relative to its folder. */
    explicit PvdSeries(const std::string &pvd_path);

    void
    add(const double time, const std::string &vtu_file_name);

    /**
     * For a run continued from a checkpoint taken before snapshot
     * @p next_snapshot: reads the existing .pvd (if any) and keeps the
     * snapshots before that one (VTU names end in _<snapshot>.vtu); the VTU
     * files of later ones, written after the checkpoint, are deleted.
     */
    void
    resume(const unsigned int next_snapshot);

  private:
    std::string                                 pvd_path;
    std::vector<std::pair<double, std::string>> times_and_names;
  };
} // namespace bfemp

#endif
