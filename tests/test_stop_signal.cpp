// What a run does when asked to stop by a signal: the handler's contract, in a child process each
// (gtest death tests), since a signal that kills would take the test binary with it.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

#include "rodsea/cli/stop_signal.hpp"

namespace rodsea {
namespace {

// One request to stop often arrives twice within milliseconds (the terminal's process group and
// a campaign runner passing it on): the repeat must not kill the run before its checkpoint.
TEST(StopSignalDeathTest, ARepeatWithinASecondIsTheSameRequestAndTheRunLivesOn) {
    EXPECT_EXIT(
        {
            const StopSignalGuard guard;
            std::raise(SIGINT);
            std::raise(SIGINT);
            std::raise(SIGTERM);
            std::_Exit(stop_signal_received() == SIGINT ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

// Ctrl-C again once the first one has had time to be seen is meant: it kills, as the default
// action does, for a user who does not want to wait for the checkpoint.
TEST(StopSignalDeathTest, ASecondCtrlCMoreThanASecondLaterKills) {
    EXPECT_EXIT(
        {
            const StopSignalGuard guard;
            std::raise(SIGINT);
            std::this_thread::sleep_for(std::chrono::milliseconds(1200));
            std::raise(SIGINT);
            std::_Exit(0);
        },
        ::testing::KilledBySignal(SIGINT), "");
}

// Once the guard is gone (the command finished), the process's previous handlers are back.
TEST(StopSignalDeathTest, TheGuardRestoresTheDefaultActionWhenItEnds) {
    EXPECT_EXIT(
        {
            { const StopSignalGuard guard; }
            std::raise(SIGTERM);
            std::_Exit(0);
        },
        ::testing::KilledBySignal(SIGTERM), "");
}

}  // namespace
}  // namespace rodsea
