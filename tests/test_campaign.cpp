// `rodsea campaign` as a user drives it: a grid of tiny runs started, interrupted with Ctrl-C,
// continued, and collected; the collected numbers are those of analysing each run by hand.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include "child_process.hpp"
#include "local_slurm_cluster.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/progress_file.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "run_comparison.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

// The base of the campaigns here: 6 polar rods and a sparse medium in a 20 mm box.
const std::string kTinyRods = R"([base.box]
side = 20.0
[[base.species]]
name = "polar"
kind = "polar_rod"
count = 6
[[base.species]]
name = "medium"
kind = "apolar_rod"
length = 2.5
area_fraction = 0.1
)";

// 4 points × 2 seeds, 0.15 s each (about 0.3 s of wall time).
const std::string kCampaign = R"([campaign]
name = "grid"
replicates = 2

)" + kTinyRods + R"([base.time]
duration = 0.15
[base.output]
interval = 0.005

[[axis]]
key = "species.medium.area_fraction"
values = [0.1, 0.3]
[[axis]]
key = "drive.gamma"
values = [5.0, 7.0]

[analysis]
observables = ["order"]

[[figure]]
name = "P_vs_phi"
x = "species.medium.area_fraction"
y = ["P_polar", "S_medium"]
series = "drive.gamma"
serieslabel = "Γ"

[[figure]]
name = "ordered"
kind = "map"
x = "species.medium.area_fraction"
series = "drive.gamma"
y = ["P_polar"]
level = 0.5

[[figure]]
name = "last_frames"
kind = "snapshot"
when = { "drive.gamma" = 7.0 }

[[figure]]
name = "order_in_time"
kind = "analysis"
plot = "order_parameters"
when = { "species.medium.area_fraction" = 0.1, "drive.gamma" = [5.0, 7.0] }

[[figure]]
name = "side_by_side"
kind = "movie"
when = { "drive.gamma" = 5.0 }
)";

std::string read_file(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The CSV's rows as maps from column to cell (no cell here holds a comma but the point names,
// which are not read).
std::vector<std::map<std::string, std::string>> csv_rows(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // comment
    std::getline(in, line);
    const auto split = [](const std::string& text) {
        std::vector<std::string> cells;
        std::string cell;
        bool quoted = false;
        for (const char c : text) {
            if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                cells.push_back(std::exchange(cell, ""));
            else
                cell += c;
        }
        cells.push_back(cell);
        return cells;
    };
    const std::vector<std::string> header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line);
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i)
            row[header[i]] = cells[i];
        rows.push_back(row);
    }
    return rows;
}

int count_of(const std::string& text, const std::string& word) {
    int n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
        ++n;
    return n;
}

