#pragma once
// A fresh directory per test, removed afterwards: tests that write files never see each
// other's output, also when ctest runs them in parallel.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rodsea {

class ScratchDir {
  public:
    explicit ScratchDir(const std::string& name)
        : path_(std::filesystem::temp_directory_path() /
                ("rodsea-test-" + name + "-" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

// The whole content of a file ("" when it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The temporary files of an atomic write of `target` (<target>.tmp.<pid>) that are left.
inline std::vector<std::filesystem::path> temporaries_of(const std::filesystem::path& target) {
    std::vector<std::filesystem::path> found;
    std::error_code ec;
    const std::string prefix = target.filename().string() + ".tmp";
    for (const auto& e : std::filesystem::directory_iterator(target.parent_path(), ec))
        if (e.path().filename().string().rfind(prefix, 0) == 0) found.push_back(e.path());
    return found;
}

}  // namespace rodsea
