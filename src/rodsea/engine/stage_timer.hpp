#pragma once
// Adds the wall-clock time of a scope to one stage of a StageProfile. A backend whose work runs
// asynchronously (a device) waits for it before the scope ends.
#include <chrono>

namespace rodsea {

class StageTimer {
  public:
    explicit StageTimer(double& sink) : sink_(sink), start_(std::chrono::steady_clock::now()) {}
    ~StageTimer() {
        sink_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

  private:
    double& sink_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace rodsea
