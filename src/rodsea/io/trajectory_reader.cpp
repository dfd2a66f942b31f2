#include "rodsea/io/trajectory_reader.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "rodsea/error.hpp"
#include "rodsea/io/detail/hdf5.hpp"

namespace rodsea {

namespace {

// The frame count and per-frame shape of an [frames, n, width] dataset.
std::vector<hsize_t> dataset_dims(const h5::File& f, const std::string& name) {
    h5::Handle set(H5Dopen2(f.id(), name.c_str(), H5P_DEFAULT));
    if (set.get() < 0) h5::fail(f.path(), "no dataset " + name + " (not a rodsea trajectory?)");
    h5::Handle space(H5Dget_space(set.get()));
    const int rank = H5Sget_simple_extent_ndims(space.get());
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank < 0 ? 0 : rank));
    if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    return dims;
}

// Frame `index` of an [frames, n, width] float dataset.
std::vector<float> read_frame(const h5::File& f, const std::string& name, std::uint64_t index,
                              size_t n, size_t width) {
    h5::Handle set(H5Dopen2(f.id(), name.c_str(), H5P_DEFAULT));
    if (set.get() < 0) h5::fail(f.path(), "no dataset " + name + " (not a rodsea trajectory?)");
    h5::Handle space(H5Dget_space(set.get()));
    const hsize_t start[3] = {index, 0, 0}, count[3] = {1, n, width};
    H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr);
    h5::Handle memory(H5Screate_simple(3, count, nullptr));
    std::vector<float> data(n * width);
    if (H5Dread(set.get(), H5T_NATIVE_FLOAT, memory.get(), space.get(), H5P_DEFAULT, data.data()) <
        0)
        h5::fail(f.path(), "cannot read frame " + std::to_string(index) + " of " + name);
    return data;
}

}  // namespace

// The files the frames come from: one, or a run's directories joined (joined()), each holding
// the reader's frames [first, first + count) as its own 0 .. count − 1.
struct TrajectoryReader::Impl {
    struct Part {
        h5::File file;
        std::uint64_t first = 0, count = 0;
    };
    std::vector<Part> parts;

    const Part& part_of(std::uint64_t index) const {
        for (const Part& p : parts)
            if (index < p.first + p.count) return p;
        return parts.back();
    }
};

namespace {
std::vector<double> part_series(const h5::File& f, std::uint64_t frames, const std::string& column);
}  // namespace

