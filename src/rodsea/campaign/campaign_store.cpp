#include "rodsea/campaign/campaign_store.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/number_text.hpp"
#include "rodsea/run/run_driver.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string scaling_text(const CampaignScaling& s) {
    return "# the --scale and --duration of this campaign's runs\nscale = " +
           exact_number(s.scale) +
           "\nduration = " + (s.duration ? exact_number(*s.duration) : std::string("none")) + "\n";
}

void check_scaling(const CampaignPaths& paths, const CampaignScaling& scaling) {
    const auto stored = read_text(paths.dir / "scaling.txt");
    if (!stored) return;
    if (*stored != scaling_text(scaling)) {
        std::string given = "--scale " + exact_number(scaling.scale);
        if (scaling.duration) given += " --duration " + exact_number(*scaling.duration);
        std::string said;
        std::istringstream lines(*stored);
        for (std::string line; std::getline(lines, line);)
            if (!line.empty() && line[0] != '#') said += (said.empty() ? "" : ", ") + line;
        const std::optional<CampaignScaling> started = read_campaign_scaling(paths);
        const bool longer = started && started->scale == scaling.scale && scaling.duration &&
                            (!started->duration || *started->duration < *scaling.duration);
        throw InvalidParameter(
            "--scale/--duration", given,
            "what the campaign in " + paths.dir.string() + " was started with (" + said + ")",
            longer ? "give the same options, or add --extend to continue every run to "
                     "--duration " +
                         exact_number(*scaling.duration) + " s"
                   : "give the same options, or another --out");
    }
}

// Several runners (the tasks of a job array) prepare the same directory at the same moment: a
// file that already says the same is left alone (each writer has its own temporary file).
void write_unless_same(const fs::path& path, const std::string& text) {
    if (read_text(path) != text) write_file_atomically(path, text);
}

// A directory whose runs/ holds points, none of them this campaign's, is another campaign's (or
// this one's with every point renamed, by an axis added or renamed): its points would all count
// as missing, its tables be replaced by empty ones, and new runs be mixed with foreign ones.
void check_points_are_this_campaigns(const CampaignPaths& paths, const CampaignGrid& grid) {
    std::error_code ec;
    if (!fs::is_directory(paths.dir / "runs", ec)) return;
    std::set<std::string> ours;
    for (const CampaignRun& r : grid.runs)
        ours.insert(fs::path(r.id).begin()->string());  // the point: the id's first part
    std::vector<std::string> foreign;
    for (const fs::directory_entry& e : fs::directory_iterator(paths.dir / "runs", ec)) {
        if (!e.is_directory(ec)) continue;
        const std::string point = e.path().filename().string();
        if (ours.count(point)) return;
        foreign.push_back(point);
    }
    if (foreign.empty()) return;
    std::sort(foreign.begin(), foreign.end());
    throw InvalidParameter(
        "campaign", grid.runs.empty() ? std::string("(no runs)") : grid.runs.front().id,
        "a point of the campaign in " + paths.dir.string(),
        "it holds " + std::to_string(foreign.size()) + " points, none of this campaign file's (" +
            foreign.front() + (foreign.size() > 1 ? ", ..." : "") +
            "): give the file it was started with, or another --out");
}

