#ifndef bfemp_io_atomic_file_h
#define bfemp_io_atomic_file_h

#include <functional>
#include <ostream>
#include <string>

namespace bfemp
{
  /**
   * Writes a file complete or not at all: @p write fills a temporary file
   * next to @p path, which is renamed onto @p path only after it was closed
   * without error. A reader (ParaView, a crash, a test) never sees a partial
   * file.
   */
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write);
} // namespace bfemp

#endif
