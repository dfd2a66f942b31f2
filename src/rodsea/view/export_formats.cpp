#include "rodsea/view/detail/export_formats.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <ostream>

#include "rodsea/error.hpp"

namespace rodsea {

namespace {

// Decimals written. Positions: 1e-6 mm, below the float32 precision of the stored frames
// (6e-8 relative: 1.5e-5 mm in a 250 mm box), so the file adds no error of its own.
// Quaternions: 1e-9, likewise below float32. Velocities: 1e-6 mm/s.
constexpr int kLengthDecimals = 6;
constexpr int kQuaternionDecimals = 9;
constexpr int kVelocityDecimals = 6;
// Lines are gathered and handed to the stream in blocks of about this many bytes.
constexpr std::size_t kBlockBytes = 1 << 20;

// Appends numbers and words to a text block with std::to_chars (no locale, no allocation per
// number): a 10⁶-sphere frame has 10⁷ numbers.
class TextBlock {
  public:
    explicit TextBlock(std::ostream* out) : out_(out) { text_.reserve(kBlockBytes + 4096); }

    void word(std::string_view w) { text_.append(w); }
    void sep() { text_.push_back(' '); }
    void end_line() {
        text_.push_back('\n');
        if (out_ && text_.size() >= kBlockBytes) flush();
    }
    void integer(long long v) {
        std::array<char, 32> buf{};
        const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
        text_.append(buf.data(), r.ptr);
    }
    void fixed(double v, int decimals) {
        std::array<char, 64> buf{};
        const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v,
                                     std::chars_format::fixed, decimals);
        text_.append(buf.data(), r.ptr);
    }
    // The shortest text that reads back as the same double: for box sizes and times.
    void exact(double v) {
        std::array<char, 64> buf{};
        const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
        text_.append(buf.data(), r.ptr);
    }
    void flush() {
        if (out_) out_->write(text_.data(), static_cast<std::streamsize>(text_.size()));
        text_.clear();
    }
    std::size_t size() const { return text_.size(); }

  private:
    std::ostream* out_;
    std::string text_;
};

void header(TextBlock& t, const ExportScene& scene, const ExportOptions& options,
            std::size_t spheres, std::int64_t step, double time) {
    if (options.format == ExportFormat::lammps_dump) {
        // Exactly nine lines, as LAMMPS writes them: MDAnalysis counts lines per frame.
        t.word("ITEM: TIMESTEP\n");
        t.integer(step);
        t.word("\nITEM: NUMBER OF ATOMS\n");
        t.integer(static_cast<long long>(spheres));
        t.word("\nITEM: BOX BOUNDS pp pp ff\n0 ");
        t.exact(scene.lx);
        t.word("\n0 ");
        t.exact(scene.ly);
        t.end_line();
        t.exact(scene.z_lo);
        t.sep();
        t.exact(scene.z_hi);
        t.word("\nITEM: ATOMS id mol type x y z radius quatw quati quatj quatk");
        if (options.velocities) t.word(" vx vy vz");
        t.end_line();
    } else {
        // Extended XYZ as OVITO and ASE read it; plain readers use the first four columns.
        t.integer(static_cast<long long>(spheres));
        t.word("\nLattice=\"");
        t.exact(scene.lx);
        t.word(" 0 0 0 ");
        t.exact(scene.ly);
        t.word(" 0 0 0 ");
        t.exact(scene.z_hi - scene.z_lo);
        t.word("\" Origin=\"0 0 ");
        t.exact(scene.z_lo);
        t.word(
            "\" Properties=species:S:1:pos:R:3:radius:R:1:molecule:I:1:"
            "orientation:R:4");
        if (options.velocities) t.word(":velo:R:3");
        t.word(" Time=");
        t.exact(time);
        t.word(" Step=");
        t.integer(step);
        t.word(" pbc=\"T T F\" units=mm");
        t.end_line();
    }
}

void sphere_line(TextBlock& t, const ExportOptions& options, long long id, long long body,
                 std::size_t species, const std::string& species_name, const Vec3& p, double radius,
                 const Quat& q, const Vec3& v) {
    if (options.format == ExportFormat::lammps_dump) {
        t.integer(id);
        t.sep();
        t.integer(body);
        t.sep();
        t.integer(static_cast<long long>(species) + 1);
        t.sep();
    } else {
        t.word(species_name);
        t.sep();
    }
    t.fixed(p.x, kLengthDecimals);
    t.sep();
    t.fixed(p.y, kLengthDecimals);
    t.sep();
    t.fixed(p.z, kLengthDecimals);
    t.sep();
    t.fixed(radius, kLengthDecimals);
    t.sep();
    if (options.format == ExportFormat::lammps_dump) {
        // quatw quati quatj quatk: LAMMPS's order, scalar part first.
        t.fixed(q.w, kQuaternionDecimals);
        t.sep();
    } else {
        t.integer(body);
        t.sep();
    }
    t.fixed(q.x, kQuaternionDecimals);
    t.sep();
    t.fixed(q.y, kQuaternionDecimals);
    t.sep();
    t.fixed(q.z, kQuaternionDecimals);
    if (options.format == ExportFormat::xyz) {
        // OVITO's Orientation property is (X, Y, Z, W): scalar part last.
        t.sep();
        t.fixed(q.w, kQuaternionDecimals);
    }
    if (options.velocities) {
        t.sep();
        t.fixed(v.x, kVelocityDecimals);
        t.sep();
        t.fixed(v.y, kVelocityDecimals);
        t.sep();
        t.fixed(v.z, kVelocityDecimals);
    }
    t.end_line();
}

}  // namespace

