#include <bfemp/base/input_error.h>
#include <bfemp/io/atomic_file.h>

#include <filesystem>
#include <fstream>

namespace bfemp
{
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".part";
    {
      std::ofstream out(temporary, std::ios::binary);
      if (!out)
        throw SimulationError("cannot open '" + temporary + "' for writing");
      write(out);
      out.close();
      if (!out)
        throw SimulationError("writing '" + temporary + "' failed");
    }
    std::filesystem::rename(temporary, path);
  }
} // namespace bfemp