TEST(Campaign, InterruptedAndContinuedWithNothingLostOrRunTwiceThenCollected) {
    const ScratchDir scratch("campaign");
    const fs::path file = scratch.path() / "grid.toml";
    // The runs analysed to 0.1 s of their 0.15 s: collect must pass [analysis] to on.
    std::string campaign = kCampaign;
    const std::string observables = "observables = [\"order\"]\n";
    campaign.insert(campaign.find(observables) + observables.size(), "to = 0.1\n");
    std::ofstream(file) << campaign;
    const fs::path dir = scratch.path() / "grid";
    const fs::path runs = dir / "runs";
    const std::string first = "medium.area_fraction=0.1,gamma=5";

    // Ctrl-C once two runs are done and a third is under way.
    ChildOptions interrupt;
    interrupt.interrupt_when = [&] {
        int done = 0, running = 0;
        std::error_code ec;
        if (!fs::exists(runs, ec)) return false;
        for (const auto& e : fs::recursive_directory_iterator(runs, ec)) {
            if (e.path().filename() != "progress.txt") continue;
            const std::string text = read_file(e.path());
            done += text.find("state = done") != std::string::npos;
            running += text.find("state = running") != std::string::npos;
        }
        return done >= 2 && running >= 1;
    };
    const ChildResult stopped = run_rodsea(
        {"campaign", "run", file.string(), "--out", dir.string()}, scratch.path(), interrupt);
    ASSERT_TRUE(stopped.interrupted) << stopped.out << stopped.err;
    ASSERT_EQ(stopped.exit_code, 130) << stopped.out << stopped.err;
    const ChildResult status =
        run_rodsea({"campaign", "status", file.string(), "--out", dir.string()}, scratch.path());
    ASSERT_EQ(status.exit_code, 0) << status.err;
    EXPECT_NE(status.out.find("interrupted"), std::string::npos) << status.out;
    EXPECT_NE(status.out.find("pending"), std::string::npos) << status.out;

    const ChildResult resumed = run_rodsea(
        {"campaign", "run", file.string(), "--out", dir.string(), "--jobs", "2"}, scratch.path());
    ASSERT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
    EXPECT_EQ(count_of(resumed.out, "campaign: resume "), 1) << resumed.out;
    EXPECT_EQ(count_of(resumed.out, "campaign: done "), 6) << resumed.out;
    // A third command has nothing to do.
    const ChildResult again =
        run_rodsea({"campaign", "run", file.string(), "--out", dir.string()}, scratch.path());
    EXPECT_NE(again.out.find("8 done, 0 to run"), std::string::npos) << again.out;
    EXPECT_EQ(count_of(again.out, "campaign: start"), 0);

    // Every run whole: 0.15 s at 5 ms is 31 frames, equally spaced, none lost or doubled.
    int resumed_runs = 0;
    for (const auto& point : fs::directory_iterator(runs)) {
        if (!point.is_directory()) continue;
        for (const char* seed : {"seed1", "seed2"}) {
            const fs::path run = point.path() / seed;
            const std::vector<double> t = TrajectoryReader(run / "trajectory.h5").times();
            ASSERT_EQ(t.size(), 31u) << run;
            for (std::size_t k = 0; k < t.size(); ++k)
                EXPECT_NEAR(t[k], 0.005 * static_cast<double>(k), 1e-12) << run;
            const std::string log = read_file(run.string() + ".log");
            const bool was_stopped = count_of(log, "rodsea: interrupted") == 1;
            resumed_runs += was_stopped;
            // The log keeps what the run said: how its start was built (once, resumed or not)
            // and, after a stop, where it took up again.
            EXPECT_EQ(count_of(log, "initial state built"), 1) << log;
            EXPECT_EQ(count_of(log, ": from step "), was_stopped ? 1 : 0) << log;
        }
    }
    EXPECT_EQ(resumed_runs, 1);

    // collect = analyse each run by hand to 0.1 s: the same per-run P; each point's the mean of
    // its two.
    const ChildResult collected =
        run_rodsea({"campaign", "collect", file.string(), "--out", dir.string()}, scratch.path());
    ASSERT_EQ(collected.exit_code, 0) << collected.out << collected.err;
    const fs::path by_hand = scratch.path() / "by_hand.csv";
    std::vector<std::string> analyze{"analyze"};
    for (const auto& point : fs::directory_iterator(runs))
        if (point.is_directory())
            for (const char* seed : {"seed1", "seed2"})
                analyze.push_back((point.path() / seed).string());
    analyze.insert(analyze.end(), {"--observables", "order", "--to", "0.1", "--table",
                                   by_hand.string(), "--quiet"});
    ASSERT_EQ(run_rodsea(analyze, scratch.path()).exit_code, 0);
    std::map<std::string, double> hand;
    for (const auto& row : csv_rows(by_hand))
        if (row.at("replicates").empty())
            hand[fs::path(row.at("run")).lexically_normal().string()] =
                std::stod(row.at("P_polar"));
    const auto collected_runs = csv_rows(dir / "collected" / "runs.csv");
    int compared = 0;
    for (const auto& row : collected_runs) {
        if (!row.at("replicates").empty()) continue;
        const std::string run = fs::path(row.at("run")).lexically_normal().string();
        ASSERT_TRUE(hand.count(run)) << run;
        EXPECT_EQ(std::stod(row.at("P_polar")), hand.at(run)) << run;
        ++compared;
    }
    EXPECT_EQ(compared, 8);
    const auto points = csv_rows(dir / "collected" / "points.csv");
    ASSERT_EQ(points.size(), 4u);
    for (const auto& p : points) {
        EXPECT_EQ(p.at("runs"), "2");
        const std::string name = p.at("point");
        const double a = hand.at((runs / name / "seed1").lexically_normal().string());
        const double b = hand.at((runs / name / "seed2").lexically_normal().string());
        EXPECT_NEAR(std::stod(p.at("P_polar")), 0.5 * (a + b), 1e-12) << name;
        // With two replicates the error is at least their spread, |a − b| / 2.
        EXPECT_GE(std::stod(p.at("P_polar_err")), 0.5 * std::abs(a - b) * (1 - 1e-12)) << name;
    }

    // Collecting again reuses every run's analysis (same trajectory, [analysis] and version):
    // the same tables to the byte, no analysis rewritten. A run whose analysis.json no longer
    // matches (here: its key edited) is analysed again, as is every run with --reanalyse.
    const std::string points_text = read_file(dir / "collected" / "points.csv");
    const std::string runs_text = read_file(dir / "collected" / "runs.csv");
    const fs::path some_run = runs / "medium.area_fraction=0.1,gamma=7" / "seed1";
    const auto written = fs::last_write_time(some_run / "analysis" / "analysis.json");
    const auto collect_again = [&](std::vector<std::string> extra) {
        std::vector<std::string> words{"campaign", "collect", file.string(), "--out", dir.string()};
        words.insert(words.end(), extra.begin(), extra.end());
        const ChildResult r = run_rodsea(words, scratch.path());
        EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
        EXPECT_EQ(read_file(dir / "collected" / "points.csv"), points_text);
        EXPECT_EQ(read_file(dir / "collected" / "runs.csv"), runs_text);
        return r.out;
    };
    EXPECT_NE(collect_again({}).find("(8 unchanged since their analysis)"), std::string::npos);
    EXPECT_EQ(fs::last_write_time(some_run / "analysis" / "analysis.json"), written);
    {
        std::string json = read_file(some_run / "analysis" / "analysis.json");
        json.replace(json.find("\"cache_key\": \"rodsea"), 20, "\"cache_key\": \"RODSEA");
        std::ofstream(some_run / "analysis" / "analysis.json") << json;
    }
    const std::string stale = collect_again({});
    EXPECT_NE(stale.find("(7 unchanged since their analysis)"), std::string::npos) << stale;
    EXPECT_NE(stale.find("analysed medium.area_fraction=0.1,gamma=7/seed1"), std::string::npos);
    EXPECT_NE(collect_again({"--reanalyse"}).find("(0 unchanged since their analysis)"),
              std::string::npos);

    // The figures: curves and the map from points.csv, each showing the points its `when` picks.
    const fs::path figures = dir / "collected" / "figures";
    EXPECT_NE(collected.out.find("collect: 7 figure files"), std::string::npos) << collected.out;
    for (const char* png : {"P_vs_phi.png", "ordered.png"})
        EXPECT_GT(fs::file_size(figures / png), 10'000u) << png;
    const std::string spec = read_file(dir / "collected" / "figures.json");
    EXPECT_NE(spec.find("\"x\": \"medium.area_fraction\""), std::string::npos) << spec;
    EXPECT_EQ(count_of(spec, "\"medium.area_fraction=0.3,gamma=7\""), 2) << spec;
    EXPECT_NE(spec.find("\"serieslabel\": \"Γ\""), std::string::npos) << spec;
    // Snapshots and analysis figures: one per chosen point, from its first finished replicate.
    EXPECT_TRUE(fs::exists(figures / "last_frames" / "medium.area_fraction=0.1,gamma=7.png"));
    EXPECT_TRUE(fs::exists(figures / "last_frames" / "medium.area_fraction=0.3,gamma=7.png"));
    EXPECT_EQ(std::distance(fs::directory_iterator(figures / "last_frames"), {}), 2);
    for (const char* point :
         {"medium.area_fraction=0.1,gamma=5", "medium.area_fraction=0.1,gamma=7"})
        EXPECT_TRUE(fs::exists(figures / "order_in_time" / point / "order_parameters.png"))
            << point;
    // The movie: the two gamma = 5 points side by side, all 31 frames in step.
    const std::string probe = shell_output(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
        "stream=width,nb_read_frames -of csv=p=0 '" +
        (figures / "side_by_side.mp4").string() + "'");
    EXPECT_EQ(probe, "960,31\n") << probe;
}

// Three runs in a 20 mm box; the gamma = 7 one lasts 30 s of simulated time (about a minute of
// one core here), so that with a one-minute wall time it is stopped by SLURM's signal at least
// once and must be resubmitted; the other two take about a second each. On a loaded machine (two
// simulations beside the test's two tasks on two cores) each task gets half a core, so the run
// needs up to about eight one-minute slots: the resubmissions and the deadline allow twelve.
const std::string kSlurmCampaign = R"([campaign]
name = "cluster"

)" + kTinyRods + R"([base.time]
duration = 0.5
[base.output]
interval = 0.05

[[axis]]
key = "drive.gamma"
values = [5.0, 6.0, 7.0]

[[override]]
when = { "drive.gamma" = 7.0 }
set = { "time.duration" = 30.0 }

[analysis]
observables = ["order"]
)";

