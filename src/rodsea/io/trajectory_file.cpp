#include "rodsea/io/trajectory_file.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

#include "rodsea/error.hpp"
#include "rodsea/io/detail/hdf5.hpp"

namespace rodsea {

namespace {

constexpr const char* kBodies = "/particles/bodies";

// One H5MD time-dependent element: the value array and its own step and time arrays.
struct Element {
    h5::Handle group;
    h5::GrowingDataset step, time, value;

    static Element create(const h5::File& f, hid_t parent, const std::string& name, hid_t type,
                          const std::vector<hsize_t>& frame_dims, const std::string& unit) {
        Element e;
        e.group = h5::create_group(f, parent, name);
        e.step = h5::GrowingDataset::create(f, e.group.get(), "step", H5T_STD_I64LE, {});
        e.time = h5::GrowingDataset::create(f, e.group.get(), "time", H5T_IEEE_F64LE, {}, "s");
        e.value = h5::GrowingDataset::create(f, e.group.get(), "value", type, frame_dims, unit);
        return e;
    }
    static Element open(const h5::File& f, hid_t parent, const std::string& name,
                        std::uint64_t keep_frames) {
        Element e;
        e.group = h5::open_group(f, parent, name);
        e.step = h5::GrowingDataset::open(f, e.group.get(), "step");
        e.time = h5::GrowingDataset::open(f, e.group.get(), "time");
        e.value = h5::GrowingDataset::open(f, e.group.get(), "value");
        if (e.value.frames() < keep_frames || e.step.frames() < keep_frames ||
            e.time.frames() < keep_frames) {
            throw FileError(f.path().string(),
                            name + " has " + std::to_string(e.value.frames()) +
                                " frames but the checkpoint says " + std::to_string(keep_frames) +
                                " were written (the file was replaced or damaged)");
        }
        e.step.truncate(f, keep_frames);
        e.time.truncate(f, keep_frames);
        e.value.truncate(f, keep_frames);
        return e;
    }
    void abandon() {
        step.abandon();
        time.abandon();
        value.abandon();
        group.release();
    }
    void append(const h5::File& f, std::uint64_t step_number, double t, const void* data,
                hid_t memory_type) {
        const auto s = static_cast<std::int64_t>(step_number);
        // Value first: if it fails (a full disk), step and time do not claim a frame.
        value.append(f, data, memory_type);
        step.append(f, &s, H5T_NATIVE_INT64);
        time.append(f, &t, H5T_NATIVE_DOUBLE);
    }
};

std::string author() {
    const char* user = std::getenv("USER");
    return user != nullptr && *user != '\0' ? user : "unknown";
}

void write_h5md_header(const h5::File& f) {
    h5::Handle h5md = h5::create_group(f, f.id(), "h5md");
    h5::write_attribute(f, h5md.get(), "version", std::vector<std::int32_t>{1, 1});
    h5::Handle who = h5::create_group(f, h5md.get(), "author");
    h5::write_attribute(f, who.get(), "name", author());
    h5::Handle creator = h5::create_group(f, h5md.get(), "creator");
    h5::write_attribute(f, creator.get(), "name", std::string("rodsea"));
    h5::write_attribute(f, creator.get(), "version", std::string(RODSEA_VERSION));
}

// The box as H5MD's time-dependent "edges" element (one row per frame, although it never
// changes): MDAnalysis's H5MD reader takes the box of a frame from box/edges/value[frame].
h5::Handle write_box(const h5::File& f, hid_t bodies) {
    h5::Handle box = h5::create_group(f, bodies, "box");
    h5::write_attribute(f, box.get(), "dimension", std::int32_t{3});
    h5::write_attribute(f, box.get(), "boundary",
                        std::vector<std::string>{"periodic", "periodic", "none"});
    return box;
}

// 128 random bits: two runs never share an id, whatever their configs and seeds.
std::string new_run_id() {
    std::random_device device;
    std::string id;
    char digits[9];
    for (int i = 0; i < 4; ++i) {
        std::snprintf(digits, sizeof digits, "%08x", static_cast<unsigned>(device()));
        id += digits;
    }
    return id;
}

std::string stored_run_id(const h5::File& f) {
    h5::Handle rodsea = h5::open_group(f, f.id(), "/parameters/rodsea");
    return H5Aexists(rodsea.get(), "run_id") > 0
               ? h5::read_string_attribute(f, rodsea.get(), "run_id")
               : std::string();
}

// Absent in a run's first file and in files written before continuations existed.
std::uint64_t stored_first_frame(const h5::File& f) {
    h5::Handle rodsea = h5::open_group(f, f.id(), "/parameters/rodsea");
    if (H5Aexists(rodsea.get(), "first_frame") <= 0) return 0;
    const std::int64_t first = h5::read_int64_attribute(f, rodsea.get(), "first_frame");
    if (first < 0)
        throw FileError(f.path().string(), "/parameters/rodsea first_frame is " +
                                               std::to_string(first) + "; allowed: 0 or more");
    return static_cast<std::uint64_t>(first);
}

void write_species(const h5::File& f, hid_t parent, const EngineParameters& p) {
    h5::Handle all = h5::create_group(f, parent, "species");
    for (size_t s = 0; s < p.species.size(); ++s) {
        const Species& sp = p.species[s];
        h5::Handle g = h5::create_group(f, all.get(), std::to_string(s));
        h5::write_attribute(f, g.get(), "name", sp.name);
        h5::write_attribute(f, g.get(), "kind", std::string(to_string(sp.kind)));
        const size_t n = sp.shape.sphere_count();
        std::vector<double> offsets;
        for (const Vec3& o : sp.shape.offsets)
            offsets.insert(offsets.end(), {o.x, o.y, o.z});
        h5::write_dataset(f, g.get(), "sphere_offsets", offsets, {n, 3}, "mm");
        h5::write_dataset(f, g.get(), "sphere_radii", sp.shape.radii, {n}, "mm");
        h5::write_dataset(f, g.get(), "mass", std::vector<double>{sp.shape.mass}, {1}, "mass unit");
        const Vec3& I = sp.shape.principal_inertia;
        h5::write_dataset(f, g.get(), "principal_inertia", std::vector<double>{I.x, I.y, I.z}, {3},
                          "mass unit mm2");
        h5::write_dataset(f, g.get(), "projected_area",
                          std::vector<double>{sp.shape.projected_area}, {1}, "mm2");
        h5::write_dataset(f, g.get(), "plate_coefficients",
                          std::vector<double>{sp.plate.friction, sp.plate.restitution}, {2});
    }
}

}  // namespace

struct TrajectoryFile::Impl {
    explicit Impl(h5::File opened) : file(std::move(opened)) {}
    h5::File file;
    Element position, orientation, velocity, spin;
    Element edges;                      // z is bounded by the plates, not periodic: its edge is w
    std::array<double, 3> box_edges{};  // L_x, L_y, w (mm)
    std::vector<Element> series;
    std::vector<float> scratch;
    std::uint64_t complete_frames = 0;
    std::string run_id;
    std::uint64_t first_frame = 0;
    std::uint64_t reserved_end = 0;  // the file offset up to which reserve() claimed blocks
};

TrajectoryFile::TrajectoryFile(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TrajectoryFile::TrajectoryFile(TrajectoryFile&&) noexcept = default;
TrajectoryFile& TrajectoryFile::operator=(TrajectoryFile&&) noexcept = default;
TrajectoryFile::~TrajectoryFile() = default;

TrajectoryFile TrajectoryFile::create(const std::filesystem::path& path,
                                      const EngineParameters& params,
                                      const std::vector<std::uint32_t>& species,
                                      const std::string& config_toml,
                                      const std::vector<SeriesColumn>& columns,
                                      const std::optional<TrajectorySegment>& segment) {
    auto impl = std::unique_ptr<Impl>(new Impl(h5::File::create(path)));
    const h5::File& f = impl->file;
    write_h5md_header(f);
    h5::Handle particles = h5::create_group(f, f.id(), "particles");
    h5::Handle bodies = h5::create_group(f, particles.get(), "bodies");
    {
        h5::Handle box = write_box(f, bodies.get());
        impl->edges = Element::create(f, box.get(), "edges", H5T_IEEE_F64LE, {3}, "mm");
        impl->box_edges = {params.box.lx, params.box.ly, params.drive.gap};
    }
    const hsize_t n = species.size();
    impl->position = Element::create(f, bodies.get(), "position", H5T_IEEE_F32LE, {n, 3}, "mm");
    impl->orientation =
        Element::create(f, bodies.get(), "orientation", H5T_IEEE_F32LE, {n, 4}, "1");
    h5::write_attribute(f, impl->orientation.group.get(), "convention",
                        std::string("unit quaternion (w, x, y, z) rotating the body's principal "
                                    "frame into the lab frame; body x is the rod axis, thick to "
                                    "thin end for polar rods"));
    impl->velocity = Element::create(f, bodies.get(), "velocity", H5T_IEEE_F32LE, {n, 3}, "mm s-1");
    impl->spin =
        Element::create(f, bodies.get(), "angular_velocity", H5T_IEEE_F32LE, {n, 3}, "rad s-1");
    std::vector<std::int32_t> ids(species.begin(), species.end());
    h5::write_dataset(f, bodies.get(), "species", ids, {n});

    h5::Handle observables = h5::create_group(f, f.id(), "observables");
    for (const SeriesColumn& c : columns)
        impl->series.push_back(
            Element::create(f, observables.get(), c.name, H5T_IEEE_F64LE, {}, c.unit));

    h5::Handle parameters = h5::create_group(f, f.id(), "parameters");
    h5::Handle rodsea = h5::create_group(f, parameters.get(), "rodsea");
    h5::write_attribute(f, rodsea.get(), "version", std::string(RODSEA_VERSION));
    impl->run_id = segment ? segment->run_id : new_run_id();
    h5::write_attribute(f, rodsea.get(), "run_id", impl->run_id);
    if (segment && segment->first_frame > 0) {
        impl->first_frame = segment->first_frame;
        h5::write_attribute(f, rodsea.get(), "first_frame",
                            static_cast<std::int64_t>(segment->first_frame));
    }
    h5::write_attribute(f, rodsea.get(), "units",
                        std::string("lengths mm, time s, velocities mm/s, angular velocities "
                                    "rad/s, masses in the config's arbitrary unit"));
    h5::write_string_dataset(f, rodsea.get(), "config", config_toml);
    write_species(f, rodsea.get(), params);
    f.flush();
    return TrajectoryFile(std::move(impl));
}

TrajectoryFile TrajectoryFile::reopen(const std::filesystem::path& path, std::uint64_t frames,
                                      const EngineParameters& params,
                                      const std::vector<SeriesColumn>& columns) {
    auto impl = std::unique_ptr<Impl>(new Impl(h5::File::open(path, true)));
    const h5::File& f = impl->file;
    h5::Handle bodies = h5::open_group(f, f.id(), kBodies);
    impl->position = Element::open(f, bodies.get(), "position", frames);
    impl->orientation = Element::open(f, bodies.get(), "orientation", frames);
    impl->velocity = Element::open(f, bodies.get(), "velocity", frames);
    impl->spin = Element::open(f, bodies.get(), "angular_velocity", frames);
    {
        h5::Handle box = h5::open_group(f, bodies.get(), "box");
        impl->edges = Element::open(f, box.get(), "edges", frames);
        impl->box_edges = {params.box.lx, params.box.ly, params.drive.gap};
    }
    h5::Handle observables = h5::open_group(f, f.id(), "observables");
    for (const SeriesColumn& c : columns)
        impl->series.push_back(Element::open(f, observables.get(), c.name, frames));
    impl->complete_frames = frames;
    impl->run_id = stored_run_id(f);
    impl->first_frame = stored_first_frame(f);
    f.flush();
    return TrajectoryFile(std::move(impl));
}

void TrajectoryFile::replace_config(const std::string& config_toml) {
    const h5::File& f = impl_->file;
    h5::Handle rodsea = h5::open_group(f, f.id(), "parameters/rodsea");
    h5::replace_string_dataset(f, rodsea.get(), "config", config_toml);
    f.flush();
}

void TrajectoryFile::append_frame(std::uint64_t step, double time, const BodyState& bodies,
                                  const std::vector<double>& series_row) {
    Impl& m = *impl_;
    if (series_row.size() != m.series.size())
        throw std::logic_error("time-series row has the wrong number of columns");
    const size_t n = bodies.size();
    const auto put3 = [&](const std::vector<Vec3>& v, Element& e) {
        m.scratch.resize(3 * n);
        for (size_t i = 0; i < n; ++i) {
            m.scratch[3 * i] = static_cast<float>(v[i].x);
            m.scratch[3 * i + 1] = static_cast<float>(v[i].y);
            m.scratch[3 * i + 2] = static_cast<float>(v[i].z);
        }
        e.append(m.file, step, time, m.scratch.data(), H5T_NATIVE_FLOAT);
    };
    put3(bodies.position, m.position);
    m.scratch.resize(4 * n);
    for (size_t i = 0; i < n; ++i) {
        const Quat& q = bodies.orientation[i];
        m.scratch[4 * i] = static_cast<float>(q.w);
        m.scratch[4 * i + 1] = static_cast<float>(q.x);
        m.scratch[4 * i + 2] = static_cast<float>(q.y);
        m.scratch[4 * i + 3] = static_cast<float>(q.z);
    }
    m.orientation.append(m.file, step, time, m.scratch.data(), H5T_NATIVE_FLOAT);
    put3(bodies.velocity, m.velocity);
    put3(bodies.spin, m.spin);
    m.edges.append(m.file, step, time, m.box_edges.data(), H5T_NATIVE_DOUBLE);
    for (size_t c = 0; c < series_row.size(); ++c)
        m.series[c].append(m.file, step, time, &series_row[c], H5T_NATIVE_DOUBLE);
    ++m.complete_frames;
}

std::uint64_t TrajectoryFile::frames() const {
    return impl_->complete_frames;
}

std::uint64_t TrajectoryFile::first_frame() const {
    return impl_->first_frame;
}

const std::string& TrajectoryFile::run_id() const {
    return impl_->run_id;
}

void TrajectoryFile::reserve(std::uint64_t bytes) {
    const std::filesystem::path& path = impl_->file.path();
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw FileError(path.string(), "cannot read its size: " + ec.message());
    const auto no_room = [&](const std::string& why) {
        throw FileError(path.string(),
                        "no room for the next frame (" + std::to_string(bytes) + " bytes): " + why);
    };
    // A batch system's file-size limit (ulimit -f) is checked here, not found by a failed write.
    rlimit limit{};
    if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
        size + bytes > limit.rlim_cur)
        no_room("the file-size limit is " + std::to_string(limit.rlim_cur) + " bytes");
    // Disk blocks (and quota) are claimed without changing the file's size, which HDF5 owns.
    const int fd = ::open(path.c_str(), O_WRONLY);
    if (fd < 0) throw FileError(path.string(), std::string("cannot open: ") + std::strerror(errno));
    const int status =
        ::fallocate(fd, FALLOC_FL_KEEP_SIZE, static_cast<off_t>(size), static_cast<off_t>(bytes));
    const int error = errno;
    ::close(fd);
    if (status == 0) {
        impl_->reserved_end = size + bytes;
        return;
    }
    if (error != EOPNOTSUPP && error != ENOSYS) no_room(std::strerror(error));
    // File systems without fallocate: the free space must at least be there.
    struct statvfs fs {};
    if (::statvfs(path.parent_path().c_str(), &fs) == 0 &&
        static_cast<std::uint64_t>(fs.f_bavail) * fs.f_frsize < bytes)
        no_room(std::strerror(ENOSPC));
}

void TrajectoryFile::release_reserve() noexcept {
    const std::filesystem::path& path = impl_->file.path();
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || impl_->reserved_end <= size) return;
    // Blocks beyond the end hold nothing: HDF5 wrote none of them (they lie past its size).
    const int fd = ::open(path.c_str(), O_WRONLY);
    if (fd < 0) return;
    if (::fallocate(fd, FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE, static_cast<off_t>(size),
                    static_cast<off_t>(impl_->reserved_end - size)) != 0)
        (void)::ftruncate(fd, static_cast<off_t>(size));  // file systems without hole punching
    ::close(fd);
    impl_->reserved_end = 0;
}

void TrajectoryFile::flush() {
    impl_->file.flush();
}

void TrajectoryFile::close() {
    if (!impl_) return;
    Impl& m = *impl_;
    // Every dataset must be closed before the file, or HDF5 keeps the file open.
    for (Element* e : {&m.position, &m.orientation, &m.velocity, &m.spin})
        *e = Element{};
    m.series.clear();
    m.file.close();
}

void TrajectoryFile::abandon() {
    if (!impl_) return;
    Impl& m = *impl_;
    for (Element* e : {&m.position, &m.orientation, &m.velocity, &m.spin})
        e->abandon();
    for (Element& e : m.series)
        e.abandon();
    m.file.abandon();
}

std::string read_stored_config(const std::filesystem::path& path) {
    const h5::File f = h5::File::open(path, false);
    h5::Handle rodsea = h5::open_group(f, f.id(), "/parameters/rodsea");
    return h5::read_string_dataset(f, rodsea.get(), "config");
}

std::string read_run_id(const std::filesystem::path& path) {
    return stored_run_id(h5::File::open(path, false));
}

std::uint64_t read_first_frame(const std::filesystem::path& path) {
    return stored_first_frame(h5::File::open(path, false));
}

}  // namespace rodsea
