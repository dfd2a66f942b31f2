#pragma once
// Files that are never seen half-written: written to a temporary name in the same directory
// (<path>.tmp.<pid>), flushed to disk, then renamed over the target (rename is atomic on POSIX
// file systems).
#include <filesystem>
#include <functional>
#include <string>

namespace rodsea {

// Writes `text` to `path` atomically. Throws FileError naming the path on any failure (a full
// disk included); the previous content of `path`, if any, is then untouched.
void write_file_atomically(const std::filesystem::path& path, const std::string& text);

// Runs `write(tmp)` to produce the file at a temporary path, makes it durable, then renames
// it onto `path`. On failure the temporary file is removed and the exception passes on.
void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write);

// Removes the temporaries (<name>.tmp.<pid>) that a writer killed before its rename left in
// `dir`, those of processes no longer alive; returns how many. For the one writer of `dir` (the
// run holding its lock) as it starts: a kill -9 leaves a checkpoint.h5.tmp.<pid> behind.
int remove_stale_temporaries(const std::filesystem::path& dir);

// Forces a file's content to disk (fsync), so that a rename that follows cannot expose an
// empty file after a power loss.
void sync_file(const std::filesystem::path& path);

}  // namespace rodsea