TrajectoryReader::TrajectoryReader(const std::filesystem::path& path) : impl_(new Impl) {
    impl_->parts.push_back({h5::File::open(path, false), 0, 0});
    const h5::File& f = impl_->parts.front().file;
    if (!h5::exists(f.id(), "h5md") || !h5::exists(f.id(), "particles/bodies/position"))
        throw FileError(path.string(), "not a rodsea trajectory (no H5MD /particles/bodies)");
    h5::Handle position = h5::open_group(f, f.id(), "particles/bodies/position");
    const std::vector<double> steps = h5::read_doubles(f, position.get(), "step");
    times_ = h5::read_doubles(f, position.get(), "time");
    const std::string where = path.string();
    // A writer killed within a frame leaves its step without its time (TrajectoryFile writes
    // value, step, time in that order): such a frame is not complete and is not read.
    times_.resize(std::min(steps.size(), times_.size()));
    for (std::size_t k = 0; k < times_.size(); ++k) {
        const auto bad = [&](const std::string& what, double value) {
            throw FileError(where, "/particles/bodies/position/" + what + ", frame " +
                                       std::to_string(k) + ": " + format_number(value) +
                                       "; allowed: finite, >= 0 and increasing from frame to "
                                       "frame");
        };
        // Steps are whole numbers below 2^53: exact in a double, as h5py reads them too.
        if (!std::isfinite(steps[k]) || steps[k] < 0.0 || steps[k] > 9.0e15 ||
            steps[k] != std::floor(steps[k]) || (k > 0 && steps[k] <= steps[k - 1]))
            bad("step", steps[k]);
        if (!std::isfinite(times_[k]) || times_[k] < 0.0 || (k > 0 && times_[k] <= times_[k - 1]))
            bad("time", times_[k]);
        steps_.push_back(static_cast<std::int64_t>(steps[k]));
    }
    h5::Handle bodies = h5::open_group(f, f.id(), "particles/bodies");
    const std::vector<std::int32_t> species = h5::read_ints(f, bodies.get(), "species");
    h5::Handle stored = h5::open_group(f, f.id(), "parameters/rodsea/species");
    H5G_info_t info{};
    if (H5Gget_info(stored.get(), &info) < 0)
        h5::fail(path, "cannot list /parameters/rodsea/species");
    const auto kinds = static_cast<std::int64_t>(info.nlinks);
    for (std::size_t b = 0; b < species.size(); ++b)
        if (species[b] < 0 || species[b] >= kinds)
            throw FileError(where, "/particles/bodies/species, body " + std::to_string(b) + ": " +
                                       std::to_string(species[b]) + "; allowed: [0, " +
                                       std::to_string(kinds - 1) + "] (the file stores " +
                                       std::to_string(kinds) + " species)");
    species_.assign(species.begin(), species.end());
    const hsize_t n = species_.size(), frames = steps_.size();
    for (const auto& [name, width] : {std::pair<const char*, hsize_t>{"position", 3},
                                      {"orientation", 4},
                                      {"velocity", 3},
                                      {"angular_velocity", 3}}) {
        const std::string dataset = std::string("particles/bodies/") + name + "/value";
        const std::vector<hsize_t> dims = dataset_dims(f, dataset);
        if (dims.size() != 3 || dims[0] < frames || dims[1] != n || dims[2] != width)
            throw FileError(where, "/" + dataset + " is not [" + std::to_string(frames) + ", " +
                                       std::to_string(n) + ", " + std::to_string(width) +
                                       "] (frames, bodies, components)");
    }
    impl_->parts.front().count = frames;
    for (const std::string& column : series_names())
        part_series(f, frames, column);
}

TrajectoryReader TrajectoryReader::joined(std::vector<TrajectoryReader> parts,
                                          const std::vector<std::uint64_t>& keep) {
    if (parts.empty() || keep.size() != parts.size())
        throw std::logic_error("TrajectoryReader::joined: one count per part");
    TrajectoryReader all;
    all.impl_ = std::make_unique<Impl>();
    all.species_ = parts.front().species_;
    const std::string first_path = parts.front().impl_->parts.front().file.path().string();
    for (std::size_t k = 0; k < parts.size(); ++k) {
        TrajectoryReader& part = parts[k];
        const std::string where = part.impl_->parts.front().file.path().string();
        if (part.impl_->parts.size() != 1 || keep[k] > part.frames())
            throw std::logic_error("TrajectoryReader::joined: a part holds fewer frames than kept");
        if (part.species_ != all.species_)
            throw FileError(where, "holds other bodies (/particles/bodies/species) than " +
                                       first_path + ": not a part of the same run");
        if (keep[k] > 0 && !all.steps_.empty() && part.steps_.front() <= all.steps_.back())
            throw FileError(where, "its first frame, at step " +
                                       std::to_string(part.steps_.front()) +
                                       ", does not follow the earlier part's last, at step " +
                                       std::to_string(all.steps_.back()));
        const auto n = static_cast<std::ptrdiff_t>(keep[k]);
        all.impl_->parts.push_back(
            {std::move(part.impl_->parts.front().file), all.steps_.size(), keep[k]});
        all.steps_.insert(all.steps_.end(), part.steps_.begin(), part.steps_.begin() + n);
        all.times_.insert(all.times_.end(), part.times_.begin(), part.times_.begin() + n);
    }
    return all;
}

TrajectoryReader::FrameSource TrajectoryReader::source_of(std::uint64_t index) const {
    const Impl::Part& part = impl_->part_of(index);
    return {part.file.path(), index - part.first};
}

TrajectoryReader::TrajectoryReader(TrajectoryReader&&) noexcept = default;
TrajectoryReader::~TrajectoryReader() = default;