TEST(CampaignOnSlurm, AWallTimeHitIsResubmittedAndEveryRunFinishesExactlyOnce) {
    if (const auto why = LocalSlurmCluster::unavailable()) GTEST_SKIP() << *why;
    const ScratchDir scratch("campaign-slurm");
    const LocalSlurmCluster cluster(scratch.path() / "cluster");
    ASSERT_TRUE(cluster.ready()) << cluster.logs();
    const fs::path file = scratch.path() / "cluster.toml";
    std::ofstream(file) << kSlurmCampaign;
    const fs::path dir = scratch.path() / "out";

    // A dry run writes the script and submits nothing.
    const ChildResult dry = run_rodsea({"campaign", "submit", file.string(), "--out", dir.string(),
                                        "--time", "1", "--pack", "2", "--dry-run"},
                                       scratch.path());
    ASSERT_EQ(dry.exit_code, 0) << dry.out << dry.err;
    const std::string script = read_file(dir / "slurm" / "array-1.sh");
    EXPECT_NE(script.find("#SBATCH --array=0-1\n"), std::string::npos) << script;
    EXPECT_NE(script.find("#SBATCH --signal=B:TERM@30\n"), std::string::npos) << script;
    EXPECT_TRUE(cluster.queue_empty());
    fs::remove_all(dir / "slurm");

    // Two array tasks on the node's two CPUs; SIGTERM 40 s before the one-minute wall time, which
    // SLURM's 30 s polling delivers 20 to 50 s into a task.
    const ChildResult submitted =
        run_rodsea({"campaign", "submit", file.string(), "--out", dir.string(), "--time", "1",
                    "--signal-seconds", "40", "--pack", "2", "--resubmit", "12"},
                   scratch.path());
    ASSERT_EQ(submitted.exit_code, 0) << submitted.out << submitted.err;
    EXPECT_NE(submitted.out.find("3 runs in 2 array tasks"), std::string::npos) << submitted.out;
    // A second submit while the first is queued takes nothing twice.
    const ChildResult twice =
        run_rodsea({"campaign", "submit", file.string(), "--out", dir.string(), "--time", "1"},
                   scratch.path());
    ASSERT_EQ(twice.exit_code, 0) << twice.out << twice.err;
    EXPECT_NE(twice.out.find("nothing submitted"), std::string::npos) << twice.out;

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(13);
    std::string status;
    while (std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::seconds(5));
        status =
            run_rodsea({"campaign", "status", file.string(), "--out", dir.string()}, scratch.path())
                .out;
        if (status.find("3 done") != std::string::npos && cluster.queue_empty()) break;
    }
    ASSERT_NE(status.find("3 runs: 0 pending, 0 running, 0 interrupted, 3 done"), std::string::npos)
        << status << cluster.logs();

    // What every task said, in order of submission.
    std::string said;
    for (int k = 1; fs::exists(dir / "slurm" / ("tasks-" + std::to_string(k) + ".txt")); ++k)
        for (const auto& e : fs::directory_iterator(dir / "slurm" / "logs"))
            if (e.path().filename().string().rfind("array-" + std::to_string(k) + "_", 0) == 0)
                said += read_file(e.path());
    for (const std::string id : {"gamma=5/seed1", "gamma=6/seed1", "gamma=7/seed1"}) {
        EXPECT_EQ(count_of(said, "campaign: start " + id), 1) << id << "\n" << said;
        EXPECT_EQ(count_of(said, "campaign: done " + id), 1) << id << "\n" << said;
    }
    // The long run hit the wall time at least once, checkpointed, and was resumed as often.
    const int stops = count_of(said, "campaign: stopped gamma=7/seed1 (checkpoint written)");
    EXPECT_GE(stops, 1) << said;
    EXPECT_EQ(count_of(said, "campaign: resume gamma=7/seed1"), stops) << said;
    EXPECT_EQ(count_of(said, " failed (exit"), 0) << said;

    // Every run whole: its frames equally spaced from 0 to its duration, none lost or doubled.
    for (const auto& [id, frames] : std::vector<std::pair<std::string, std::size_t>>{
             {"gamma=5/seed1", 11}, {"gamma=6/seed1", 11}, {"gamma=7/seed1", 601}}) {
        const std::vector<double> t = TrajectoryReader(dir / "runs" / id / "trajectory.h5").times();
        ASSERT_EQ(t.size(), frames) << id;
        for (std::size_t k = 0; k < t.size(); ++k)
            EXPECT_NEAR(t[k], 0.05 * static_cast<double>(k), 1e-9) << id;
    }

    // The collected table holds what analysing each run by hand gives.
    ASSERT_EQ(run_rodsea({"campaign", "collect", file.string(), "--out", dir.string(), "--quiet"},
                         scratch.path())
                  .exit_code,
              0);
    const fs::path by_hand = scratch.path() / "by_hand.csv";
    ASSERT_EQ(run_rodsea({"analyze", (dir / "runs" / "gamma=5" / "seed1").string(),
                          (dir / "runs" / "gamma=6" / "seed1").string(),
                          (dir / "runs" / "gamma=7" / "seed1").string(), "--observables", "order",
                          "--table", by_hand.string(), "--quiet"},
                         scratch.path())
                  .exit_code,
              0);
    std::map<std::string, double> hand;
    for (const auto& row : csv_rows(by_hand))
        if (row.at("replicates").empty())
            hand[fs::path(row.at("run")).lexically_normal().string()] =
                std::stod(row.at("P_polar"));
    const auto points = csv_rows(dir / "collected" / "points.csv");
    ASSERT_EQ(points.size(), 3u);
    for (const auto& p : points) {
        EXPECT_EQ(p.at("runs"), "1");
        const std::string run =
            (dir / "runs" / p.at("point") / "seed1").lexically_normal().string();
        ASSERT_TRUE(hand.count(run)) << run;
        EXPECT_EQ(std::stod(p.at("P_polar")), hand.at(run)) << run;
    }
}

