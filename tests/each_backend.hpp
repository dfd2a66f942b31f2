#pragma once
// Runs a physics test on every backend: the CPU's, the GPU's algorithm on the host, and the GPU
// itself where this build and machine have one (it skips, saying why, elsewhere).
//
//   class Collisions : public testing::EachBackend {};
//   TEST_P(Collisions, ...) { Simulation sim(params, bodies, options()); ... }
//   RODSEA_ON_EACH_BACKEND(Collisions);
#include <gtest/gtest.h>

#include <string>

#include "rodsea/engine/backend_factory.hpp"

namespace rodsea::testing {

class EachBackend : public ::testing::TestWithParam<BackendKind> {
  protected:
    void SetUp() override {
        if (GetParam() != BackendKind::gpu) return;
        const GpuAvailability gpu = gpu_availability();
        if (!gpu.usable) GTEST_SKIP() << "no GPU backend here: " << gpu.description;
    }
    BackendOptions options(int threads = 1) const {
        BackendOptions o;
        o.threads = threads;
        o.backend = GetParam();
        return o;
    }
};

inline std::string backend_test_name(const ::testing::TestParamInfo<BackendKind>& info) {
    std::string name = to_string(info.param);
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

}  // namespace rodsea::testing

#define RODSEA_ON_EACH_BACKEND(fixture)                                                   \
    INSTANTIATE_TEST_SUITE_P(                                                             \
        Backends, fixture,                                                                \
        ::testing::Values(::rodsea::BackendKind::cpu, ::rodsea::BackendKind::gpu_on_host, \
                          ::rodsea::BackendKind::gpu),                                    \
        ::rodsea::testing::backend_test_name)