// The config a run was written with is its plan's, or (an extension cut short leaves configs at
// the longer duration beside the old scaling) the same but for its run length.
bool is_config_of(const std::string& stored, const RunPlan& plan) {
    if (stored == plan.config_toml) return true;
    try {
        return with_run_length(stored, "stored config", plan.control.duration, std::nullopt)
                   .config_toml == plan.config_toml;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

bool ends_before(const RunProgress& progress, double duration) {
    // Both are the same decimal number read back, or the shorter is shorter by a step at least.
    return progress.duration < duration * (1.0 - 1e-12);
}

fs::path default_campaign_dir(const Campaign& campaign) {
    return fs::path("out") / campaign.name;
}

std::optional<CampaignScaling> read_campaign_scaling(const CampaignPaths& paths) {
    const fs::path file = paths.dir / "scaling.txt";
    const auto text = read_text(file);
    if (!text) return std::nullopt;
    CampaignScaling scaling;
    bool scale_read = false, duration_read = false;
    std::istringstream lines(*text);
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t eq = line.find(" = ");
        const std::string key = line.substr(0, eq),
                          value = eq == std::string::npos ? "" : line.substr(eq + 3);
        try {
            if (key == "scale") {
                scaling.scale = parse_number("scale", value, 1e-3, 1.0);
                scale_read = true;
                continue;
            }
            if (key == "duration") {
                if (value != "none")
                    scaling.duration = parse_number("duration", value, 1e-6, 1e6, "s");
                duration_read = true;
                continue;
            }
        } catch (const InvalidParameter& e) {
            throw FileError(file.string(), std::string("is not a campaign's scaling: ") + e.what());
        }
        throw FileError(file.string(), "is not a campaign's scaling: its line '" + line + "'");
    }
    if (!scale_read || !duration_read)
        throw FileError(file.string(), "is not a campaign's scaling: it lacks scale or duration");
    return scaling;
}

void check_campaign_dir(const CampaignPaths& paths, const CampaignScaling& scaling,
                        const CampaignGrid& grid, const std::vector<RunPlan>& plans) {
    std::error_code ec;
    if (!fs::is_directory(paths.dir, ec) || !fs::exists(paths.dir / "campaign.toml", ec))
        throw FileError(paths.dir.string(),
                        "no campaign here yet (rodsea campaign run starts it; --out names another "
                        "directory)");
    check_scaling(paths, scaling);
    check_points_are_this_campaigns(paths, grid);
    for (std::size_t i = 0; i < grid.runs.size(); ++i) {
        const auto stored = read_text(paths.config(grid.runs[i]));
        if (stored && !is_config_of(*stored, plans[i]))
            throw InvalidParameter(
                "campaign", grid.runs[i].id,
                "the config it was started with (" + paths.config(grid.runs[i]).string() + ")",
                "the campaign file or its base changed this point: give the file the directory "
                "was started with");
    }
}

void prepare_campaign_dir(const CampaignPaths& paths, const Campaign& campaign,
                          const CampaignScaling& scaling, const CampaignGrid& grid,
                          const std::vector<RunPlan>& plans,
                          const std::vector<RunPlan>* plans_before) {
    std::error_code ec;
    if (fs::exists(paths.dir, ec) && !fs::is_directory(paths.dir, ec))
        throw FileError(paths.dir.string(), "is a file, not a campaign directory");
    const bool fresh = !fs::exists(paths.dir / "campaign.toml", ec);
    if (fresh && fs::exists(paths.dir, ec) && !fs::is_empty(paths.dir, ec))
        throw FileError(paths.dir.string(),
                        "exists, is not empty and holds no campaign: give another --out");
    if (!plans_before) check_scaling(paths, scaling);
    check_points_are_this_campaigns(paths, grid);
    // Every existing config is compared before anything is written. Extended, a run's config
    // may be the one it started with or (an extension cut short) the one it is extended to.
    for (std::size_t i = 0; i < grid.runs.size(); ++i) {
        const auto stored = read_text(paths.config(grid.runs[i]));
        if (stored && *stored != plans[i].config_toml &&
            (!plans_before || *stored != (*plans_before)[i].config_toml))
            throw InvalidParameter(
                "campaign", grid.runs[i].id,
                "the config it was started with (" + paths.config(grid.runs[i]).string() + ")",
                "the campaign file or its base changed this point; run the changed campaign "
                "with another --out, or remove that point's files");
    }
    fs::create_directories(paths.dir / "runs", ec);
    if (ec) throw FileError(paths.dir.string(), "cannot be created: " + ec.message());
    if (!campaign.file.empty()) {
        if (const auto text = read_text(campaign.file))
            write_unless_same(paths.dir / "campaign.toml", *text);
    }
    if (!fs::exists(paths.dir / "campaign.toml", ec))
        write_file_atomically(paths.dir / "campaign.toml", "# (given as a string)\n");
    for (std::size_t i = 0; i < grid.runs.size(); ++i) {
        const fs::path config = paths.config(grid.runs[i]);
        if (fs::exists(config, ec) && !plans_before) continue;
        fs::create_directories(config.parent_path(), ec);
        if (ec)
            throw FileError(config.parent_path().string(), "cannot be created: " + ec.message());
        write_unless_same(config, plans[i].config_toml);
    }
    // Last: an extension cut short leaves the old scaling beside configs of both durations, which
    // the same `--extend` accepts and completes.
    write_unless_same(paths.dir / "scaling.txt", scaling_text(scaling));
}

const char* to_string(RunState state) {
    switch (state) {
        case RunState::pending:
            return "pending";
        case RunState::running:
            return "running";
        case RunState::interrupted:
            return "interrupted";
        case RunState::done:
            return "done";
        case RunState::failed:
            return "failed";
    }
    return "?";
}

RunStatus run_status(const CampaignPaths& paths, const CampaignRun& run, int max_failures) {
    RunStatus s;
    const fs::path dir = paths.run_dir(run);
    s.progress = read_progress_file(dir);
    if (const auto failed = read_text(paths.failures(run))) {
        std::istringstream lines(*failed);
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("--- exit ", 0) == 0) {
                ++s.failures;
                s.blew_up = line.rfind("--- exit " + std::to_string(kExitBlownUp) + " ", 0) == 0;
            } else if (!line.empty()) {
                s.last_failure = line;
            }
        }
    }
    std::error_code ec;
    const bool has_checkpoint = fs::exists(dir / kCheckpointFile, ec);
    // A run that ran to a shorter duration than the campaign's now (extended since) is not;
    // one that stopped at a steady state is (it would stop there again).
    const bool finished =
        s.progress && (s.progress->state == "steady" ||
                       (s.progress->state == "done" && !ends_before(*s.progress, run.duration)));
    const int fd = ::open(paths.lock(run).c_str(), O_RDONLY | O_CLOEXEC);
    bool locked = false;
    if (fd >= 0) {
        struct flock probe {};
        probe.l_type = F_WRLCK;
        probe.l_whence = SEEK_SET;
        locked = ::fcntl(fd, F_OFD_GETLK, &probe) == 0 && probe.l_type != F_UNLCK;
        ::close(fd);
    }
    // A run continued by hand (rodsea run --resume DIR) holds its directory but no runner's claim.
    if (!locked && has_checkpoint) locked = run_directory_in_use(dir);
    if (finished && has_checkpoint)
        s.state = RunState::done;
    else if (locked)
        s.state = RunState::running;
    else if (s.failures >= max_failures || s.blew_up)
        s.state = RunState::failed;
    else if (has_checkpoint)
        s.state = RunState::interrupted;
    return s;
}

