#pragma once
// What a checkpoint must satisfy before a run continues from it (rodsea run --resume, rodsea run
// --continue), checked before any file is touched; each refusal names the file and what is wrong.
#include <filesystem>
#include <optional>
#include <string>

#include "rodsea/config/run_plan.hpp"
#include "rodsea/io/checkpoint.hpp"

namespace rodsea {

// The bodies its config asks for, species by species (what any checkpoint must hold, Python's
// save_checkpoint's included).
void check_checkpoint_bodies(const Checkpoint& c, const RunPlan& plan,
                             const std::filesystem::path& path);
// check_checkpoint_bodies, and a time-series interval its config's recorder can continue (a run's
// checkpoint).
void check_checkpoint(const Checkpoint& c, const RunPlan& plan, const std::filesystem::path& path);
// A state the engine could have produced (finite, between the plates, no gross overlap).
void check_checkpoint_state(const Checkpoint& c, const RunPlan& plan,
                            const std::filesystem::path& path);
// The plan of a run given a new length (--duration, --steady-samples), checked against what the
// run has done.
RunPlan extended_plan(const Checkpoint& c, std::optional<double> duration,
                      std::optional<long long> steady_samples, const std::filesystem::path& path);
// That the checkpoint counts the frames its (possibly extended) plan has written by its step.
void check_frames_counted(const Checkpoint& c, const RunPlan& plan, bool extending,
                          const std::filesystem::path& path);

// A checkpoint in `dir` resumes only the run it was written by: the trajectory's run id, the config
// stored in the trajectory and in config.toml (or, during an extension not yet written to
// every file, the config it extends), the frames it counts, and a state that the engine could
// have produced. Checked before any file is touched; every refusal names the file and what
// differs.
void check_checkpoint_belongs(const std::filesystem::path& dir, const Checkpoint& c,
                              const RunPlan& plan);

// A continuation (rodsea run --continue) holds its run's frames from its first on, and stopping
// when steady judges the run's whole series: InvalidParameter naming time.steady_samples unless
// it is 0. `where` names the checkpoint or directory.
void refuse_steady_stop(const RunPlan& plan, const std::string& where);

}  // namespace rodsea