TEST(Campaign, RunsTakeTheirThreadsFromTheCommandLineAndReportProgressInAPlainFile) {
    const ScratchDir scratch("campaign-run");
    const fs::path config = scratch.path() / "small.toml";
    std::ofstream(config)
        << "[box]\nside = 15.0\n[time]\nduration = 0.01\n[output]\ninterval = 0.005\n";
    const fs::path dir = scratch.path() / "small";
    const ChildResult r =
        run_rodsea({"run", config.string(), "--out", dir.string(), "--threads", "2", "--quiet"},
                   scratch.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The stored config says what ran: the same config and seed on 2 threads reproduce it.
    EXPECT_NE(read_file(dir / "config.toml").find("threads = 2"), std::string::npos);
    const std::string progress = read_file(dir / "progress.txt");
    EXPECT_NE(progress.find("state = done"), std::string::npos) << progress;
    EXPECT_NE(progress.find("step = 8000\ntotal_steps = 8000\n"), std::string::npos) << progress;
    // Continued on another thread count for a session, the trajectory is the one a single
    // thread gives from the start (threads change the speed only), and the stored config still
    // says how the run started.
    const ChildResult resumed = run_rodsea(
        {"run", "--resume", dir.string(), "--threads", "1", "--duration", "0.015", "--quiet"},
        scratch.path());
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_NE(read_file(dir / "config.toml").find("threads = 2"), std::string::npos);
    const fs::path one_thread = scratch.path() / "one-thread";
    ASSERT_EQ(run_rodsea({"run", config.string(), "--out", one_thread.string(), "--threads", "1",
                          "--quiet"},
                         scratch.path())
                  .exit_code,
              0);
    ASSERT_EQ(run_rodsea({"run", "--resume", one_thread.string(), "--duration", "0.015", "--quiet"},
                         scratch.path())
                  .exit_code,
              0);
    const Checkpoint a = read_checkpoint(dir / "checkpoint.h5");
    const Checkpoint b = read_checkpoint(one_thread / "checkpoint.h5");
    EXPECT_EQ(a.step, 12000u);
    EXPECT_EQ(a.step, b.step);
    EXPECT_TRUE(a.bodies.position == b.bodies.position && a.bodies.velocity == b.bodies.velocity &&
                a.bodies.spin == b.bodies.spin && a.bodies.orientation == b.bodies.orientation);
}

// Two points of 0.3 s each (about 5 s of wall time together here), then a third.
std::string ensemble_campaign(const std::string& values) {
    return R"([campaign]
name = "together"

)" + kTinyRods +
           R"([base.time]
duration = 0.3
[base.output]
interval = 0.01

[[axis]]
key = "species.medium.area_fraction"
values = )" +
           values + "\n";
}

// `campaign run --ensemble` steps a campaign's runs as one ensemble in one process. Interrupted,
// then continued with a point added (two resumed runs and a new one in one ensemble), every run
// is bit for bit the run the local executor makes of it, one process per run.
TEST(Campaign, AnEnsembleRunnerMakesTheRunsTheLocalExecutorMakes) {
    const ScratchDir scratch("campaign-ensemble");
    const fs::path file = scratch.path() / "together.toml";
    std::ofstream(file) << ensemble_campaign("[0.1, 0.3]");
    const fs::path dir = scratch.path() / "together";
    const fs::path runs = dir / "runs";
    const std::vector<std::string> points{"medium.area_fraction=0.1", "medium.area_fraction=0.3"};

    // Ctrl-C once both runs have stepped past their first frames.
    ChildOptions interrupt;
    interrupt.interrupt_when = [&] {
        for (const std::string& p : points) {
            const std::string text = read_file(runs / p / "seed1" / "progress.txt");
            if (text.find("state = running") == std::string::npos ||
                text.find("\nstep = 0\n") != std::string::npos)
                return false;
        }
        return true;
    };
    const ChildResult stopped =
        run_rodsea({"campaign", "run", file.string(), "--out", dir.string(), "--ensemble"},
                   scratch.path(), interrupt);
    ASSERT_TRUE(stopped.interrupted) << stopped.out << stopped.err;
    ASSERT_EQ(stopped.exit_code, 130) << stopped.out << stopped.err;
    EXPECT_NE(stopped.out.find("as one ensemble on each run's run.backend, 1 thread"),
              std::string::npos)
        << stopped.out;
    for (const std::string& p : points) {
        EXPECT_NE(read_file(runs / p / "seed1" / "progress.txt").find("state = stopped"),
                  std::string::npos)
            << p;
        // The run's log has its session and its own message, which names it.
        const std::string log = read_file(runs / p / "seed1.log");
        EXPECT_NE(log.find("started with 1 other runs"), std::string::npos) << log;
        EXPECT_NE(log.find("rodsea: " + (runs / p / "seed1").string() + ": interrupted (SIGINT)"),
                  std::string::npos)
            << log;
        EXPECT_EQ(count_of(log, "rodsea: "), 1) << log;
        EXPECT_NE(log.find("=== exit 130"), std::string::npos) << log;
    }

    std::ofstream(file) << ensemble_campaign("[0.1, 0.3, 0.2]");
    const ChildResult continued = run_rodsea(
        {"campaign", "run", file.string(), "--out", dir.string(), "--ensemble"}, scratch.path());
    ASSERT_EQ(continued.exit_code, 0) << continued.out << continued.err;
    EXPECT_EQ(count_of(continued.out, "campaign: resume "), 2) << continued.out;
    EXPECT_EQ(count_of(continued.out, "campaign: start "), 1) << continued.out;
    EXPECT_NE(continued.out.find("the ensemble of 3 runs"), std::string::npos) << continued.out;
    EXPECT_NE(continued.out.find("3/3 runs done"), std::string::npos) << continued.out;

    const fs::path local = scratch.path() / "local";
    const ChildResult alone = run_rodsea(
        {"campaign", "run", file.string(), "--out", local.string(), "--quiet"}, scratch.path());
    ASSERT_EQ(alone.exit_code, 0) << alone.out << alone.err;
    for (const char* p :
         {"medium.area_fraction=0.1", "medium.area_fraction=0.3", "medium.area_fraction=0.2"})
        expect_same_run(runs / p / "seed1", local / "runs" / p / "seed1");

    // On a cluster each array task steps its runs as one ensemble on all its CPUs.
    const ChildResult dry = run_rodsea(
        {"campaign", "submit", file.string(), "--out", (scratch.path() / "cluster").string(),
         "--ensemble", "--pack", "3", "--cpus-per-task", "4", "--backend", "cpu", "--dry-run"},
        scratch.path());
    ASSERT_EQ(dry.exit_code, 0) << dry.out << dry.err;
    EXPECT_NE(dry.out.find("as one ensemble on 4 threads"), std::string::npos) << dry.out;
    const std::string script = read_file(scratch.path() / "cluster" / "slurm" / "array-1.sh");
    EXPECT_NE(script.find("'--ensemble' '--threads' '4' '--backend' 'cpu'"), std::string::npos)
        << script;
    EXPECT_EQ(script.find("--jobs"), std::string::npos) << script;
    const std::string follow_up = read_file(scratch.path() / "cluster" / "slurm" / "resubmit-1.sh");
    EXPECT_NE(follow_up.find("--ensemble"), std::string::npos) << follow_up;
    EXPECT_NE(follow_up.find("'--backend' 'cpu'"), std::string::npos) << follow_up;
}

