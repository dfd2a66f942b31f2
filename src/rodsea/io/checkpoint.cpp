#include "rodsea/io/checkpoint.hpp"

#include <cmath>
#include <cstdio>

#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/detail/hdf5.hpp"

namespace rodsea {

namespace {

constexpr const char* kGroup = "rodsea_checkpoint";
constexpr const char* kFormat = "rodsea checkpoint 2";
constexpr const char* kFormatBeforeRunIds = "rodsea checkpoint 1";

std::vector<double> flatten(const std::vector<Vec3>& v) {
    std::vector<double> out;
    out.reserve(3 * v.size());
    for (const Vec3& x : v)
        out.insert(out.end(), {x.x, x.y, x.z});
    return out;
}

std::vector<Vec3> unflatten(const std::vector<double>& d, size_t n, const std::string& name,
                            const std::filesystem::path& path) {
    if (d.size() != 3 * n)
        throw FileError(path.string(), name + " has " + std::to_string(d.size()) +
                                           " numbers, expected " + std::to_string(3 * n));
    std::vector<Vec3> v(n);
    for (size_t i = 0; i < n; ++i)
        v[i] = {d[3 * i], d[3 * i + 1], d[3 * i + 2]};
    return v;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c) {
    replace_file_atomically(path, [&](const std::filesystem::path& tmp) {
        h5::File f = h5::File::create(tmp);
        {
            h5::Handle g = h5::create_group(f, f.id(), kGroup);
            h5::write_attribute(f, g.get(), "format", std::string(kFormat));
            h5::write_attribute(f, g.get(), "version", std::string(RODSEA_VERSION));
            h5::write_attribute(f, g.get(), "run_id", c.run_id);
            h5::write_attribute(f, g.get(), "config_fingerprint",
                                config_fingerprint(c.config_toml));
            h5::write_attribute(f, g.get(), "extending_from", c.extending_from);
            h5::write_string_dataset(f, g.get(), "config", c.config_toml);
            h5::write_dataset(
                f, g.get(), "counters",
                std::vector<std::uint64_t>{c.step, c.frames_written, c.complete ? 1u : 0u}, {3});
            h5::write_dataset(f, g.get(), "wall_seconds", std::vector<double>{c.wall_seconds}, {1},
                              "s");
            h5::write_dataset(f, g.get(), "interval_accumulators", c.interval_accumulators,
                              {c.interval_accumulators.size()});
            const size_t n = c.bodies.size();
            std::vector<std::int32_t> species(c.bodies.species.begin(), c.bodies.species.end());
            h5::write_dataset(f, g.get(), "species", species, {n});
            h5::write_dataset(f, g.get(), "position", flatten(c.bodies.position), {n, 3}, "mm");
            std::vector<double> q;
            q.reserve(4 * n);
            for (const Quat& o : c.bodies.orientation)
                q.insert(q.end(), {o.w, o.x, o.y, o.z});
            h5::write_dataset(f, g.get(), "orientation", q, {n, 4}, "1");
            h5::write_dataset(f, g.get(), "velocity", flatten(c.bodies.velocity), {n, 3}, "mm s-1");
            h5::write_dataset(f, g.get(), "angular_velocity", flatten(c.bodies.spin), {n, 3},
                              "rad s-1");
        }
        f.close();
    });
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
    const h5::File f = h5::File::open(path, false);
    if (!h5::exists(f.id(), kGroup))
        throw FileError(path.string(), "not a rodsea checkpoint (no /" + std::string(kGroup) + ")");
    h5::Handle g = h5::open_group(f, f.id(), kGroup);
    const std::string format = h5::read_string_attribute(f, g.get(), "format");
    if (format != kFormat && format != kFormatBeforeRunIds)
        throw FileError(path.string(), "checkpoint format is '" + format + "', not '" +
                                           std::string(kFormat) + "'");
    Checkpoint c;
    c.config_toml = h5::read_string_dataset(f, g.get(), "config");
    if (format == kFormat) {
        c.run_id = h5::read_string_attribute(f, g.get(), "run_id");
        c.extending_from = h5::read_string_attribute(f, g.get(), "extending_from");
        const std::string stored = h5::read_string_attribute(f, g.get(), "config_fingerprint");
        if (stored != config_fingerprint(c.config_toml))
            throw FileError(path.string(),
                            "its config was changed after it was written "
                            "(fingerprint " +
                                config_fingerprint(c.config_toml) + ", written with " + stored +
                                "): a checkpoint is resumed with the config it "
                                "was written with; extend a run with "
                                "rodsea run --resume DIR --duration T");
    }
    const std::vector<std::uint64_t> counters = h5::read_uint64s(f, g.get(), "counters");
    if (counters.size() != 3) throw FileError(path.string(), "damaged checkpoint counters");
    c.step = counters[0];
    c.frames_written = counters[1];
    c.complete = counters[2] != 0;
    const std::vector<double> wall = h5::read_doubles(f, g.get(), "wall_seconds");
    if (wall.size() != 1) throw FileError(path.string(), "damaged checkpoint wall time");
    c.wall_seconds = wall[0];
    c.interval_accumulators = h5::read_doubles(f, g.get(), "interval_accumulators");
    const std::vector<std::int32_t> species = h5::read_ints(f, g.get(), "species");
    const size_t n = species.size();
    for (size_t i = 0; i < n; ++i)
        if (species[i] < 0)
            throw FileError(path.string(), "damaged: dataset species gives body " +
                                               std::to_string(i) + " the species index " +
                                               std::to_string(species[i]));
    c.bodies.species.assign(species.begin(), species.end());
    c.bodies.position = unflatten(h5::read_doubles(f, g.get(), "position"), n, "position", path);
    c.bodies.velocity = unflatten(h5::read_doubles(f, g.get(), "velocity"), n, "velocity", path);
    c.bodies.spin =
        unflatten(h5::read_doubles(f, g.get(), "angular_velocity"), n, "angular_velocity", path);
    const std::vector<double> q = h5::read_doubles(f, g.get(), "orientation");
    if (q.size() != 4 * n) throw FileError(path.string(), "damaged checkpoint orientations");
    c.bodies.orientation.resize(n);
    for (size_t i = 0; i < n; ++i)
        c.bodies.orientation[i] = {q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]};
    for (double x : c.interval_accumulators)
        if (!std::isfinite(x))
            throw FileError(path.string(),
                            "damaged: a time-series accumulator is " + format_number(x));
    // 10^10 s is three centuries of wall time.
    if (!std::isfinite(c.wall_seconds) || c.wall_seconds < 0.0 || c.wall_seconds > 1e10)
        throw FileError(path.string(),
                        "damaged: wall_seconds is " + format_number(c.wall_seconds) + " s");
    return c;
}

std::string config_fingerprint(const std::string& config_toml) {
    std::uint64_t h = 14695981039346656037ULL;
    for (const unsigned char ch : config_toml) {
        h ^= ch;
        h *= 1099511628211ULL;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

}  // namespace rodsea
