#pragma once
// A campaign's directory, the one place its runners, `status` and `collect` meet:
//
//   campaign.toml             the campaign file as given, and
//   scaling.txt               the --scale and --duration it is run at (a later command must agree)
//   runs/<point>/seed<k>.toml the run's config (resolved); compared on every later command
//   runs/<point>/seed<k>/     the run directory (`rodsea run`'s files, progress.txt)
//   runs/<point>/seed<k>.lock held (fcntl) by the runner running it, on any host of a cluster
//   runs/<point>/seed<k>.log  the run's output, every session appended
//   runs/<point>/seed<k>.failed  how it failed, once per failure
//   collected/                what `collect` writes
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/campaign/campaign_points.hpp"
#include "rodsea/io/progress_file.hpp"

namespace rodsea {

struct CampaignPaths {
    std::filesystem::path dir;
    std::filesystem::path config(const CampaignRun& r) const {
        return dir / "runs" / (r.id + ".toml");
    }
    std::filesystem::path run_dir(const CampaignRun& r) const { return dir / "runs" / r.id; }
    std::filesystem::path lock(const CampaignRun& r) const {
        return dir / "runs" / (r.id + ".lock");
    }
    std::filesystem::path log(const CampaignRun& r) const { return dir / "runs" / (r.id + ".log"); }
    std::filesystem::path failures(const CampaignRun& r) const {
        return dir / "runs" / (r.id + ".failed");
    }
    std::filesystem::path collected() const { return dir / "collected"; }
};

// The default directory of a campaign: out/<campaign name>.
std::filesystem::path default_campaign_dir(const Campaign& campaign);

// Makes `dir` this campaign's directory, or checks that it already is: the same scaling, points
// of this campaign (a directory of another's is refused), and for every run already written the
// same config. A changed point is refused by name (nothing is
// written); new points (values added to an axis) are added. Throws InvalidParameter/FileError.
// Extending (`plans_before`: every run's plan at the scaling the directory holds, which the
// caller has checked may be extended to `scaling`), a run's config may instead be its plan
// before, and is rewritten; scaling.txt is written last.
void prepare_campaign_dir(const CampaignPaths& paths, const Campaign& campaign,
                          const CampaignScaling& scaling, const CampaignGrid& grid,
                          const std::vector<RunPlan>& plans,
                          const std::vector<RunPlan>* plans_before = nullptr);

// The --scale and --duration `dir` was started with (scaling.txt); none for a directory that
// holds no campaign yet. Throws FileError for a scaling.txt that is not one.
std::optional<CampaignScaling> read_campaign_scaling(const CampaignPaths& paths);

// Checks, without writing, that `dir` holds this campaign at this scaling (status, collect): its
// points are this campaign's, and every run's stored config is its plan's (`plans`, one per run
// of `grid`), as `prepare_campaign_dir` checks before a run.
void check_campaign_dir(const CampaignPaths& paths, const CampaignScaling& scaling,
                        const CampaignGrid& grid, const std::vector<RunPlan>& plans);

enum class RunState { pending, running, interrupted, done, failed };
const char* to_string(RunState state);

struct RunStatus {
    RunState state = RunState::pending;
    std::optional<RunProgress> progress;
    int failures = 0;
    std::string last_failure;  // the last line of the last failure's message
    // Its last failure was a blow-up (exit 3): resuming repeats the same steps, so it is failed
    // at once, whatever the count, until its config changes.
    bool blew_up = false;
};

// Whether a run's progress says it runs, or ran, to less than `duration` (s): a run of a campaign
// extended since it ended.
bool ends_before(const RunProgress& progress, double duration);

// A run's state from its files: done once its progress says steady, or done at run.duration or
// longer (written after its final checkpoint), running while a runner holds its lock, failed
// after `max_failures`; a run done at a shorter duration (its campaign since extended) is
// interrupted.
RunStatus run_status(const CampaignPaths& paths, const CampaignRun& run, int max_failures = 2);

// An fcntl lock (open-file-description lock, so that no other open of the file in this process
// drops it) on the run's lock file, held while this object lives; `held()` is false when another
// runner has it. fcntl locks work across the hosts of a cluster's NFS or Lustre file system.
class RunClaim {
  public:
    RunClaim(const CampaignPaths& paths, const CampaignRun& run);
    ~RunClaim();
    RunClaim(RunClaim&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
    RunClaim(const RunClaim&) = delete;
    RunClaim& operator=(const RunClaim&) = delete;
    bool held() const { return fd_ >= 0; }

  private:
    int fd_ = -1;
};

// What a runner finds to do among `only` (indices into grid.runs; none: every run): the runs
// done, those failed `max_failures` times, and the others, to run, in grid order.
struct CampaignWork {
    std::vector<std::size_t> mine, to_run, failed;
    std::size_t done = 0;
};
CampaignWork campaign_work(const CampaignPaths& paths, const CampaignGrid& grid,
                           const std::optional<std::vector<std::size_t>>& only, int max_failures);

// Appends a failure record (exit code and the message's last lines).
void record_failure(const CampaignPaths& paths, const CampaignRun& run, int exit_code,
                    const std::string& message);

}  // namespace rodsea
