#include "rodsea/io/progress_file.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "rodsea/io/atomic_file.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

double unix_time_now() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

void write_progress_file(const std::filesystem::path& run_dir, const RunProgress& p) {
    std::ostringstream s;
    s << "# rodsea run progress; times in s\n"
      << "state = " << p.state << "\nstep = " << p.step << "\ntotal_steps = " << p.total_steps
      << "\ntime = " << exact_number(p.time) << "\nduration = " << exact_number(p.duration)
      << "\nsteps_per_second = " << exact_number(p.steps_per_second)
      << "\nwall_seconds = " << exact_number(p.wall_seconds)
      << "\nupdated = " << exact_number(p.updated) << "\n";
    write_file_atomically(run_dir / kProgressFile, s.str());
}

std::optional<RunProgress> read_progress_file(const std::filesystem::path& run_dir) {
    std::ifstream in(run_dir / kProgressFile);
    if (!in) return std::nullopt;
    RunProgress p;
    int found = 0;
    for (std::string line; std::getline(in, line);) {
        const std::size_t eq = line.find(" = ");
        if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
        const std::string key = line.substr(0, eq), value = line.substr(eq + 3);
        try {
            if (key == "state")
                p.state = value;
            else if (key == "step")
                p.step = std::stoull(value);
            else if (key == "total_steps")
                p.total_steps = std::stoull(value);
            else if (key == "time")
                p.time = std::stod(value);
            else if (key == "duration")
                p.duration = std::stod(value);
            else if (key == "steps_per_second")
                p.steps_per_second = std::stod(value);
            else if (key == "wall_seconds")
                p.wall_seconds = std::stod(value);
            else if (key == "updated")
                p.updated = std::stod(value);
            else
                continue;
            ++found;
        } catch (const std::exception&) {
            return std::nullopt;  // a damaged file says nothing
        }
    }
    if (found < 8 || p.total_steps == 0 || p.step > p.total_steps) return std::nullopt;
    // Values read from a file are input: a NaN or a negative time is a damaged file too.
    for (const double v : {p.time, p.duration, p.steps_per_second, p.wall_seconds, p.updated})
        if (!std::isfinite(v) || v < 0.0) return std::nullopt;
    return p;
}

}  // namespace rodsea