// A run's log that cannot be written (here its path is taken by a directory) is the campaign's
// record, not the run: the ensemble runner names it and runs the run to the end, and the campaign
// counts it done. (A point added to a finished campaign, as a
// campaign's directory must be the campaign's before its runs' logs can be tampered with.)
// Ctrl-C at a terminal signals the whole foreground job: the runner and each of its runs, and the
// runner passes the signal on, so each run gets it twice. Killed by the repeat, a run would lose
// everything since its last checkpoint while the runner reported it written: here there is no
// earlier checkpoint (they come every 30 min of wall time), so each run's checkpoint must be the
// one written at the step it stopped, which its progress file names.
TEST(Campaign, CtrlCAtTheTerminalStopsEveryRunAtACheckpointThoughEachGetsTheSignalTwice) {
    const ScratchDir scratch("campaign-ctrl-c");
    const fs::path file = scratch.path() / "long.toml";
    std::string campaign = ensemble_campaign("[0.1, 0.3]");
    campaign.replace(campaign.find("duration = 0.3"), 14, "duration = 60.0");
    std::ofstream(file) << campaign;
    const fs::path runs = scratch.path() / "long" / "runs";
    const std::vector<std::string> points{"medium.area_fraction=0.1", "medium.area_fraction=0.3"};
    ChildOptions ctrl_c;
    ctrl_c.interrupt_group = true;
    ctrl_c.interrupt_when = [&] {
        for (const std::string& p : points) {
            const std::optional<RunProgress> progress = read_progress_file(runs / p / "seed1");
            if (!progress || progress->state != "running" || progress->step == 0) return false;
        }
        return true;
    };
    const ChildResult stopped = run_rodsea({"campaign", "run", file.string(), "--out",
                                            (scratch.path() / "long").string(), "--jobs", "2"},
                                           scratch.path(), ctrl_c);
    ASSERT_TRUE(stopped.interrupted) << stopped.out << stopped.err;
    ASSERT_EQ(stopped.exit_code, 130) << stopped.out << stopped.err;
    EXPECT_EQ(count_of(stopped.out, "(checkpoint written)"), 2) << stopped.out;
    EXPECT_EQ(count_of(stopped.out, "was killed by signal"), 0) << stopped.out;
    for (const std::string& p : points) {
        const fs::path run = runs / p / "seed1";
        const std::optional<RunProgress> progress = read_progress_file(run);
        ASSERT_TRUE(progress) << p;
        EXPECT_EQ(progress->state, "stopped") << p;
        ASSERT_TRUE(fs::exists(run / "checkpoint.h5")) << p;
        EXPECT_EQ(read_checkpoint(run / "checkpoint.h5").step, progress->step) << p;
        EXPECT_GT(progress->step, 0u) << p;
    }
}

TEST(Campaign, AnEnsembleRunnerRunsOnWhenARunsLogCannotBeWritten) {
    const ScratchDir scratch("campaign-ensemble-log");
    const fs::path file = scratch.path() / "together.toml";
    const fs::path dir = scratch.path() / "together";
    const auto run_campaign = [&] {
        return run_rodsea({"campaign", "run", file.string(), "--out", dir.string(), "--ensemble"},
                          scratch.path());
    };
    std::ofstream(file) << ensemble_campaign("[0.1]");
    ASSERT_EQ(run_campaign().exit_code, 0);
    std::ofstream(file) << ensemble_campaign("[0.1, 0.3]");
    const fs::path run_dir = dir / "runs" / "medium.area_fraction=0.3" / "seed1";
    fs::create_directories(run_dir.string() + ".log");
    const ChildResult result = run_campaign();
    ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
    EXPECT_NE(result.err.find(run_dir.string() + ".log cannot be written"), std::string::npos)
        << result.err;
    EXPECT_NE(result.out.find("2/2 runs done"), std::string::npos) << result.out;
    EXPECT_NE(read_file(run_dir / "progress.txt").find("state = done"), std::string::npos);
}

