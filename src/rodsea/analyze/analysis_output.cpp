// The files of `rodsea analyze` (layout: docs/analysis.md), written into a staging directory
// that replaces the previous analysis whole.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/analysis_h5.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/csv_table.hpp"
#include "rodsea/number_text.hpp"
#include "rodsea/text_file.hpp"

namespace rodsea {

namespace {

namespace fs = std::filesystem;

// In key order, as the analysis is read by people too. JSON has no NaN: nlohmann writes null.
using Json = nlohmann::ordered_json;

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
            out << (c ? "," : "") << exact_number(row[c]);
        out << "\n";
    }
    return out.str();
}

void write_hdf5(const RunAnalysis& a, const fs::path& path) {
    std::vector<AnalysisArrays> arrays;
    for (const ObservableResults& r : a.results)
        arrays.push_back({r.observable, r.maps, r.labels, r.datasets});
    write_analysis_h5(path, a.run.run_dir.string(), arrays);
}

Json estimate_json(const ScalarResult& s) {
    return {{"value", s.estimate.mean},
            {"error", s.estimate.error},
            {"unit", s.unit},
            {"tau_int_samples", s.estimate.tau_int},
            {"n_eff", s.estimate.n_eff},
            {"samples", s.estimate.samples},
            {"error_method", s.estimate.from_blocks ? "time blocks" : "tau_int"},
            {"short_series", s.estimate.short_series()},
            {"description", s.description}};
}

Json run_parameters_json(const PreparedRun& run) {
    const EngineParameters& e = run.plan.engine;
    Json species = Json::array();
    for (const SpeciesInfo& s : run.setup.species)
        species.push_back({{"name", s.name},
                           {"kind", to_string(s.kind)},
                           {"length_mm", s.length},
                           {"count", s.count},
                           {"area_fraction", s.area_fraction}});
    return {{"box_lx_mm", e.box.lx},
            {"box_ly_mm", e.box.ly},
            {"gamma", e.drive.gamma},
            {"frequency_hz", e.drive.angular_frequency / (2.0 * M_PI)},
            {"gap_mm", e.drive.gap},
            {"gravity_mm_per_s2", e.drive.gravity},
            {"noise_epsilon_per_mm", e.noise_epsilon},
            {"dt_s", e.dt},
            {"seed", e.seed},
            {"duration_s", run.plan.control.duration},
            {"species", species}};
}

Json observable_json(const ObservableResults& r, const fs::path& out_dir) {
    Json parameters = Json::object(), scalars = Json::object(), tables = Json::object(),
         maps = Json::object();
    for (const ParameterValue& p : r.parameters)
        parameters[p.name] = {{"value", p.value}, {"unit", p.unit}};
    for (const ScalarResult& s : r.scalars)
        scalars[s.name] = estimate_json(s);
    for (const TableResult& t : r.tables) {
        const fs::path file = out_dir / (t.name + ".csv");
        write_file_atomically(file, csv_text(t));
        tables[t.name] = {{"file", file.filename().string()},
                          {"description", t.description},
                          {"columns", t.columns}};
    }
    for (const MapResult& m : r.maps)
        maps[m.name] = {{"file", "analysis.h5"},
                        {"dataset", "/maps/" + m.name + "/value"},
                        {"description", m.description}};
    for (const LabelResult& l : r.labels)
        maps[l.name] = {{"file", "analysis.h5"},
                        {"dataset", "/labels/" + l.name + "/value"},
                        {"description", l.description}};
    for (const DatasetResult& d : r.datasets)
        maps[d.path] = {{"file", "analysis.h5"},
                        {"dataset", "/" + d.path},
                        {"shape", d.dims},
                        {"unit", d.unit},
                        {"description", d.description}};
    return {{"frames", r.frames}, {"seconds", r.seconds}, {"parameters", parameters},
            {"scalars", scalars}, {"tables", tables},     {"maps", maps},
            {"notes", r.notes}};
}

