#include "rodsea/run/output_directory.hpp"

#include "rodsea/error.hpp"
#include "rodsea/io/progress_file.hpp"
#include "rodsea/run/run_files.hpp"

namespace rodsea {

namespace {

bool is_empty_directory(const std::filesystem::path& dir) {
    return std::filesystem::is_directory(dir) && std::filesystem::is_empty(dir);
}

}  // namespace

std::filesystem::path directory_key(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::path key = std::filesystem::weakly_canonical(dir, ec);
    return ec ? dir.lexically_normal() : key;
}

void check_output_directory(const std::filesystem::path& dir, bool overwrite) {
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) return;
    if (!std::filesystem::is_directory(dir, ec))
        throw FileError(dir.string(), "exists and is not a directory");
    if (is_empty_directory(dir) || overwrite) return;
    // Without a checkpoint there is nothing --resume could continue.
    const bool resumable = std::filesystem::exists(dir / kCheckpointFile, ec);
    throw InvalidParameter(
        "--out", dir.string(), "a new or empty directory",
        resumable ? "it exists and is not empty: choose another --out, add --overwrite to "
                    "replace its run files, or continue it with rodsea run --resume " +
                        dir.string()
                  : "it exists and is not empty, and has no checkpoint to resume (a run stopped "
                    "before its first checkpoint?): choose another --out, or add --overwrite to "
                    "start again there");
}

bool create_output_directory(const std::filesystem::path& dir) {
    std::error_code ec;
    const bool existed = std::filesystem::exists(dir, ec);
    std::filesystem::create_directories(dir, ec);
    if (ec) throw FileError(dir.string(), "cannot create the output directory: " + ec.message());
    return !existed;
}

void remove_run_files(const std::filesystem::path& dir) {
    std::error_code ec;
    for (const char* name :
         {kConfigFile, kTrajectoryFile, kSeriesFile, kCheckpointFile, kProgressFile})
        std::filesystem::remove(dir / name, ec);
    std::filesystem::remove_all(dir / "analysis", ec);
}

}  // namespace rodsea
