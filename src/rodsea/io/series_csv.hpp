#pragma once
// The scalar time series as CSV beside the HDF5 file, for a quick look with any tool: a comment
// line with the units, a header, then one row per output interval, appended and flushed as the
// run goes.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "rodsea/io/trajectory_file.hpp"

namespace rodsea {

class SeriesCsv {
  public:
    // Creates (or truncates) `path` and writes the header.
    static SeriesCsv create(const std::filesystem::path& path,
                            const std::vector<SeriesColumn>& columns);
    // Keeps the header and the first `rows` rows (those the checkpoint knows of), atomically,
    // then appends after them.
    static SeriesCsv reopen(const std::filesystem::path& path, std::uint64_t rows);

    void append(std::uint64_t step, double time, const std::vector<double>& values);
    void flush();  // throws FileError when the data did not reach the file

  private:
    SeriesCsv(std::filesystem::path path, std::ofstream out)
        : path_(std::move(path)), out_(std::move(out)) {}
    std::filesystem::path path_;
    std::ofstream out_;
};

}  // namespace rodsea