// Each order series' own steady start, its independent samples in the window and whether it
// drifts there.
// The trajectories a run was read from: one, or a run's directories joined in order.
Json part_paths(const std::vector<std::filesystem::path>& parts) {
    Json paths = Json::array();
    for (const std::filesystem::path& p : parts)
        paths.push_back(p.string());
    return paths;
}

Json window_series_json(const PreparedRun& run) {
    Json series = Json::array();
    for (const SeriesStart& s : run.window.series)
        series.push_back({{"name", s.name},
                          {"steady_from_s", run.times[s.start]},
                          {"n_eff", s.n_eff},
                          {"drifting", s.drifting}});
    return series;
}

void write_analysis_files(const RunAnalysis& a, const fs::path& out_dir) {
    const SteadyWindow& w = a.run.window;
    Json observables = Json::object();
    for (const ObservableResults& r : a.results)
        observables[r.observable] = observable_json(r, out_dir);
    const Json j = {
        {"creator", std::string("rodsea ") + RODSEA_VERSION},
        {"units", "lengths mm, times s, angles rad, velocities mm/s"},
        {"run",
         {{"directory", a.run.run_dir.string()},
          {"trajectory", a.run.trajectory.string()},
          {"parts", part_paths(a.run.parts)},
          {"frames", a.run.stored_frames},
          {"first_time_s", a.run.times.front()},
          {"last_time_s", a.run.stored_last_time},
          {"frame_interval_s", a.run.setup.frame_interval},
          {"still_running", a.run.still_running}}},
        {"parameters", run_parameters_json(a.run)},
        {"steady_state",
         {{"from_s", w.from},
          {"first_frame", w.first_frame},
          {"frames", a.run.setup.steady_frames},
          {"to_s", a.run.times.back()},
          {"end", w.to_given ? "given: --to (the frames after it are not analysed)"
                             : "the run's last frame"},
          {"method", w.automatic
                         ? "automatic: the latest of the order series' steady starts (each the "
                           "earliest start maximising n_eff = n/(2 tau_int)), decided by " +
                               (w.basis.empty() ? std::string("(none)") : w.basis)
                         : std::string("given: --from")},
          {"decided_by", w.basis},
          {"series", window_series_json(a.run)},
          {"error_bars",
           "per-frame series: sqrt(var * 2 tau_int / n), tau_int by Sokal's "
           "window; window averages (D_r, sigma_f, N_avg): spread of " +
               std::to_string(a.run.setup.blocks) + " time blocks"}}},
        {"observables", observables},
        {"skipped", a.run.skipped},
        {"seconds", a.seconds},
        {"cache_key", a.run.cache_key}};
    write_hdf5(a, out_dir / "analysis.h5");
    write_file_atomically(out_dir / "summary.csv", summary_table_csv({a}));
    // Paths are bytes: one that is not UTF-8 is written with replacement characters.
    write_file_atomically(out_dir / "analysis.json",
                          j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
}

}  // namespace

std::optional<RunAnalysis> reuse_run_analysis(const PreparedRun& run, const fs::path& out_dir) {
    if (run.cache_key.empty()) return std::nullopt;
    std::string text;
    try {
        text = read_text_file(out_dir / "analysis.json");
    } catch (const FileError&) {
        return std::nullopt;
    }
    const Json j = Json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("cache_key") ||
        !j["cache_key"].is_string() || j["cache_key"].get<std::string>() != run.cache_key)
        return std::nullopt;
    // JSON has no NaN: nlohmann wrote it as null. Anything else is not what write_run_analysis
    // wrote: the run is analysed again.
    const auto number = [](const Json& v) {
        if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
        if (!v.is_number()) throw std::invalid_argument("not a number");
        return v.get<double>();
    };
    RunAnalysis a;
    a.run = run;
    try {
        for (const std::string& name : run.observables) {
            const Json& o = j.at("observables").at(name);
            ObservableResults r;
            r.observable = name;
            r.frames = o.value("frames", std::size_t{0});
            for (const auto& [key, s] : o.at("scalars").items()) {
                ScalarResult result{key, s.value("unit", ""), s.value("description", ""), {}};
                Estimate& e = result.estimate;
                e.mean = number(s.at("value"));
                e.error = number(s.at("error"));
                e.tau_int = number(s.at("tau_int_samples"));
                e.n_eff = number(s.at("n_eff"));
                e.samples = s.at("samples").get<std::size_t>();
                e.from_blocks = s.at("error_method").get<std::string>() == "time blocks";
                r.scalars.push_back(std::move(result));
            }
            a.results.push_back(std::move(r));
        }
    } catch (const Json::exception&) {
        return std::nullopt;  // not what write_run_analysis writes: analyse again
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
    a.seconds =
        j.contains("seconds") && j["seconds"].is_number() ? j["seconds"].get<double>() : 0.0;
    return a;
}

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