const std::vector<std::string>& export_format_names() {
    static const std::vector<std::string> names{"lammps-dump", "xyz", "gsd"};
    return names;
}

const char* to_string(ExportFormat format) {
    switch (format) {
        case ExportFormat::lammps_dump:
            return "lammps-dump";
        case ExportFormat::xyz:
            return "xyz";
        case ExportFormat::gsd:
            return "gsd";
    }
    return "";
}

std::optional<ExportFormat> parse_export_format(std::string_view name) {
    if (name == "lammps-dump") return ExportFormat::lammps_dump;
    if (name == "xyz") return ExportFormat::xyz;
    if (name == "gsd") return ExportFormat::gsd;
    return std::nullopt;
}

ExportScene make_export_scene(const RunPlan& plan) {
    const EngineParameters& e = plan.engine;
    ExportScene scene;
    scene.lx = e.box.lx;
    scene.ly = e.box.ly;
    // The base moves between −A and +A, the lid between w − A and w + A: every sphere of a
    // body between them lies inside [−A, w + A].
    const double a = e.drive.amplitude();
    scene.z_lo = -a;
    scene.z_hi = e.drive.gap + a;
    scene.dt = e.dt;
    for (const Species& s : e.species)
        scene.species.push_back({s.name, s.shape.offsets, s.shape.radii});
    return scene;
}

std::size_t export_sphere_count(const ExportScene& scene, const BodyState& bodies,
                                const std::string& source) {
    std::size_t n = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const std::uint32_t s = bodies.species[b];
        if (s >= scene.species.size()) {
            // Appended: GCC 12 at -O3 warns falsely (-Wrestrict) on "literal" + std::string.
            std::string what("body ");
            what.append(std::to_string(b + 1))
                .append(" has species index ")
                .append(std::to_string(s))
                .append(", but the config has ")
                .append(std::to_string(scene.species.size()))
                .append(" species");
            throw FileError(source, what);
        }
        n += scene.species[s].radii.size();
    }
    return n;
}

Vec3 export_sphere_position(const Vec3& centre, const Quat& q, const Vec3& offset) {
    return centre + rotate(q, offset);
}

void write_export_frame(std::ostream& out, const ExportScene& scene, const ExportOptions& options,
                        const BodyState& bodies, std::int64_t step, double time) {
    TextBlock t(&out);
    header(t, scene, options, export_sphere_count(scene, bodies, "frame"), step, time);
    long long id = 0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const ExportScene::Species& s = scene.species[bodies.species[b]];
        // Stored in single precision: normalise so that the quaternion written is the exact
        // rotation that carried the offsets onto the spheres written.
        const Quat q = normalized(bodies.orientation[b]);
        const Vec3& v = bodies.velocity[b];
        for (std::size_t k = 0; k < s.radii.size(); ++k)
            sphere_line(t, options, ++id, static_cast<long long>(b) + 1, bodies.species[b], s.name,
                        export_sphere_position(bodies.position[b], q, s.offsets[k]), s.radii[k], q,
                        v);
    }
    t.flush();
}

double estimated_frame_bytes(const ExportScene& scene, const ExportOptions& options,
                             std::size_t spheres, std::size_t bodies) {
    // GSD: float32 position, orientation, velocity and a type id per body, and the index.
    if (options.format == ExportFormat::gsd)
        return static_cast<double>(bodies) * (3 + 4 + 3 + 1) * 4.0 + 4096.0;
    // One line of typical width: a sphere mid-box with a generic orientation and a velocity
    // of tens of mm/s, ids of the frame's median size.
    TextBlock t(nullptr);
    header(t, scene, options, spheres, 1000000, 1.0);
    const double header_bytes = static_cast<double>(t.size());
    TextBlock line(nullptr);
    const std::size_t species = scene.species.empty() ? 0 : scene.species.size() - 1;
    const std::string name = scene.species.empty() ? "x" : scene.species[species].name;
    sphere_line(line, options, static_cast<long long>(spheres / 2 + 1),
                static_cast<long long>(bodies / 2 + 1), species, name,
                {0.5 * scene.lx, 0.5 * scene.ly, 0.5 * (scene.z_lo + scene.z_hi)}, 0.5,
                {0.5, -0.5, 0.5, -0.5}, {-12.5, 12.5, -1.25});
    return header_bytes + static_cast<double>(spheres) * static_cast<double>(line.size());
}

}  // namespace rodsea
