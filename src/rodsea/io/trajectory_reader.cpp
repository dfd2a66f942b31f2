#include "rodsea/io/trajectory_reader.hpp"

#include "rodsea/error.hpp"
#include "rodsea/io/detail/hdf5.hpp"

namespace rodsea {

namespace {

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

struct TrajectoryReader::Impl {
    h5::File file;
};

TrajectoryReader::TrajectoryReader(const std::filesystem::path& path)
    : impl_(new Impl{h5::File::open(path, false)}) {
    const h5::File& f = impl_->file;
    if (!h5::exists(f.id(), "h5md") || !h5::exists(f.id(), "particles/bodies/position"))
        throw FileError(path.string(), "not a rodsea trajectory (no H5MD /particles/bodies)");
    h5::Handle position = h5::open_group(f, f.id(), "particles/bodies/position");
    std::vector<double> steps = h5::read_doubles(f, position.get(), "step");
    steps_.assign(steps.begin(), steps.end());
    times_ = h5::read_doubles(f, position.get(), "time");
}

TrajectoryReader::TrajectoryReader(TrajectoryReader&&) noexcept = default;
TrajectoryReader::~TrajectoryReader() = default;

BodyState TrajectoryReader::frame(std::uint64_t index) const {
    const h5::File& f = impl_->file;
    if (index >= frames())
        throw FileError(f.path().string(), "frame " + std::to_string(index) + " of " +
                                               std::to_string(frames()) + " requested");
    h5::Handle bodies = h5::open_group(f, f.id(), "particles/bodies");
    const std::vector<std::int32_t> species = h5::read_ints(f, bodies.get(), "species");
    const size_t n = species.size();
    const auto x = read_frame(f, "particles/bodies/position/value", index, n, 3);
    const auto q = read_frame(f, "particles/bodies/orientation/value", index, n, 4);
    const auto v = read_frame(f, "particles/bodies/velocity/value", index, n, 3);
    const auto w = read_frame(f, "particles/bodies/angular_velocity/value", index, n, 3);
    BodyState b;
    for (size_t i = 0; i < n; ++i)
        b.add(static_cast<std::uint32_t>(species[i]), {x[3 * i], x[3 * i + 1], x[3 * i + 2]},
              {q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]},
              {v[3 * i], v[3 * i + 1], v[3 * i + 2]}, {w[3 * i], w[3 * i + 1], w[3 * i + 2]});
    return b;
}

std::vector<double> TrajectoryReader::series(const std::string& column) const {
    const h5::File& f = impl_->file;
    const std::string group = "observables/" + column;
    if (!h5::exists(f.id(), group))
        throw FileError(f.path().string(), "no time-series column " + column);
    h5::Handle g = h5::open_group(f, f.id(), group);
    return h5::read_doubles(f, g.get(), "value");
}

bool TrajectoryReader::has_series(const std::string& column) const {
    return h5::exists(impl_->file.id(), "observables/" + column);
}

}  // namespace rodsea
