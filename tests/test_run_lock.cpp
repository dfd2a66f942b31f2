#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "rodsea/error.hpp"
#include "rodsea/io/run_lock.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using rodsea::run_directory_in_use;
using rodsea::RunDirectoryLock;
using rodsea::ScratchDir;

// One writer per run directory. flock locks belong to an open file description, so a second
// lock taken in this process conflicts with the first exactly as another process's would.
TEST(RunDirectoryLock, ASecondWriterIsRefusedAndTheProbeSeesTheFirst) {
    const ScratchDir scratch("run-lock");
    const fs::path dir = scratch.path();
    EXPECT_FALSE(run_directory_in_use(dir));  // no run has started in it: no lock file
    {
        const RunDirectoryLock first(dir);
        EXPECT_TRUE(run_directory_in_use(dir));
        try {
            const RunDirectoryLock second(dir);
            FAIL() << "a second writer was let in";
        } catch (const rodsea::InvalidParameter& e) {
            EXPECT_NE(std::string(e.what()).find("another rodsea process is running in it"),
                      std::string::npos)
                << e.what();
        }
        // The probe took nothing from the holder: still held, by the first alone.
        EXPECT_TRUE(run_directory_in_use(dir));
    }
    // Released with its holder; the probes held it only while they looked: a writer gets it.
    EXPECT_FALSE(run_directory_in_use(dir));
    const RunDirectoryLock again(dir);
    EXPECT_TRUE(run_directory_in_use(dir));
}
