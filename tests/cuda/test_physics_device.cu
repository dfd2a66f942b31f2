// The per-element physics of engine/physics/ compiled by nvcc and run in a kernel, against the
// same functions run on the host: one physics, two executors. Skips, saying why, where no CUDA
// device can be used; where nvcc exists the build compiles it whatever the machine.
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rodsea/engine/physics/contact_geometry.hpp"
#include "rodsea/engine/physics/free_flight.hpp"
#include "rodsea/engine/physics/impulse.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/engine/physics/rigid_rotation.hpp"
#include "rodsea/engine/physics/sphere_placement.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

// One case: a body to fly, spheres to place, a contact to build and resolve, a noise sign.
struct Case {
    Vec3 x, v, w;
    Quat q;
    physics::Rotor rotor;
    double reach2;
    Vec3 offsets[3];
    int axis;
    Vec3 other;  // a second sphere's centre, for a contact with the first
};

// Everything each function returned, on one executor.
struct Result {
    Vec3 x, v, w;
    Quat q;
    physics::PlanarSpeed2 speed;
    Vec3 spheres[3];
    bool touching;
    Contact contact;
    Contact plate;
    Vec3 impulse;
    double sign;
    physics::PlateState plates;
    Vec3 image;
};

RODSEA_HD void evaluate(const Case& c, const StepContext& step, Result& r) {
    r.x = c.x, r.v = c.v, r.w = c.w, r.q = c.q;
    r.speed = physics::planar_speed2(r.v, r.q, r.w, c.rotor, c.reach2);
    physics::fly_freely(r.x, r.v, r.q, r.w, c.rotor, step.dt, step.gravity, step.drop(), step.box);
    physics::place_spheres(r.spheres, c.offsets, 3, r.x, r.q, c.axis);
    r.touching = physics::sphere_sphere_contact(r.spheres[0] - c.other, 0, r.spheres[0], 0.4, r.x,
                                                1, c.other, 0.4, c.x, r.contact);
    const physics::PlateOverlaps o = physics::plate_overlaps(r.spheres[1].z, 0.5, step.plates);
    r.plate = physics::plate_contact(0, r.spheres[1], 0.5, r.x, true, o.base, {0.03, 0.1});
    const Mat3 inverse = physics::world_inverse_inertia(r.q, c.rotor.inverse);
    const Mat3 k = physics::collision_matrix(1.0, inverse, r.plate.arm_a, 0.0, Mat3::zero(), {});
    const Vec3 u = physics::point_velocity(r.v, r.w, r.plate.arm_a) - Vec3{0.0, 0.0, 30.0};
    r.impulse = physics::stronge_impulse(u, r.plate.normal, k, 0.3, 0.3).p;
    r.sign = physics::noise_sign(step.seed, step.step, 7, kBasePlate);
    r.plates = physics::plate_state({0.0435, 1256.6, 1.4}, c.x.x * 1e-3);
    r.image = step.box.minimum_image(c.other - c.x);
}

__global__ void evaluate_all(const Case* cases, StepContext step, Result* results, int n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) evaluate(cases[i], step, results[i]);
}

std::vector<Case> random_cases(int n) {
    SplitMix64 rng(11);
    std::vector<Case> cases(n);
    const Vec3 inertias[3] = {{0.2, 1.1, 1.1}, {0.6, 0.6, 0.6}, {0.7, 1.3, 2.2}};
    for (int i = 0; i < n; ++i) {
        Case& c = cases[i];
        c.x = {rng.uniform(-5, 25), rng.uniform(-5, 25), rng.uniform(0.3, 1.0)};
        c.v = {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
        c.w = {rng.uniform(-300, 300), rng.uniform(-300, 300), rng.uniform(-300, 300)};
        c.q = normalized(
            Quat{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
        c.rotor = physics::make_rotor(inertias[i % 3]);
        c.reach2 = 4.0;
        c.axis = i % 4 == 3 ? -1 : 0;
        c.offsets[0] = {-1.0, 0.0, 0.0}, c.offsets[1] = {0.3, 0.0, 0.0};
        c.offsets[2] = {1.2, c.axis < 0 ? 0.4 : 0.0, 0.0};
        c.other = c.x + Vec3{rng.uniform(-1.6, -0.4), rng.uniform(-0.3, 0.3), 0.0};
    }
    return cases;
}

// The device may fuse a multiply and an add into one rounding (FMA), the host compiler does not:
// the two agree to round-off, a few ulps per operation over ~300 operations.
void expect_close(double host, double device, const char* what, int i) {
    EXPECT_NEAR(device, host, 1e-12 * std::max(1.0, std::abs(host))) << what << " case " << i;
}
void expect_close(const Vec3& host, const Vec3& device, const char* what, int i) {
    for (int k = 0; k < 3; ++k)
        expect_close(host[k], device[k], what, i);
}

TEST(PhysicsOnTheDevice, EveryFunctionGivesTheHostsResultToRoundOff) {
    int devices = 0;
    if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0)
        GTEST_SKIP() << "no usable CUDA device here (" << cudaGetErrorString(cudaGetLastError())
                     << "): the kernel was compiled, not run";
    const int n = 4096;
    const std::vector<Case> cases = random_cases(n);
    StepContext step;
    step.dt = 1.25e-6;
    step.gravity = 9810.0;
    step.box = {20.0, 20.0};
    step.plates = {0.04, 1.44, -12.0};
    step.seed = 3;
    step.step = 99;
    Case* d_cases = nullptr;
    Result* d_results = nullptr;
    ASSERT_EQ(cudaMalloc(&d_cases, n * sizeof(Case)), cudaSuccess);
    ASSERT_EQ(cudaMalloc(&d_results, n * sizeof(Result)), cudaSuccess);
    cudaMemcpy(d_cases, cases.data(), n * sizeof(Case), cudaMemcpyHostToDevice);
    evaluate_all<<<(n + 127) / 128, 128>>>(d_cases, step, d_results, n);
    ASSERT_EQ(cudaDeviceSynchronize(), cudaSuccess);
    std::vector<Result> device(n);
    cudaMemcpy(device.data(), d_results, n * sizeof(Result), cudaMemcpyDeviceToHost);
    cudaFree(d_cases);
    cudaFree(d_results);
    for (int i = 0; i < n; ++i) {
        Result host;
        evaluate(cases[i], step, host);
        const Result& d = device[i];
        expect_close(host.x, d.x, "position", i);
        expect_close(host.v, d.v, "velocity", i);
        expect_close(host.w, d.w, "spin", i);
        expect_close(Vec3{host.q.x, host.q.y, host.q.z}, Vec3{d.q.x, d.q.y, d.q.z}, "q", i);
        expect_close(host.speed.turn2, d.speed.turn2, "speed bound", i);
        for (int s = 0; s < 3; ++s)
            expect_close(host.spheres[s], d.spheres[s], "sphere", i);
        ASSERT_EQ(host.touching, d.touching) << "case " << i;
        if (host.touching) expect_close(host.contact.arm_a, d.contact.arm_a, "arm", i);
        expect_close(host.plate.arm_a, d.plate.arm_a, "plate arm", i);
        expect_close(host.impulse, d.impulse, "impulse", i);
        EXPECT_EQ(host.sign, d.sign) << "integer hash, the same bits";
        expect_close(host.plates.base_z, d.plates.base_z, "base", i);
        expect_close(host.image, d.image, "minimum image", i);
    }
}

}  // namespace
}  // namespace rodsea
