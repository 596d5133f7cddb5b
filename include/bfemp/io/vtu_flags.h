#ifndef bfemp_io_vtu_flags_h
#define bfemp_io_vtu_flags_h

#include <deal.II/base/data_out_base.h>

namespace bfemp
{
  using namespace dealii;

  /**
   * The flags of every VTU file bfemp writes: the snapshot's @p time, and
   * zlib's fastest compression. deal.II's default (best compression) made
   * zlib take 62 % of a 2D cMPM run that writes its 16000 particles every
   * step (doc/performance.md "Output"); the fastest level writes the same
   * data several times faster in files only slightly larger.
   */
  inline DataOutBase::VtkFlags
  vtu_flags(const double time)
  {
    DataOutBase::VtkFlags flags;
    flags.time              = time;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    return flags;
  }
} // namespace bfemp

#endif
