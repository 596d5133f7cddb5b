#include <bfemp/base/input_error.h>
#include <bfemp/io/atomic_file.h>
#include <bfemp/io/csv_file.h>

#include <cctype>
#include <filesystem>
#include <vector>

namespace bfemp
{
  namespace
  {
    /** The header and the rows up to @p last_step of an existing file. */
    std::vector<std::string>
    lines_up_to_step(const std::string &path,
                     const std::string &header,
                     const unsigned int last_step)
    {
      std::ifstream            in(path);
      std::vector<std::string> lines;
      std::string              line;
      if (!std::getline(in, line) || line != header)
        throw InputError(
          path + ": its columns differ from this run's, so the continued run "
                 "cannot append to it (an entry that adds columns changed "
                 "since the checkpoint); restore that entry or start again "
                 "with 'checkpoint/resume = false'");
      lines.push_back(line);
      while (std::getline(in, line))
        {
          // A line cut short by a crash can only follow the checkpoint's row.
          if (line.empty() ||
              !std::isdigit(static_cast<unsigned char>(line[0])) ||
              std::stoul(line) > last_step)
            break;
          lines.push_back(line);
        }
      return lines;
    }
  } // namespace



  void
  open_csv_file(std::ofstream                     &file,
                const std::string                 &path,
                const std::string                 &header,
                const std::optional<unsigned int> &resume_after_step)
  {
    if (resume_after_step && std::filesystem::exists(path))
      {
        const std::vector<std::string> kept =
          lines_up_to_step(path, header, *resume_after_step);
        write_file_atomically(path, [&](std::ostream &out) {
          for (const std::string &line : kept)
            out << line << '\n';
        });
        file.open(path, std::ios::app);
      }
    else
      {
        file.open(path);
        file << header << std::endl;
      }
    if (!file)
      throw SimulationError("cannot open " + path + " for writing");
  }
} // namespace bfemp
