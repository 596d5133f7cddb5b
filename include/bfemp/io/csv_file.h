#ifndef bfemp_io_csv_file_h
#define bfemp_io_csv_file_h

#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace bfemp
{
  /**
   * Opens @p file at @p path for a run's rows (first column: the step) and
   * writes @p header (without a line end) to a new file. A run continued
   * from the checkpoint of step @p resume_after_step appends instead: the
   * existing rows after that step came from the interrupted part and are
   * dropped (the cut file replaces the old one atomically). If the existing
   * file lacks some of the columns of @p header (it was written by an older
   * bfemp), its rows are rewritten to the new columns with nan in the
   * missing ones, and the names of those are returned. Throws InputError if
   * the existing file has a column that @p header lacks, SimulationError if
   * the file cannot be written.
   */
  std::vector<std::string>
  open_csv_file(std::ofstream                     &file,
                const std::string                 &path,
                const std::string                 &header,
                const std::optional<unsigned int> &resume_after_step);
} // namespace bfemp

#endif
