#include "rodsea/io/series_csv.hpp"

#include <cerrno>
#include <cstring>
#include <sstream>
#include <string>

#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"

namespace rodsea {

namespace {

std::ofstream open_for_append(const std::filesystem::path& path) {
    std::ofstream out(path, std::ios::binary | std::ios::app);
    if (!out) throw FileError(path.string(), std::string("cannot open: ") + std::strerror(errno));
    out.precision(17);
    return out;
}

}  // namespace

SeriesCsv SeriesCsv::create(const std::filesystem::path& path,
                            const std::vector<SeriesColumn>& columns) {
    std::ostringstream head;
    head << "# rodsea " << RODSEA_VERSION << " time series; units:";
    for (const SeriesColumn& c : columns)
        head << ' ' << c.name << " [" << c.unit << "]";
    head << "\nstep,time";
    for (const SeriesColumn& c : columns)
        head << ',' << c.name;
    head << '\n';
    write_file_atomically(path, head.str());
    return SeriesCsv(path, open_for_append(path));
}

SeriesCsv SeriesCsv::reopen(const std::filesystem::path& path, std::uint64_t rows) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path.string(), "cannot read the time series to resume it");
    std::string kept, line;
    std::uint64_t data_rows = 0;
    int header_lines = 0;
    while (std::getline(in, line)) {
        const bool header = header_lines < 2;
        if (header) {
            ++header_lines;
        } else {
            // A line cut short by a crash has no newline at the end: drop it with the rest.
            if (data_rows == rows || in.eof()) break;
            ++data_rows;
        }
        kept += line + '\n';
    }
    if (header_lines < 2 || data_rows < rows)
        throw FileError(path.string(), "has " + std::to_string(data_rows) +
                                           " rows but the checkpoint says " + std::to_string(rows) +
                                           " were written");
    write_file_atomically(path, kept);
    return SeriesCsv(path, open_for_append(path));
}

void SeriesCsv::append(std::uint64_t step, double time, const std::vector<double>& values) {
    out_ << step << ',' << time;
    for (double v : values)
        out_ << ',' << v;
    out_ << '\n';
}

void SeriesCsv::flush() {
    out_.flush();
    if (!out_)
        throw FileError(path_.string(), std::string("write failed: ") + std::strerror(errno));
}

}  // namespace rodsea
