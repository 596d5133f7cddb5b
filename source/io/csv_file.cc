#include <bfemp/base/input_error.h>
#include <bfemp/io/atomic_file.h>
#include <bfemp/io/csv_file.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

namespace bfemp
{
  namespace
  {
    std::string
    joined(const std::vector<std::string> &fields)
    {
      std::string line;
      for (const std::string &field : fields)
        line += (line.empty() ? "" : ",") + field;
      return line;
    }

    /**
     * For each column of @p header, its index in @p old_header, or -1 for a
     * column the old file lacks. An old column that this run no longer
     * writes cannot be carried over, so it is an InputError.
     */
    std::vector<int>
    old_column_of_each_column(const std::string &path,
                              const std::string &old_header,
                              const std::string &header)
    {
      const std::vector<std::string> old_columns =
        dealii::Utilities::split_string_list(old_header, ',');
      const std::vector<std::string> columns =
        dealii::Utilities::split_string_list(header, ',');
      std::vector<std::string> dropped;
      for (const std::string &column : old_columns)
        if (std::find(columns.begin(), columns.end(), column) == columns.end())
          dropped.push_back(column);
      if (!dropped.empty())
        throw InputError(
          path + ": the continued run does not write its column(s) " +
          joined(dropped) +
          ", so it cannot append to it (an entry that adds columns changed "
          "since the checkpoint, or another bfemp version wrote it); restore "
          "that entry or start again with 'checkpoint/resume = false'");
      std::vector<int> old_index;
      for (const std::string &column : columns)
        {
          const auto found =
            std::find(old_columns.begin(), old_columns.end(), column);
          old_index.push_back(
            found == old_columns.end()
              ? -1
              : static_cast<int>(found - old_columns.begin()));
        }
      return old_index;
    }

    /**
     * The header and the rows up to @p last_step of an existing file, with
     * the rows rewritten to the columns of @p header: a column that the
     * file lacks (a newer bfemp writes more) is nan in the earlier rows, and
     * its name is added to @p added_columns.
     */
    std::vector<std::string>
    lines_up_to_step(const std::string        &path,
                     const std::string        &header,
                     const unsigned int        last_step,
                     std::vector<std::string> &added_columns)
    {
      std::ifstream            in(path);
      std::vector<std::string> lines{header};
      std::string              line;
      if (!std::getline(in, line))
        throw InputError(path + ": the file is empty, so the continued run "
                                "cannot append to it; start again with "
                                "'checkpoint/resume = false'");
      const bool       same_columns = (line == header);
      std::vector<int> old_index;
      if (!same_columns)
        {
          old_index = old_column_of_each_column(path, line, header);
          const std::vector<std::string> columns =
            dealii::Utilities::split_string_list(header, ',');
          for (unsigned int c = 0; c < columns.size(); ++c)
            if (old_index[c] < 0)
              added_columns.push_back(columns[c]);
        }
      while (std::getline(in, line))
        {
          // A line cut short by a crash can only follow the checkpoint's row.
          if (line.empty() ||
              !std::isdigit(static_cast<unsigned char>(line[0])) ||
              std::stoul(line) > last_step)
            break;
          if (same_columns)
            {
              lines.push_back(line);
              continue;
            }
          const std::vector<std::string> old_fields =
            dealii::Utilities::split_string_list(line, ',');
          std::vector<std::string> fields;
          for (const int index : old_index)
            fields.push_back(index >= 0 && static_cast<std::size_t>(index) <
                                             old_fields.size()
                               ? old_fields[index]
                               : "nan");
          lines.push_back(joined(fields));
        }
      return lines;
    }
  } // namespace



  std::vector<std::string>
  open_csv_file(std::ofstream                     &file,
                const std::string                 &path,
                const std::string                 &header,
                const std::optional<unsigned int> &resume_after_step)
  {
    std::vector<std::string> added_columns;
    if (resume_after_step && std::filesystem::exists(path))
      {
        const std::vector<std::string> kept =
          lines_up_to_step(path, header, *resume_after_step, added_columns);
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
    return added_columns;
  }
} // namespace bfemp