namespace {

// The parameters of a run, shared by its replicates but for the seed and the window.
CsvTable::Row parameter_row(CsvTable& table, const RunAnalysis& a) {
    const EngineParameters& e = a.run.plan.engine;
    CsvTable::Row row;
    table.set(row, "box_lx_mm", exact_number(e.box.lx));
    table.set(row, "box_ly_mm", exact_number(e.box.ly));
    table.set(row, "gamma", exact_number(e.drive.gamma));
    table.set(row, "frequency_hz", exact_number(e.drive.angular_frequency / (2.0 * M_PI)));
    table.set(row, "gap_mm", exact_number(e.drive.gap));
    table.set(row, "epsilon_per_mm", exact_number(e.noise_epsilon));
    table.set(row, "dt_s", exact_number(e.dt));
    table.set(row, "duration_s", exact_number(a.run.plan.control.duration));
    for (const SpeciesInfo& s : a.run.setup.species) {
        table.set(row, "phi_" + s.name, exact_number(s.area_fraction));
        table.set(row, "count_" + s.name, std::to_string(s.count));
        table.set(row, "length_mm_" + s.name, exact_number(s.length));
    }
    return row;
}

// Groups of at least two runs whose configs differ only in the seed, in order of first run. A
// run with the seed of an earlier one in its group is that run's trajectory again, not a
// replicate: it is left out (same_seed_runs names it).
std::vector<std::vector<const RunAnalysis*>> replicate_groups(
    const std::vector<RunAnalysis>& runs) {
    std::vector<std::string> keys;
    std::vector<std::vector<const RunAnalysis*>> groups;
    for (const RunAnalysis& a : runs) {
        const std::string key = config_without_seed(a.run.plan.config_toml);
        const auto at = std::find(keys.begin(), keys.end(), key);
        if (at == keys.end()) {
            keys.push_back(key);
            groups.push_back({&a});
            continue;
        }
        std::vector<const RunAnalysis*>& group =
            groups[static_cast<std::size_t>(at - keys.begin())];
        const bool seen = std::any_of(group.begin(), group.end(), [&](const RunAnalysis* b) {
            return b->run.plan.engine.seed == a.run.plan.engine.seed;
        });
        if (!seen) group.push_back(&a);
    }
    std::erase_if(groups, [](const auto& g) { return g.size() < 2; });
    return groups;
}

}  // namespace

std::vector<std::pair<std::filesystem::path, std::filesystem::path>> same_seed_runs(
    const std::vector<RunAnalysis>& runs) {
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> pairs;
    for (std::size_t i = 0; i < runs.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
            const RunPlan& a = runs[i].run.plan;
            const RunPlan& b = runs[j].run.plan;
            if (a.engine.seed == b.engine.seed &&
                config_without_seed(a.config_toml) == config_without_seed(b.config_toml)) {
                pairs.emplace_back(runs[i].run.run_dir, runs[j].run.run_dir);
                break;
            }
        }
    return pairs;
}

