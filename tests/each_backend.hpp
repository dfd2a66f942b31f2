#pragma once
// Runs a physics test on every backend: the CPU's, the GPU's algorithm on the host, and the GPU
// itself where this build and machine have one (it skips, saying why, elsewhere); the physics
// tests also on the CPU's coasting step (cpu/coasting_backend.hpp), which is the CPU backend
// (GetParam() is BackendKind::cpu) with BackendOptions::coasting.
//
//   class Collisions : public testing::EachBackend {};
//   TEST_P(Collisions, ...) { Simulation sim(params, bodies, options()); ... }
//   RODSEA_ON_EACH_STEP(Collisions);     // or RODSEA_ON_EACH_BACKEND: without coasting
#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "rodsea/engine/backend_factory.hpp"

namespace rodsea::testing {

// A backend, and for the CPU's whether it coasts; compares as its BackendKind.
struct BackendChoice {
    BackendKind kind = BackendKind::cpu;
    bool coasting = false;
    operator BackendKind() const { return kind; }  // NOLINT: GetParam() == BackendKind::cpu
};

// What a failing test prints for its parameter (gtest would show the struct's bytes).
inline void PrintTo(const BackendChoice& choice, std::ostream* os) {
    *os << to_string(choice.kind) << (choice.coasting ? ", coasting" : "");
}

class EachBackend : public ::testing::TestWithParam<BackendChoice> {
  protected:
    void SetUp() override {
        if (GetParam().kind != BackendKind::gpu) return;
        const GpuAvailability gpu = gpu_availability();
        if (!gpu.usable) GTEST_SKIP() << "no GPU backend here: " << gpu.description;
    }
    BackendOptions options(int threads = 1) const {
        BackendOptions o;
        o.threads = threads;
        o.backend = GetParam().kind;
        o.coasting = GetParam().coasting;
        return o;
    }
};

inline std::string backend_test_name(const ::testing::TestParamInfo<BackendChoice>& info) {
    std::string name = to_string(info.param.kind);
    if (info.param.coasting) name += "_coasting";
    for (char& c : name)
        if (c == '-') c = '_';
    return name;
}

}  // namespace rodsea::testing

#define RODSEA_ON_EACH_BACKEND(fixture)                                                         \
    INSTANTIATE_TEST_SUITE_P(                                                                   \
        Backends, fixture,                                                                      \
        ::testing::Values(::rodsea::testing::BackendChoice{::rodsea::BackendKind::cpu},         \
                          ::rodsea::testing::BackendChoice{::rodsea::BackendKind::gpu_on_host}, \
                          ::rodsea::testing::BackendChoice{::rodsea::BackendKind::gpu}),        \
        ::rodsea::testing::backend_test_name)

#define RODSEA_ON_EACH_STEP(fixture)                                                            \
    INSTANTIATE_TEST_SUITE_P(                                                                   \
        Backends, fixture,                                                                      \
        ::testing::Values(::rodsea::testing::BackendChoice{::rodsea::BackendKind::cpu},         \
                          ::rodsea::testing::BackendChoice{::rodsea::BackendKind::cpu, true},   \
                          ::rodsea::testing::BackendChoice{::rodsea::BackendKind::gpu_on_host}, \
                          ::rodsea::testing::BackendChoice{::rodsea::BackendKind::gpu}),        \
        ::rodsea::testing::backend_test_name)
