#include "rodsea/calibration/calibration_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "rodsea/engine/parameters.hpp"
#include "rodsea/error.hpp"
#include "rodsea/text_file.hpp"

namespace rodsea {

namespace {

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ','))
        cells.push_back(cell);
    return cells;
}

bool same(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

std::string joined(const std::set<double>& values) {
    std::string s;
    for (double v : values) {
        if (!s.empty()) s += ", ";
        s += format_number(v);
    }
    return s;
}

}  // namespace

CalibrationTable CalibrationTable::read(const std::filesystem::path& path, double gap, double dt,
                                        physics::NoiseMode mode) {
    std::istringstream in(read_text_file(path));
    std::string line;
    std::vector<std::string> header;
    std::map<std::string, std::size_t> column;
    CalibrationTable table;
    table.path_ = path;
    std::set<double> gaps, steps;
    std::set<std::string> modes;
    long row = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> cells = split(line);
        if (header.empty()) {
            header = cells;
            for (std::size_t i = 0; i < header.size(); ++i)
                column[header[i]] = i;
            for (const char* needed : {"species", "gap", "dt", "epsilon", "D_r"})
                if (!column.count(needed))
                    throw FileError(path.string(), std::string("has no column '") + needed +
                                                       "': not a table from rodsea calibrate");
            continue;
        }
        ++row;
        if (cells.size() != header.size())
            throw FileError(path.string(),
                            "row " + std::to_string(row) + " has " + std::to_string(cells.size()) +
                                " cells, the header " + std::to_string(header.size()));
        if (cells[column["species"]] != "polar_rod") continue;
        // Values from a file meet the ranges their config keys have.
        const auto value = [&](const char* name, double lo, double hi) {
            const std::string& text = cells[column[name]];
            double v = 0.0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
            if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(v) ||
                v < lo || v > hi)
                throw FileError(path.string(), "row " + std::to_string(row) + ", column " + name +
                                                   ": '" + text + "'; allowed: a number in [" +
                                                   format_number(lo) + ", " + format_number(hi) +
                                                   "]");
            return v;
        };
        const std::string row_mode =
            column.count("noise_mode") ? cells[column["noise_mode"]] : std::string("add");
        if (row_mode != "add" && row_mode != "set")
            throw FileError(path.string(), "row " + std::to_string(row) + ", column noise_mode: '" +
                                               row_mode + "'; allowed: add or set");
        const double g = value("gap", 1e-6, 1e3), s = value("dt", 1e-12, 1.0);
        gaps.insert(g);
        steps.insert(s);
        modes.insert(row_mode);
        if (same(g, gap) && same(s, dt) && row_mode == to_string(mode))
            table.points_.push_back(
                {value("epsilon", 0.0, max_noise_epsilon(mode)), value("D_r", 0.0, 1e6)});
    }
    std::sort(table.points_.begin(), table.points_.end(),
              [](const Point& a, const Point& b) { return a.epsilon < b.epsilon; });
    if (table.points_.size() < 2) {
        std::string mode_list;
        for (const std::string& m : modes)
            mode_list += (mode_list.empty() ? "" : ", ") + m;
        throw InvalidParameter(
            "noise.calibration_table", path.string(),
            "a table with at least two polar_rod rows at gap " + format_number(gap) + " mm, dt " +
                format_number(dt) + " s and noise.mode = " + to_string(mode),
            "it has " + std::to_string(table.points_.size()) + " (its gaps: " + joined(gaps) +
                " mm; its dt: " + joined(steps) + " s; its noise modes: " + mode_list +
                "); run rodsea calibrate at this gap, dt and mode");
    }
    for (std::size_t i = 1; i < table.points_.size(); ++i) {
        const Point &a = table.points_[i - 1], &b = table.points_[i];
        if (!(b.d_r > a.d_r))
            throw InvalidParameter(
                "noise.calibration_table", path.string(), "D_r increasing with ε",
                "ε = " + format_number(a.epsilon) + " /mm gives D_r = " + format_number(a.d_r) +
                    ", ε = " + format_number(b.epsilon) + " /mm gives " + format_number(b.d_r) +
                    " rad²/s: measure longer (more copies, longer duration) or space ε wider");
    }
    return table;
}

double CalibrationTable::epsilon_for(double d_r) const {
    const Point &lo = points_.front(), &hi = points_.back();
    // A row at ε = 0 is the noiseless rod: its small measured D_r (start-up turning) is the
    // least the table can give, and any D_r from 0 up to it means no noise.
    const double least = lo.epsilon == 0.0 ? 0.0 : lo.d_r;
    if (!(d_r >= least && d_r <= hi.d_r))
        throw InvalidParameter(
            "noise.rotational_diffusion", format_number(d_r) + " rad²/s",
            "[" + format_number(least) + ", " + format_number(hi.d_r) + "] rad²/s",
            "the range of " + path_.string() + " (ε from " + format_number(lo.epsilon) + " to " +
                format_number(hi.epsilon) + " /mm); extend it with rodsea calibrate");
    if (d_r <= lo.d_r) return lo.epsilon;
    std::size_t i = 1;
    while (i + 1 < points_.size() && points_[i].d_r < d_r)
        ++i;
    const Point &a = points_[i - 1], &b = points_[i];
    return a.epsilon + (b.epsilon - a.epsilon) * (d_r - a.d_r) / (b.d_r - a.d_r);
}

EpsilonLookup calibration_table_lookup() {
    return [](const std::filesystem::path& table, double gap, double dt, physics::NoiseMode mode,
              double d_r) { return CalibrationTable::read(table, gap, dt, mode).epsilon_for(d_r); };
}

}  // namespace rodsea