// A campaign run to 0.1 s and found short is extended to 0.2 s with one command: the runs done
// continue from their last checkpoints, one process each or as one ensemble, and are bit for bit
// the runs of a campaign given 0.2 s from the start. What an extension may not change (the scale,
// a shorter duration) is refused before anything is written.
TEST(Campaign, AnExtendedCampaignsRunsAreTheRunsGivenTheLongerDurationFromTheStart) {
    const ScratchDir scratch("campaign-extend");
    const fs::path file = scratch.path() / "together.toml";
    std::ofstream(file) << ensemble_campaign("[0.1, 0.3]");
    const std::string f = file.string();
    const std::vector<std::string> points{"medium.area_fraction=0.1", "medium.area_fraction=0.3"};
    const auto campaign = [&](const std::string& sub, const fs::path& dir,
                              std::vector<std::string> more) {
        std::vector<std::string> args{"campaign", sub, f, "--out", dir.string()};
        args.insert(args.end(), more.begin(), more.end());
        return run_rodsea(args, scratch.path());
    };
    const fs::path reference = scratch.path() / "reference", local = scratch.path() / "local",
                   together = scratch.path() / "together";
    ASSERT_EQ(campaign("run", reference, {"--duration", "0.2", "--quiet"}).exit_code, 0);
    ASSERT_EQ(campaign("run", local, {"--duration", "0.1", "--quiet"}).exit_code, 0);
    ASSERT_EQ(campaign("run", together, {"--duration", "0.1", "--ensemble", "--quiet"}).exit_code,
              0);

    const std::string scaling = read_file(local / "scaling.txt");
    const struct {
        std::vector<std::string> more;
        std::string message;
    } refused[] = {
        {{"--duration", "0.2"}, "add --extend to continue every run to --duration 0.2 s"},
        {{"--duration", "0.05", "--extend"}, "a campaign is extended, not shortened"},
        {{"--duration", "0.2", "--scale", "0.5", "--extend"}, "an extension changes the runs'"},
        {{"--extend"}, "--extend with --duration T"},
    };
    for (const auto& c : refused) {
        const ChildResult r = campaign("run", local, c.more);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    const ChildResult nowhere =
        campaign("run", scratch.path() / "none", {"--duration", "0.2", "--extend"});
    EXPECT_EQ(nowhere.exit_code, 2) << nowhere.err;
    EXPECT_NE(nowhere.err.find("holds none yet"), std::string::npos) << nowhere.err;
    EXPECT_FALSE(fs::exists(scratch.path() / "none"));
    EXPECT_EQ(read_file(local / "scaling.txt"), scaling);
    for (const std::string& p : points)
        EXPECT_NE(read_file(local / "runs" / p / "seed1.toml").find("duration = 0.1\n"),
                  std::string::npos);

    // A submission (dry: nothing runs) takes the directory to 0.2 s: every run is to continue,
    // from 0.1 s, and is in the array.
    const ChildResult submitted =
        campaign("submit", local, {"--duration", "0.2", "--extend", "--dry-run"});
    ASSERT_EQ(submitted.exit_code, 0) << submitted.err;
    EXPECT_NE(submitted.out.find("extended from --duration 0.1 s to 0.2 s"), std::string::npos)
        << submitted.out;
    const ChildResult status = campaign("status", local, {"--duration", "0.2"});
    ASSERT_EQ(status.exit_code, 0) << status.err;
    EXPECT_EQ(count_of(status.out, "0.1 / 0.2"), 2) << status.out;
    EXPECT_NE(status.out.find("0 done"), std::string::npos) << status.out;
    EXPECT_EQ(count_of(read_file(local / "slurm" / "tasks-1.txt"), "seed1"), 2);

    const ChildResult extended = campaign("run", local, {"--duration", "0.2"});
    ASSERT_EQ(extended.exit_code, 0) << extended.out << extended.err;
    EXPECT_EQ(count_of(extended.out, "campaign: resume "), 2) << extended.out;
    const ChildResult in_ensemble =
        campaign("run", together, {"--duration", "0.2", "--extend", "--ensemble"});
    ASSERT_EQ(in_ensemble.exit_code, 0) << in_ensemble.out << in_ensemble.err;
    EXPECT_NE(in_ensemble.out.find("2/2 runs done"), std::string::npos) << in_ensemble.out;
    for (const std::string& p : points) {
        expect_same_run(local / "runs" / p / "seed1", reference / "runs" / p / "seed1");
        expect_same_run(together / "runs" / p / "seed1", reference / "runs" / p / "seed1");
    }
    // Done at 0.2 s, and the directory is a 0.2 s campaign's to every command.
    const ChildResult again = campaign("run", local, {"--duration", "0.2", "--extend"});
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.out.find("extended from"), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("2 done, 0 to run"), std::string::npos) << again.out;
    // Every later command but plan takes the directory's scaling when none is given; one given
    // is still checked against it.
    const ChildResult remembered = campaign("status", local, {});
    ASSERT_EQ(remembered.exit_code, 0) << remembered.err;
    EXPECT_EQ(count_of(remembered.out, "0.2 / 0.2"), 2) << remembered.out;
    const ChildResult continued = campaign("run", local, {});
    ASSERT_EQ(continued.exit_code, 0) << continued.err;
    EXPECT_NE(continued.out.find("2 done, 0 to run"), std::string::npos) << continued.out;
    const ChildResult other_scale = campaign("status", local, {"--scale", "0.5"});
    EXPECT_EQ(other_scale.exit_code, 2) << other_scale.err;
    EXPECT_NE(other_scale.err.find("was started with (scale = 1, duration = 0.2)"),
              std::string::npos)
        << other_scale.err;
    // plan describes the file: its 0.3 s (the sphere-steps of its runs), not the directory's 0.2.
    const auto sphere_steps = [&](std::vector<std::string> more) {
        more.push_back("--no-measure");
        const std::string out = campaign("plan", local, more).out;
        const std::size_t total = out.find("total ");
        return total == std::string::npos ? out : out.substr(total, out.find('\n', total) - total);
    };
    EXPECT_EQ(sphere_steps({}), sphere_steps({"--duration", "0.3"}));
    EXPECT_NE(sphere_steps({}), sphere_steps({"--duration", "0.2"}));
    // scaling.txt is input too.
    std::ofstream(together / "scaling.txt") << "scale = 1\nduration = soon\n";
    const ChildResult garbled = campaign("run", together, {"--duration", "0.3", "--extend"});
    EXPECT_EQ(garbled.exit_code, 74) << garbled.err;
    EXPECT_NE(
        garbled.err.find("scaling.txt: is not a campaign's scaling: invalid duration = 'soon'"),
        std::string::npos)
        << garbled.err;
}

