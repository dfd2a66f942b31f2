#pragma once
// The output directory of a new run (rodsea run CONFIG, rodsea run --continue): refused when it
// holds anything but with --overwrite, created, and removed again when the start fails before
// its first checkpoint.
#include <filesystem>
#include <system_error>

namespace rodsea {

// The same path for two spellings of one directory (relative, with `..`, through a link), for
// comparing directories; the lexical form where the file system cannot tell.
std::filesystem::path directory_key(const std::filesystem::path& dir);
// Refuses (InvalidParameter naming --out) a directory that holds anything unless `overwrite`;
// FileError for a path that is not a directory.
void check_output_directory(const std::filesystem::path& dir, bool overwrite);
// Creates the directory; true when it did not exist. FileError when it cannot.
bool create_output_directory(const std::filesystem::path& dir);
// What --overwrite removes: only the files a run writes and the analysis of them (rodsea
// analyze's RUN_DIR/analysis/, which would otherwise describe the old run); anything else stays.
void remove_run_files(const std::filesystem::path& dir);

// A start that fails before its first checkpoint (the build runs out of memory, a signal during
// the build, a full disk at the first frame) leaves nothing to resume: a directory it created
// goes with it.
class RemoveUnlessStarted {
  public:
    RemoveUnlessStarted(std::filesystem::path dir, bool armed)
        : dir_(std::move(dir)), armed_(armed) {}
    RemoveUnlessStarted(const RemoveUnlessStarted&) = delete;
    RemoveUnlessStarted& operator=(const RemoveUnlessStarted&) = delete;
    ~RemoveUnlessStarted() {
        std::error_code ignored;
        if (armed_) std::filesystem::remove_all(dir_, ignored);
    }
    void started() { armed_ = false; }

  private:
    std::filesystem::path dir_;
    bool armed_;
};

}  // namespace rodsea
