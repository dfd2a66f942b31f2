#pragma once
// The trajectory file, laid out after H5MD 1.1 (https://www.nongnu.org/h5md/) so that h5py,
// MDAnalysis (with convert_units=False: mm is not among its units) and other H5MD readers find
// their way around it:
//
//   /h5md                       version = [1, 1]; author, creator (rodsea + version)
//   /particles/bodies/box       dimension = 3, boundary = [periodic, periodic, none],
//                               edges/{step, time, value}: (L_x, L_y, w) per frame (mm)
//   /particles/bodies/{position, orientation, velocity, angular_velocity}/{step, time, value}
//                               one frame per output interval; value is float32 [frames, N, 3|4]
//   /particles/bodies/species   [N] int32 index into /parameters/rodsea/species (fixed in time)
//   /observables/<name>/{step, time, value}   the scalar time series, one row per frame
//   /parameters/rodsea          version, config (the full resolved TOML), units, run_id,
//                               first_frame; species/<i>/... with each species' sphere offsets
//                               and radii, mass and inertia
//
// Every "value" and "time" carries a `unit` attribute (mm, mm s-1, rad s-1, s, ...).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"

namespace rodsea {

// A named scalar column of the time series with its unit ("1" for dimensionless).
struct SeriesColumn {
    std::string name;
    std::string unit;
};

// Where a file's frames sit in their run. A run continued from its checkpoint alone in another
// directory (rodsea run --continue) keeps its run id and writes a new file whose first frame is
// frame `first_frame` of the whole run: the frames before it stay with the run's earlier files.
struct TrajectorySegment {
    std::string run_id;
    std::uint64_t first_frame = 0;
};

class TrajectoryFile {
  public:
    // Creates (or truncates) `path` and writes everything that does not change in time: a new
    // run's first file (a new run id, first frame 0), or with `segment` the file that continues
    // that run from that frame.
    static TrajectoryFile create(const std::filesystem::path& path, const EngineParameters& params,
                                 const std::vector<std::uint32_t>& species,
                                 const std::string& config_toml,
                                 const std::vector<SeriesColumn>& columns,
                                 const std::optional<TrajectorySegment>& segment = std::nullopt);
    // Reopens a file to continue after its first `frames` frames (counted in this file, not
    // from first_frame()): later frames (written after the checkpoint that is being resumed)
    // are dropped, so none is ever duplicated.
    // `params` are the run's (its box edges go on in every frame).
    static TrajectoryFile reopen(const std::filesystem::path& path, std::uint64_t frames,
                                 const EngineParameters& params,
                                 const std::vector<SeriesColumn>& columns);

    TrajectoryFile(TrajectoryFile&&) noexcept;
    TrajectoryFile& operator=(TrajectoryFile&&) noexcept;
    ~TrajectoryFile();

    // One frame: the bodies and the time-series row. frames() counts it only once all of it
    // is written, so after a failure (a full disk) it still says what is complete.
    void append_frame(std::uint64_t step, double time, const BodyState& bodies,
                      const std::vector<double>& series_row);
    std::uint64_t frames() const;  // in this file
    // The run's frame that is this file's first: 0 but in a continuation (TrajectorySegment).
    std::uint64_t first_frame() const;
    // The identity of this trajectory (/parameters/rodsea attribute run_id: 32 random hex
    // digits drawn at create); a checkpoint carries it so that resume can refuse a checkpoint
    // copied from another run. Empty for a file written before run ids existed.
    const std::string& run_id() const;
    // Makes sure the file can grow by `bytes` before a frame is written, by claiming that many
    // disk blocks beyond its end (fallocate, keeping the size) and checking the process's
    // file-size limit: a full disk, a quota or a limit then fails here, cleanly, and not in the
    // middle of HDF5's own writes, which would leave a file HDF5 cannot open again. Throws
    // FileError naming the file and the reason.
    void reserve(std::uint64_t bytes);
    // Gives back the disk blocks reserve() claimed beyond the file's end: after a failed write,
    // so that a full disk still has room for the checkpoint of the step where the run stopped.
    void release_reserve() noexcept;
    // Replaces the stored config (/parameters/rodsea/config): an extended run's new length.
    void replace_config(const std::string& config_toml);
    void flush();  // makes every appended frame durable before a checkpoint refers to it
    void close();
    // Drops every HDF5 id without closing it, after a failed write (see h5::Handle::release):
    // the file on disk stays as the last successful flush left it.
    void abandon();

  private:
    struct Impl;
    explicit TrajectoryFile(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// The config stored in a trajectory or checkpoint file (for `--resume` and for analysis).
std::string read_stored_config(const std::filesystem::path& path);
// A trajectory's run id (see TrajectoryFile::run_id), read without opening it for writing.
std::string read_run_id(const std::filesystem::path& path);
// A trajectory's first frame in its run (TrajectoryFile::first_frame), read likewise.
std::uint64_t read_first_frame(const std::filesystem::path& path);

}  // namespace rodsea
