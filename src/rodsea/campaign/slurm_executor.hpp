#pragma once
// The SLURM executor: a campaign's unfinished runs as one sbatch job array. Each array task runs
// `rodsea campaign run --tasks FILE --task $SLURM_ARRAY_TASK_ID` on its share of runs (one run,
// or `pack` runs, `jobs` at a time or as one ensemble), so everything the local executor guarantees
// holds on the cluster too: locks across hosts, resume from checkpoints, a failure retried once.
// SLURM sends SIGTERM `signal_seconds` before the wall time (--signal=B:TERM@S): every run writes
// its checkpoint and stops. A follow-up job, started when the array has ended
// (--dependency=afterany), submits what is left, `resubmit` times at most.
//
// Files, under DIR/slurm/: array-<k>.sh and tasks-<k>.txt (submission k: the script and its
// tasks' runs, one line per task, run ids separated by tabs), resubmit-<k>.sh, jobs.txt (one
// line per submitted job: "array|resubmit <job id> <k>"), logs/.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include "rodsea/campaign/campaign_store.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea {

struct SlurmOptions {
    std::filesystem::path campaign_file;  // absolute: the jobs run it from any directory
    CampaignScaling scaling;
    std::string partition, account;      // "" : the cluster's default
    std::string time = "24:00:00";       // wall time per task, as sbatch --time takes it
    long time_seconds = 24 * 3600;       // the same, in s
    std::optional<long> signal_seconds;  // SIGTERM this long before the wall time; default
                                         // min(300 s, half the wall time)
    int cpus_per_task = 1;
    int gpus_per_task = 0;
    int throttle = 0;       // array tasks at a time (0: no limit)
    int pack = 1;           // runs per array task
    int jobs = 1;           // runs at a time inside a task, each on cpus_per_task / jobs threads
    bool ensemble = false;  // a task steps its runs as one ensemble on cpus_per_task threads
    std::optional<BackendKind> backend;  // every run's (--backend); none: its run.backend
    int resubmit = 3;                    // follow-up submissions left
    bool retry_failed = false;
    bool dry_run = false;
    std::filesystem::path executable;  // rodsea itself; empty: this process's executable
};

// "90" (minutes), "MM:SS", "HH:MM:SS", "D-HH", "D-HH:MM", "D-HH:MM:SS" (sbatch --time) in s;
// throws InvalidParameter naming `--time`.
long parse_slurm_time(const std::string& text);

// Checks what can be checked before anything is written: sbatch on PATH (unless a dry run), the
// signal's lead time against the wall time. Returns that lead time, s; throws InvalidParameter.
long check_slurm_options(const SlurmOptions& options);

// Submits the runs not yet done (nor failed twice, nor held by a runner, nor in an array still
// queued). Returns an ExitCode: 0 when submitted (or nothing is left), 1 when sbatch refused.
int submit_campaign_to_slurm(const CampaignPaths& paths, const Campaign& campaign,
                             const CampaignGrid& grid, const SlurmOptions& options,
                             std::ostream& out);

// The runs of task `index` of a tasks file, as indices into grid.runs; throws InvalidParameter
// (--tasks, --task) naming an unknown run or a task out of range.
std::vector<std::size_t> runs_of_task(const std::filesystem::path& tasks_file, long index,
                                      const CampaignGrid& grid);

}  // namespace rodsea