// A run of a campaign continued by hand (`rodsea run --resume DIR --duration T`, which holds the
// run directory's lock, not a runner's claim) while the campaign is looked at and run again:
// status calls it running, not interrupted, and a runner leaves it alone rather than resume it,
// which would fail (one process per run directory) and count as the run's failure.
TEST(Campaign, ARunContinuedByHandIsLeftToItsProcess) {
    const ScratchDir scratch("campaign-by-hand");
    const fs::path file = scratch.path() / "together.toml";
    std::ofstream(file) << ensemble_campaign("[0.1]");
    const fs::path dir = scratch.path() / "out";
    const auto campaign = [&](const std::string& sub, std::vector<std::string> more) {
        std::vector<std::string> args{"campaign", sub, file.string(), "--out", dir.string()};
        args.insert(args.end(), more.begin(), more.end());
        return run_rodsea(args, scratch.path());
    };
    ASSERT_EQ(campaign("run", {"--duration", "0.1", "--quiet"}).exit_code, 0);
    const fs::path runs = dir / "runs";
    const fs::path run_dir = runs / "medium.area_fraction=0.1" / "seed1";
    {
        const RunDirectoryLock by_hand(run_dir);
        const ChildResult extended = campaign("run", {"--duration", "0.2", "--extend"});
        ASSERT_EQ(extended.exit_code, 0) << extended.out << extended.err;
        EXPECT_NE(extended.out.find("is being run by another rodsea process"), std::string::npos)
            << extended.out;
        EXPECT_FALSE(fs::exists(runs / "medium.area_fraction=0.1" / "seed1.failed"));
        const ChildResult status = campaign("status", {});
        ASSERT_EQ(status.exit_code, 0) << status.err;
        EXPECT_NE(status.out.find("1 running"), std::string::npos) << status.out;
    }
    // Its process gone (here: the lock released), the campaign's runner resumes it.
    const ChildResult status = campaign("status", {});
    EXPECT_NE(status.out.find("1 interrupted"), std::string::npos) << status.out;
    const ChildResult resumed = campaign("run", {});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.out << resumed.err;
    EXPECT_NE(resumed.out.find("1/1 runs done"), std::string::npos) << resumed.out;
    EXPECT_NE(read_file(run_dir / "progress.txt").find("time = 0.2"), std::string::npos);
}

struct BadRun {
    std::vector<std::string> args;
    std::string message;
};

TEST(Campaign, BadOptionsAndChangedCampaignsAreRefusedBeforeAnyRunStarts) {
    const ScratchDir scratch("campaign-bad");
    const fs::path file = scratch.path() / "grid.toml";
    std::ofstream(file) << kCampaign;
    const std::string f = file.string();
    const std::string dir = (scratch.path() / "grid").string();
    const std::vector<BadRun> cases{
        {{"campaign", "plna", f}, "did you mean 'plan'"},
        {{"campaign", "run"}, "CAMPAIGN"},
        {{"campaign", "run", f, "--scale", "2"}, "--scale"},
        {{"campaign", "run", f, "--jobs", "0"}, "--jobs"},
        {{"campaign", "status", f, "--out", dir}, "no campaign here yet"},
        {{"campaign", "submit", f, "--out", dir, "--dry-run", "--time", "1h"}, "--time"},
        {{"campaign", "submit", f, "--out", dir, "--dry-run", "--time", "30", "--signal-seconds",
          "1800"},
         "less than the wall time (1800 s)"},
        {{"campaign", "submit", f, "--out", dir, "--dry-run", "--pack", "2", "--jobs", "3",
          "--cpus-per-task", "4"},
         "at most --pack (2)"},
        {{"campaign", "submit", f, "--out", dir, "--dry-run", "--partition", "a b"}, "--partition"},
        {{"campaign", "submit", f, "--out", dir + " 2", "--dry-run"}, "no spaces"},
        {{"campaign", "run", f, "--out", dir, "--task", "0"}, "--task together with --tasks"},
        {{"campaign", "status", f, "--out", dir, "--jobs", "2"}, "an option of campaign status"},
        {{"campaign", "run", f, "--out", dir, "--partition", "x"}, "an option of campaign run"},
        {{"campaign", "run", f, "--out", dir, "--ensemble", "--jobs", "2"},
         "no --jobs with --ensemble"},
        {{"campaign", "submit", f, "--out", dir, "--dry-run", "--ensemble", "--jobs", "2"},
         "no --jobs with --ensemble"},
        {{"campaign", "run", f, "--out", dir, "--backend", "tpu"}, "--backend"},
    };
    // Without SLURM's commands on PATH, submit is refused (a dry run is not).
    {
        const ScopedEnv no_slurm("PATH", "/nonexistent");
        const ChildResult r = run_rodsea({"campaign", "submit", f, "--out", dir}, scratch.path());
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("no sbatch on PATH"), std::string::npos) << r.err;
    }
    for (const BadRun& c : cases) {
        const ChildResult r = run_rodsea(c.args, scratch.path());
        EXPECT_EQ(r.exit_code, c.message == "no campaign here yet" ? 74 : 2) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir));
    EXPECT_FALSE(fs::exists(dir + " 2"));
    // A campaign directory keeps its scaling and its points' configs.
    ASSERT_EQ(run_rodsea({"campaign", "run", f, "--out", dir, "--duration", "0.01", "--quiet"},
                         scratch.path())
                  .exit_code,
              0);
    const ChildResult rescaled =
        run_rodsea({"campaign", "run", f, "--out", dir, "--duration", "0.02"}, scratch.path());
    EXPECT_EQ(rescaled.exit_code, 2);
    EXPECT_NE(rescaled.err.find("duration = 0.01"), std::string::npos) << rescaled.err;
    std::string changed = kCampaign;
    changed.replace(changed.find("side = 20.0"), 11, "side = 21.0");
    std::ofstream(file) << changed;
    const ChildResult edited =
        run_rodsea({"campaign", "run", f, "--out", dir, "--duration", "0.01"}, scratch.path());
    EXPECT_EQ(edited.exit_code, 2);
    EXPECT_NE(edited.err.find("the campaign file or its base changed this point"),
              std::string::npos)
        << edited.err;
}