BodyState TrajectoryReader::frame(std::uint64_t index) const {
    const Impl::Part& part = impl_->part_of(index);
    const h5::File& f = part.file;
    if (index >= frames())
        throw FileError(f.path().string(), "frame " + std::to_string(index) + " of " +
                                               std::to_string(frames()) + " requested");
    index -= part.first;
    const std::vector<std::uint32_t>& species = species_;
    const size_t n = species.size();
    const auto x = read_frame(f, "particles/bodies/position/value", index, n, 3);
    const auto q = read_frame(f, "particles/bodies/orientation/value", index, n, 4);
    const auto v = read_frame(f, "particles/bodies/velocity/value", index, n, 3);
    const auto w = read_frame(f, "particles/bodies/angular_velocity/value", index, n, 3);
    BodyState b;
    for (size_t i = 0; i < n; ++i)
        b.add(species[i], {x[3 * i], x[3 * i + 1], x[3 * i + 2]},
              {q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]},
              {v[3 * i], v[3 * i + 1], v[3 * i + 2]}, {w[3 * i], w[3 * i + 1], w[3 * i + 2]});
    return b;
}

namespace {

// The first `frames` rows of a time-series column of one file, checked.
std::vector<double> part_series(const h5::File& f, std::uint64_t frames,
                                const std::string& column) {
    const std::string group = "observables/" + column;
    if (!h5::exists(f.id(), group))
        throw FileError(f.path().string(), "no time-series column " + column);
    h5::Handle g = h5::open_group(f, f.id(), group);
    std::vector<double> values = h5::read_doubles(f, g.get(), "value");
    const std::string dataset = "/" + group + "/value";
    if (values.size() < frames)
        throw FileError(f.path().string(), dataset + " has " + std::to_string(values.size()) +
                                               " rows for " + std::to_string(frames) + " frames");
    values.resize(frames);
    // Order parameters lie in [0, 1]; every other column but the mean velocities (signed) is a
    // rate, a count, an energy or an overlap: never negative.
    const bool order =
        column.rfind("polar_order_", 0) == 0 || column.rfind("nematic_order_", 0) == 0;
    const bool signed_column = column.rfind("mean_velocity_", 0) == 0;
    const double lo = signed_column ? -std::numeric_limits<double>::infinity() : 0.0;
    const double hi = order ? 1.0 + 1e-9 : std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < values.size(); ++k)
        if (!std::isfinite(values[k]) || values[k] < lo || values[k] > hi)
            throw FileError(f.path().string(), dataset + ", frame " + std::to_string(k) + ": " +
                                                   format_number(values[k]) + "; allowed: " +
                                                   (order           ? "[0, 1]"
                                                    : signed_column ? "finite values"
                                                                    : "finite, >= 0"));
    return values;
}

}  // namespace

std::vector<double> TrajectoryReader::series(const std::string& column) const {
    std::vector<double> all;
    for (const Impl::Part& part : impl_->parts) {
        const std::vector<double> values = part_series(part.file, part.count, column);
        all.insert(all.end(), values.begin(), values.end());
    }
    return all;
}

std::vector<std::string> TrajectoryReader::series_names() const {
    const h5::File& f = impl_->parts.front().file;
    std::vector<std::string> names;
    if (!h5::exists(f.id(), "observables")) return names;
    h5::Handle g = h5::open_group(f, f.id(), "observables");
    H5G_info_t info{};
    if (H5Gget_info(g.get(), &info) < 0) h5::fail(f.path(), "cannot list /observables");
    for (hsize_t i = 0; i < info.nlinks; ++i) {
        const ssize_t length = H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                                  nullptr, 0, H5P_DEFAULT);
        if (length <= 0) continue;
        std::string name(static_cast<std::size_t>(length) + 1, '\0');
        H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                           H5P_DEFAULT);
        name.resize(static_cast<std::size_t>(length));
        names.push_back(name);
    }
    return names;
}

bool TrajectoryReader::has_series(const std::string& column) const {
    for (const Impl::Part& part : impl_->parts)
        if (!h5::exists(part.file.id(), "observables/" + column)) return false;
    return true;
}

}  // namespace rodsea
