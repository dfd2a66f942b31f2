// The files of `rodsea analyze` (layout: docs/analysis.md), written into a staging directory
// that replaces the previous analysis whole.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "rodsea/analysis/analyze_run.hpp"
#include "rodsea/analysis/json_writer.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/hdf5.hpp"

namespace rodsea {

namespace {

namespace fs = std::filesystem;

std::string csv_number(double v) {
    if (std::isnan(v)) return "nan";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// RFC 4180: a field with a comma, quote or newline is quoted, quotes doubled.
std::string csv_quoted(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q(1, '"');
    for (char c : text) {
        q.push_back(c);
        if (c == '"') q.push_back('"');
    }
    q.push_back('"');
    return q;
}

std::string csv_text(const TableResult& t) {
    std::ostringstream out;
    out << "# rodsea " << RODSEA_VERSION << " " << t.name << ": " << t.description << "; units:";
    for (std::size_t c = 0; c < t.columns.size(); ++c)
        out << " " << t.columns[c] << " [" << (t.units[c].empty() ? "1" : t.units[c]) << "]";
    out << "\n";
    for (std::size_t c = 0; c < t.columns.size(); ++c)
        out << (c ? "," : "") << t.columns[c];
    out << "\n";
    for (const auto& row : t.rows) {
        for (std::size_t c = 0; c < row.size(); ++c)
            out << (c ? "," : "") << csv_number(row[c]);
        out << "\n";
    }
    return out.str();
}

void write_hdf5(const RunAnalysis& a, const fs::path& path) {
    replace_file_atomically(path, [&](const fs::path& tmp) {
        h5::File f = h5::File::create(tmp);
        h5::write_attribute(f, f.id(), "creator", std::string("rodsea ") + RODSEA_VERSION);
        h5::write_attribute(f, f.id(), "run", a.run.run_dir.string());
        h5::Handle maps = h5::create_group(f, f.id(), "maps");
        h5::Handle labels = h5::create_group(f, f.id(), "labels");
        for (const ObservableResults& r : a.results) {
            for (const MapResult& m : r.maps) {
                h5::Handle g = h5::create_group(f, maps.get(), m.name);
                h5::write_attribute(f, g.get(), "description", m.description);
                h5::write_attribute(f, g.get(), "observable", r.observable);
                const hsize_t nr = m.r_edges.size() - 1, nt = m.theta_edges.size() - 1;
                h5::write_dataset(f, g.get(), "value", m.values, {nr, nt}, m.unit);
                h5::write_dataset(f, g.get(), "r_edges", m.r_edges, {nr + 1}, "mm");
                h5::write_dataset(f, g.get(), "theta_edges", m.theta_edges, {nt + 1}, "rad");
            }
            for (const LabelResult& l : r.labels) {
                h5::Handle g = h5::create_group(f, labels.get(), l.name);
                h5::write_attribute(f, g.get(), "description", l.description);
                const hsize_t frames = l.times.size(), n = l.bodies.size();
                h5::write_dataset(f, g.get(), "value", l.labels, {frames, n});
                std::vector<std::int32_t> bodies(l.bodies.begin(), l.bodies.end());
                h5::write_dataset(f, g.get(), "body", bodies, {n});
                h5::write_dataset(f, g.get(), "time", l.times, {frames}, "s");
            }
        }
        f.close();
    });
}

void write_estimate(JsonWriter& j, const ScalarResult& s) {
    j.begin_object(s.name)
        .value("value", s.estimate.mean)
        .value("error", s.estimate.error)
        .value("unit", s.unit)
        .value("tau_int_samples", s.estimate.tau_int)
        .value("n_eff", s.estimate.n_eff)
        .value("samples", static_cast<long long>(s.estimate.samples))
        .value("error_method", s.estimate.from_blocks ? "time blocks" : "tau_int")
        .value("short_series", s.estimate.short_series())
        .value("description", s.description)
        .end_object();
}

void write_run_parameters(JsonWriter& j, const PreparedRun& run) {
    const EngineParameters& e = run.plan.engine;
    j.begin_object("parameters")
        .value("box_lx_mm", e.box.lx)
        .value("box_ly_mm", e.box.ly)
        .value("gamma", e.drive.gamma)
        .value("frequency_hz", e.drive.angular_frequency / (2.0 * M_PI))
        .value("gap_mm", e.drive.gap)
        .value("gravity_mm_per_s2", e.drive.gravity)
        .value("noise_epsilon_per_mm", e.noise_epsilon)
        .value("dt_s", e.dt)
        .value("seed", static_cast<long long>(e.seed))
        .value("duration_s", run.plan.control.duration);
    j.begin_array("species");
    for (const SpeciesInfo& s : run.setup.species)
        j.begin_object()
            .value("name", s.name)
            .value("kind", to_string(s.kind))
            .value("length_mm", s.length)
            .value("count", s.count)
            .value("area_fraction", s.area_fraction)
            .end_object();
    j.end_array().end_object();
}

}  // namespace

namespace {

void write_analysis_files(const RunAnalysis& a, const fs::path& out_dir) {
    JsonWriter j;
    j.begin_object()
        .value("creator", std::string("rodsea ") + RODSEA_VERSION)
        .value("units", "lengths mm, times s, angles rad, velocities mm/s");
    j.begin_object("run")
        .value("directory", a.run.run_dir.string())
        .value("trajectory", a.run.trajectory.string())
        .value("frames", static_cast<long long>(a.run.times.size()))
        .value("first_time_s", a.run.times.front())
        .value("last_time_s", a.run.times.back())
        .value("frame_interval_s", a.run.setup.frame_interval)
        .end_object();
    write_run_parameters(j, a.run);
    j.begin_object("steady_state")
        .value("from_s", a.run.window.from)
        .value("first_frame", static_cast<long long>(a.run.window.first_frame))
        .value("frames", static_cast<long long>(a.run.setup.steady_frames))
        .value("method",
               a.run.window.automatic
                   ? "automatic: earliest start maximising n_eff = n/(2 tau_int) of " +
                         (a.run.window.basis.empty() ? std::string("(none)") : a.run.window.basis)
                   : std::string("given: --from"))
        .value("basis_n_eff", a.run.window.n_eff)
        .value("error_bars",
               "per-frame series: sqrt(var * 2 tau_int / n), tau_int by Sokal's "
               "window; window averages (D_r, sigma_f, N_avg): spread of " +
                   std::to_string(a.run.setup.blocks) + " time blocks")
        .end_object();
    j.begin_object("observables");
    for (const ObservableResults& r : a.results) {
        j.begin_object(r.observable)
            .value("frames", static_cast<long long>(r.frames))
            .value("seconds", r.seconds);
        j.begin_object("parameters");
        for (const ParameterValue& p : r.parameters)
            j.begin_object(p.name).value("value", p.value).value("unit", p.unit).end_object();
        j.end_object().begin_object("scalars");
        for (const ScalarResult& s : r.scalars)
            write_estimate(j, s);
        j.end_object().begin_object("tables");
        for (const TableResult& t : r.tables) {
            const fs::path file = out_dir / (t.name + ".csv");
            write_file_atomically(file, csv_text(t));
            j.begin_object(t.name)
                .value("file", file.filename().string())
                .value("description", t.description);
            j.begin_array("columns");
            for (const std::string& c : t.columns)
                j.element(c);
            j.end_array().end_object();
        }
        j.end_object().begin_object("maps");
        for (const MapResult& m : r.maps)
            j.begin_object(m.name)
                .value("file", "analysis.h5")
                .value("dataset", "/maps/" + m.name + "/value")
                .value("description", m.description)
                .end_object();
        for (const LabelResult& l : r.labels)
            j.begin_object(l.name)
                .value("file", "analysis.h5")
                .value("dataset", "/labels/" + l.name + "/value")
                .value("description", l.description)
                .end_object();
        j.end_object().begin_array("notes");
        for (const std::string& n : r.notes)
            j.element(n);
        j.end_array().end_object();
    }
    j.end_object();
    j.begin_array("skipped");
    for (const std::string& s : a.run.skipped)
        j.element(s);
    j.end_array().value("seconds", a.seconds).end_object();
    write_hdf5(a, out_dir / "analysis.h5");
    write_file_atomically(out_dir / "summary.csv", summary_table_csv({a}));
    write_file_atomically(out_dir / "analysis.json", j.str());
}

}  // namespace

void check_analysis_output_directory(const fs::path& out_dir) {
    std::error_code ec;
    if (!fs::exists(out_dir, ec)) return;
    if (!fs::is_directory(out_dir))
        throw FileError(out_dir.string(), "exists and is not a directory");
    if (!fs::is_empty(out_dir) && !fs::exists(out_dir / "analysis.json"))
        throw FileError(out_dir.string(),
                        "exists, is not empty and holds no earlier analysis (analysis.json): "
                        "refusing to replace it; choose another --out");
}

std::vector<fs::path> write_run_analysis(const RunAnalysis& a, const fs::path& out_dir) {
    check_analysis_output_directory(out_dir);
    // The whole set is written into a fresh directory next to the target and swapped in, so a
    // reader never sees a mix of two analyses or files left from an earlier, larger one.
    std::string suffix = ".";  // (not "." + ...: GCC 12 warns falsely, -Werror=restrict)
    suffix += std::to_string(::getpid());
    const fs::path parent = out_dir.has_parent_path() ? out_dir.parent_path() : fs::path(".");
    const fs::path staging = parent / (out_dir.filename().string() + ".tmp" + suffix);
    const fs::path previous = parent / (out_dir.filename().string() + ".old" + suffix);
    std::error_code ec;
    fs::remove_all(staging, ec);
    fs::create_directories(staging, ec);
    if (ec || !fs::is_directory(staging))
        throw FileError(staging.string(), "cannot create the output directory (" +
                                              (ec ? ec.message() : "not a directory") + ")");
    try {
        write_analysis_files(a, staging);
    } catch (...) {
        fs::remove_all(staging, ec);
        throw;
    }
    const bool replacing = fs::exists(out_dir);
    if (replacing) fs::rename(out_dir, previous, ec);
    if (!ec) fs::rename(staging, out_dir, ec);
    if (ec) {
        if (replacing && !fs::exists(out_dir)) fs::rename(previous, out_dir, ec);
        fs::remove_all(staging, ec);
        throw FileError(out_dir.string(), "cannot move the new analysis into place");
    }
    fs::remove_all(previous, ec);
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(out_dir))
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string summary_table_csv(const std::vector<RunAnalysis>& runs) {
    std::vector<std::string> columns{
        "run",          "box_lx_mm",  "box_ly_mm",      "gamma",
        "frequency_hz", "gap_mm",     "epsilon_per_mm", "dt_s",
        "seed",         "duration_s", "steady_from_s",  "steady_frames"};
    std::vector<std::map<std::string, std::string>> rows;
    const auto add = [&](std::map<std::string, std::string>& row, const std::string& key,
                         const std::string& value) {
        if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
        row[key] = value;
    };
    for (const RunAnalysis& a : runs) {
        const EngineParameters& e = a.run.plan.engine;
        std::map<std::string, std::string> row;
        row["run"] = csv_quoted(a.run.run_dir.string());
        row["box_lx_mm"] = csv_number(e.box.lx);
        row["box_ly_mm"] = csv_number(e.box.ly);
        row["gamma"] = csv_number(e.drive.gamma);
        row["frequency_hz"] = csv_number(e.drive.angular_frequency / (2.0 * M_PI));
        row["gap_mm"] = csv_number(e.drive.gap);
        row["epsilon_per_mm"] = csv_number(e.noise_epsilon);
        row["dt_s"] = csv_number(e.dt);
        row["seed"] = std::to_string(e.seed);
        row["duration_s"] = csv_number(a.run.plan.control.duration);
        row["steady_from_s"] = csv_number(a.run.window.from);
        row["steady_frames"] = std::to_string(a.run.setup.steady_frames);
        for (const SpeciesInfo& s : a.run.setup.species) {
            add(row, "phi_" + s.name, csv_number(s.area_fraction));
            add(row, "count_" + s.name, std::to_string(s.count));
            add(row, "length_mm_" + s.name, csv_number(s.length));
        }
        for (const ObservableResults& r : a.results)
            for (const ScalarResult& s : r.scalars) {
                add(row, s.name, csv_number(s.estimate.mean));
                add(row, s.name + "_err", csv_number(s.estimate.error));
            }
        rows.push_back(std::move(row));
    }
    std::ostringstream out;
    out << "# rodsea " << RODSEA_VERSION
        << " analysis summary: one row per run, its parameters (mm, s), then each steady-state "
           "scalar and its error bar (<name>_err); the definitions are in each run's "
           "analysis.json\n";
    for (std::size_t c = 0; c < columns.size(); ++c)
        out << (c ? "," : "") << columns[c];
    out << "\n";
    for (const auto& row : rows) {
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const auto it = row.find(columns[c]);
            out << (c ? "," : "") << (it == row.end() ? "" : it->second);
        }
        out << "\n";
    }
    return out.str();
}

}  // namespace rodsea