ReplicateSummary summarise_replicates(const std::vector<const RunAnalysis*>& group) {
    ReplicateSummary g;
    for (const RunAnalysis* a : group) {
        g.runs.push_back(a->run.run_dir);
        g.seeds.push_back(a->run.plan.engine.seed);
    }
    if (group.empty()) return g;
    // The scalars of the first run, combined over every run that has them.
    for (const ObservableResults& r : group.front()->results) {
        for (const ScalarResult& s : r.scalars) {
            std::vector<double> values, errors, error_dof;
            for (const RunAnalysis* a : group)
                for (const ObservableResults& ra : a->results)
                    for (const ScalarResult& sa : ra.scalars)
                        if (ra.observable == r.observable && sa.name == s.name) {
                            values.push_back(sa.estimate.mean);
                            errors.push_back(sa.estimate.error);
                            // A run's error rests on its n_eff independent samples (or blocks).
                            error_dof.push_back(std::max(sa.estimate.n_eff - 1.0, 1.0));
                        }
            g.scalars.push_back({s.name, s.unit, combine_replicates(values, errors, error_dof)});
        }
    }
    return g;
}

std::vector<ReplicateSummary> replicate_summaries(const std::vector<RunAnalysis>& runs) {
    std::vector<ReplicateSummary> summaries;
    for (const auto& group : replicate_groups(runs))
        summaries.push_back(summarise_replicates(group));
    return summaries;
}

std::string summary_table_csv(const std::vector<RunAnalysis>& runs) {
    CsvTable table({"run", "replicates", "box_lx_mm", "box_ly_mm", "gamma", "frequency_hz",
                    "gap_mm", "epsilon_per_mm", "dt_s", "seed", "duration_s", "steady_from_s",
                    "steady_to_s", "steady_frames"});
    for (const RunAnalysis& a : runs) {
        CsvTable::Row row = parameter_row(table, a);
        table.set(row, "run", csv_quoted(a.run.run_dir.string()));
        table.set(row, "seed", std::to_string(a.run.plan.engine.seed));
        table.set(row, "steady_from_s", exact_number(a.run.window.from));
        table.set(row, "steady_to_s", exact_number(a.run.times.back()));
        table.set(row, "steady_frames", std::to_string(a.run.setup.steady_frames));
        for (const ObservableResults& r : a.results)
            for (const ScalarResult& s : r.scalars) {
                table.set(row, s.name, exact_number(s.estimate.mean));
                table.set(row, s.name + "_err", exact_number(s.estimate.error));
                // 1: the window is shorter than 50 τ_int, the error an underestimate.
                table.set(row, s.name + "_short", s.estimate.short_series() ? "1" : "0");
            }
        table.add(std::move(row));
    }
    for (const auto& group : replicate_groups(runs)) {
        const ReplicateSummary g = summarise_replicates(group);
        CsvTable::Row row = parameter_row(table, *group.front());
        std::string seeds;
        for (const std::uint64_t seed : g.seeds) {
            if (!seeds.empty()) seeds += ' ';
            seeds += std::to_string(seed);
        }
        table.set(row, "run", csv_quoted("replicates of " + g.runs.front().string()));
        table.set(row, "replicates", std::to_string(g.runs.size()));
        table.set(row, "seed", csv_quoted(seeds));
        for (const ReplicateScalar& s : g.scalars) {
            table.set(row, s.name, exact_number(s.estimate.mean));
            table.set(row, s.name + "_err", exact_number(s.estimate.error));
            table.set(row, s.name + "_chi2", exact_number(s.estimate.chi2_per_dof));
        }
        table.add(std::move(row));
    }
    return table.text(
        std::string("rodsea ") + RODSEA_VERSION +
        " analysis summary: one row per run, its parameters (mm, s), then each steady-state "
        "scalar, its error bar (<name>_err) and whether the window was shorter than 50 tau_int "
        "(<name>_short = 1: the error is an underestimate); then, for runs that differ only in "
        "their seed, one row per group with the mean over the replicates, the error from their "
        "spread (<name>_err) and chi2/dof of that spread against the runs' own errors "
        "(<name>_chi2, ~1 when those are honest); the definitions are in each run's "
        "analysis.json");
}

}  // namespace rodsea