TEST(Campaign, AnotherCampaignsDirectoryIsRefusedAndNoTableShrinksWithoutAWord) {
    const ScratchDir scratch("campaign-foreign");
    const fs::path file = scratch.path() / "grid.toml";
    std::ofstream(file) << kCampaign;
    const std::string dir = (scratch.path() / "grid").string();
    ASSERT_EQ(run_rodsea(
                  {"campaign", "run", file.string(), "--out", dir, "--duration", "0.01", "--quiet"},
                  scratch.path())
                  .exit_code,
              0);
    ASSERT_EQ(
        run_rodsea({"campaign", "collect", file.string(), "--out", dir, "--quiet"}, scratch.path())
            .exit_code,
        0);
    const fs::path points = fs::path(dir) / "collected" / "points.csv";
    const std::string collected = read_file(points);
    ASSERT_EQ(csv_rows(points).size(), 4u);
    const std::string started_with = read_file(fs::path(dir) / "campaign.toml");

    // Another campaign (other drives: not one point in common) is refused by every command, and
    // nothing in the directory changes.
    std::string other = kCampaign;
    for (const auto& [was, now] : {std::pair{"5.0", "4.0"}, {"7.0", "6.0"}})
        for (std::size_t at = other.find(was); at != std::string::npos; at = other.find(was, at))
            other.replace(at, 3, now);
    const fs::path other_file = scratch.path() / "other.toml";
    std::ofstream(other_file) << other;
    for (const char* sub : {"status", "collect", "run"}) {
        const ChildResult r =
            run_rodsea({"campaign", sub, other_file.string(), "--out", dir}, scratch.path());
        EXPECT_EQ(r.exit_code, 2) << sub << ": " << r.err;
        EXPECT_NE(r.err.find("none of this campaign file's"), std::string::npos) << r.err;
    }
    EXPECT_EQ(read_file(points), collected);
    EXPECT_EQ(read_file(fs::path(dir) / "campaign.toml"), started_with);

    // The same points from a changed base: status and collect refuse them as run does.
    std::string changed = kCampaign;
    changed.replace(changed.find("side = 20.0"), 11, "side = 21.0");
    const fs::path changed_file = scratch.path() / "changed.toml";
    std::ofstream(changed_file) << changed;
    for (const char* sub : {"status", "collect"}) {
        const ChildResult r =
            run_rodsea({"campaign", sub, changed_file.string(), "--out", dir}, scratch.path());
        EXPECT_EQ(r.exit_code, 2) << sub << ": " << r.err;
        EXPECT_NE(r.err.find("changed this point"), std::string::npos) << r.err;
    }
    EXPECT_EQ(read_file(points), collected);

    // A value taken off an axis: collect writes the smaller table, says so and keeps the old one.
    std::string fewer = kCampaign;
    fewer.replace(fewer.find("values = [5.0, 7.0]"), 19, "values = [5.0]");
    fewer.replace(fewer.find("\"drive.gamma\" = [5.0, 7.0]"), 26, "\"drive.gamma\" = 5.0");
    fewer.replace(fewer.find("when = { \"drive.gamma\" = 7.0 }"), 30,
                  "when = { \"drive.gamma\" = 5.0 }");
    const fs::path fewer_file = scratch.path() / "fewer.toml";
    std::ofstream(fewer_file) << fewer;
    const ChildResult shrunk = run_rodsea(
        {"campaign", "collect", fewer_file.string(), "--out", dir, "--quiet"}, scratch.path());
    EXPECT_EQ(shrunk.exit_code, 0) << shrunk.err;
    EXPECT_NE(shrunk.out.find("points.csv held 4 rows, now 2"), std::string::npos) << shrunk.out;
    EXPECT_EQ(csv_rows(points).size(), 2u);
    EXPECT_EQ(read_file(fs::path(dir) / "collected" / "points.previous.csv"), collected);
}

// A run that blew up would blow up again from its checkpoint (the same steps): it is failed at
// once, shown as such, and not run again by the next `campaign run`.
TEST(Campaign, ARunThatBlewUpIsFailedNotInterrupted) {
    const ScratchDir scratch("campaign-blowup");
    const fs::path file = scratch.path() / "blowup.toml";
    std::ofstream(file) << "[campaign]\nname = \"blowup\"\n"
                        << kTinyRods
                        << "[base.time]\nduration = 0.05\ndt = 2e-4\n[base.output]\n"
                           "interval = 0.005\n";
    const std::string dir = (scratch.path() / "blowup").string();
    const ChildResult first =
        run_rodsea({"campaign", "run", file.string(), "--out", dir}, scratch.path());
    EXPECT_EQ(first.exit_code, 1) << first.out << first.err;
    EXPECT_NE(first.out.find("it blew up: change the config"), std::string::npos) << first.out;
    const ChildResult status =
        run_rodsea({"campaign", "status", file.string(), "--out", dir}, scratch.path());
    EXPECT_NE(status.out.find("failed"), std::string::npos) << status.out;
    EXPECT_NE(status.out.find("blew up (a resume would repeat the same steps"), std::string::npos)
        << status.out;
    EXPECT_NE(status.out.find("0 interrupted, 0 done, 1 failed"), std::string::npos) << status.out;
    const ChildResult again =
        run_rodsea({"campaign", "run", file.string(), "--out", dir}, scratch.path());
    EXPECT_EQ(again.exit_code, 1) << again.out << again.err;
    EXPECT_EQ(count_of(read_file(fs::path(dir) / "runs" / "base" / "seed1.failed"), "--- exit 3"),
              1);
}

// squeue answering with something other than job ids (a timeout's message on its standard
// output): the queue cannot be read, and nothing is submitted, rather than every run twice.
TEST(CampaignOnSlurm, AQueueThatCannotBeReadSubmitsNothing) {
    const ScratchDir scratch("campaign-squeue");
    const fs::path bin = scratch.path() / "bin";
    fs::create_directories(bin);
    const auto script = [&](const std::string& name, const std::string& body) {
        std::ofstream(bin / name) << "#!/bin/sh\n" << body << "\n";
        fs::permissions(bin / name, fs::perms::owner_all);
    };
    script("squeue", "echo 'slurm_load_jobs error: Socket timed out on send/recv operation'");
    script("sbatch", "touch " + (scratch.path() / "submitted").string() + "; echo 123");
    const fs::path file = scratch.path() / "grid.toml";
    std::ofstream(file) << kCampaign;
    const ScopedEnv path("PATH", bin.string() + ":/usr/bin:/bin");
    const ChildResult r = run_rodsea(
        {"campaign", "submit", file.string(), "--out", (scratch.path() / "grid").string()},
        scratch.path());
    EXPECT_EQ(r.exit_code, 74) << r.out << r.err;
    EXPECT_NE(r.err.find("where a job id belongs"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(scratch.path() / "submitted"));
}

}  // namespace
}  // namespace rodsea