RunClaim::RunClaim(const CampaignPaths& paths, const CampaignRun& run) {
    const int fd = ::open(paths.lock(run).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw FileError(paths.lock(run).string(), "cannot be created");
    struct flock lock {};
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;
    if (::fcntl(fd, F_OFD_SETLK, &lock) != 0) {
        ::close(fd);
        return;
    }
    fd_ = fd;
}

RunClaim::~RunClaim() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

void record_failure(const CampaignPaths& paths, const CampaignRun& run, int exit_code,
                    const std::string& message) {
    std::ofstream out(paths.failures(run), std::ios::app);
    out << "--- exit " << exit_code << " at " << exact_number(unix_time_now()) << "\n"
        << message << (message.empty() || message.back() == '\n' ? "" : "\n");
    if (!out) throw FileError(paths.failures(run).string(), "cannot be written");
}

CampaignWork campaign_work(const CampaignPaths& paths, const CampaignGrid& grid,
                           const std::optional<std::vector<std::size_t>>& only, int max_failures) {
    CampaignWork work;
    if (only)
        work.mine = *only;
    else
        for (std::size_t i = 0; i < grid.runs.size(); ++i)
            work.mine.push_back(i);
    for (const std::size_t i : work.mine) {
        const RunState state = run_status(paths, grid.runs[i], max_failures).state;
        if (state == RunState::done)
            ++work.done;
        else if (state == RunState::failed)
            work.failed.push_back(i);
        else
            work.to_run.push_back(i);
    }
    return work;
}

}  // namespace rodsea
