// The CUDA executor's collective operations against the host executor's, on random data: the
// parts of the GPU backend that only a device runs (warp-aggregated maxima, a launch's tail run by
// its last block, launches counted by a number on the device, recorded graphs). Skips, saying why,
// where no CUDA device can be used.
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "rodsea/engine/cuda/cuda_executor.cuh"
#include "rodsea/engine/parallel/atomics.hpp"
#include "rodsea/engine/parallel/host_executor.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

bool no_device(std::string& why) {
    int devices = 0;
    if (cudaGetDeviceCount(&devices) == cudaSuccess && devices > 0) return false;
    why = std::string("no usable CUDA device here (") + cudaGetErrorString(cudaGetLastError()) +
          "): compiled, not run";
    return true;
}

// Each element's value joins the maximum of its group (groups of uneven, unaligned lengths, so
// that warps hold one group, several, or part of one); each element adds 1 to its group's count.
struct GroupMaxima {
    const double* value;
    const std::uint32_t* group;
    std::uint64_t* max_bits;
    std::uint64_t* count;

    RODSEA_HD void operator()(std::uint32_t i) const {
        parallel::atomic_max_of(max_bits + group[i], value[i]);
        parallel::atomic_add(count + group[i], std::uint64_t{1});
    }
};

// out[i] = 3 in[i] + 1 for the first *n elements.
struct Affine {
    const std::uint32_t* in;
    std::uint32_t* out;

    RODSEA_HD void operator()(std::uint32_t i) const { out[i] = 3 * in[i] + 1; }
};

// written[i] = in[i] + 7, then, as the launch's tail, total[j] = the sum of written[i] over
// i ≡ j (mod tails): the tail must see every element's write.
struct Written {
    const std::uint32_t* in;
    std::uint64_t* written;

    RODSEA_HD void operator()(std::uint32_t i) const { written[i] = in[i] + 7u; }
};
struct SumWritten {
    const std::uint64_t* written;
    std::uint64_t* total;
    std::uint32_t elements, tails;

    RODSEA_HD void operator()(std::uint32_t j) const {
        std::uint64_t sum = 0;
        for (std::uint32_t i = j; i < elements; i += tails)
            sum += written[i];
        total[j] = sum;
    }
};
constexpr std::uint32_t kTails = 300;  // more than a block's threads: they take several each

// The inputs, on both executors.
template <class Exec>
struct Inputs {
    typename Exec::template Array<double> value;
    typename Exec::template Array<std::uint32_t> group, counts, n, out;
    typename Exec::template Array<std::uint64_t> max_bits, count, written, total;
};

template <class Exec>
void fill(Exec& exec, Inputs<Exec>& in, std::uint32_t elements, std::uint32_t groups,
          std::uint32_t counted) {
    SplitMix64 rng(17);
    std::vector<double> value(elements);
    std::vector<std::uint32_t> group(elements), counts(elements);
    std::uint32_t g = 0, left = 1;
    for (std::uint32_t i = 0; i < elements; ++i) {
        if (--left == 0 && g + 1 < groups) {
            ++g;
            left = 1 + static_cast<std::uint32_t>(rng.next() % 90);
        }
        group[i] = g;
        value[i] = i % 97 == 5 ? -0.0 : rng.uniform(0.0, 1e3);  // −0 counts as +0
        counts[i] = static_cast<std::uint32_t>(rng.next() % 1000);
    }
    exec.upload(in.value, value);
    exec.upload(in.group, group);
    exec.upload(in.counts, counts);
    in.written.resize(elements);
    in.total.resize(kTails);
    exec.fill(in.total, kTails, std::uint64_t{0});
    in.out.resize(elements);
    exec.fill(in.out, elements, 0u);
    in.max_bits.resize(groups);
    in.count.resize(groups);
    exec.fill(in.max_bits, groups, std::uint64_t{0});
    exec.fill(in.count, groups, std::uint64_t{0});
    exec.upload(in.n, std::vector<std::uint32_t>{counted});
}

template <class Exec>
void run_all(Exec& exec, Inputs<Exec>& in, std::uint32_t elements) {
    exec.launch(elements,
                GroupMaxima{in.value.data(), in.group.data(), in.max_bits.data(), in.count.data()});
    exec.launch_then(elements, Written{in.counts.data(), in.written.data()}, kTails,
                     SumWritten{in.written.data(), in.total.data(), elements, kTails});
    exec.launch_counted(elements, in.n.data(), Affine{in.group.data(), in.out.data()});
}

template <class T, class Exec, class Array>
std::vector<T> back(const Exec& exec, const Array& a, std::size_t n) {
    std::vector<T> v;
    exec.download(a, n, v);
    return v;
}

TEST(ExecutorOnTheDevice, CollectiveOperationsGiveTheHostsResults) {
    std::string why;
    if (no_device(why)) GTEST_SKIP() << why;
    const std::uint32_t elements = 300'001, groups = 5000, counted = 123'457;
    parallel::HostExecutor host;
    cuda::CudaExecutor device;
    Inputs<parallel::HostExecutor> h;
    Inputs<cuda::CudaExecutor> d;
    fill(host, h, elements, groups, counted);
    fill(device, d, elements, groups, counted);
    for (int round = 0; round < 3; ++round) {  // the tail's count of blocks starts again at 0
        SCOPED_TRACE("round " + std::to_string(round));
        run_all(host, h, elements);
        run_all(device, d, elements);
        EXPECT_EQ((back<std::uint64_t>(device, d.max_bits, groups)),
                  (back<std::uint64_t>(host, h.max_bits, groups)));
        EXPECT_EQ((back<std::uint64_t>(device, d.count, groups)),
                  (back<std::uint64_t>(host, h.count, groups)));
        EXPECT_EQ((back<std::uint64_t>(device, d.total, kTails)),
                  (back<std::uint64_t>(host, h.total, kTails)));
        EXPECT_EQ((back<std::uint32_t>(device, d.out, elements)),
                  (back<std::uint32_t>(host, h.out, elements)));
    }
    EXPECT_GT((back<std::uint64_t>(host, h.total, kTails))[0], 0u);
}

// A recorded graph replays what it recorded: the same launches as run singly, to the bit.
TEST(ExecutorOnTheDevice, AReplayedGraphDoesWhatItsLaunchesDo) {
    std::string why;
    if (no_device(why)) GTEST_SKIP() << why;
    const std::uint32_t elements = 50'000, groups = 700, counted = 40'000;
    cuda::CudaExecutor plain, recorded;
    Inputs<cuda::CudaExecutor> p, r;
    fill(plain, p, elements, groups, counted);
    fill(recorded, r, elements, groups, counted);
    run_all(plain, p, elements);
    run_all(recorded, r, elements);
    cuda::CudaExecutor::Graph graph;
    ASSERT_TRUE(recorded.begin_capture());
    run_all(recorded, r, elements);
    ASSERT_TRUE(recorded.end_capture(graph));
    run_all(plain, p, elements);
    recorded.replay(graph);
    EXPECT_EQ((back<std::uint64_t>(recorded, r.count, groups)),
              (back<std::uint64_t>(plain, p.count, groups)));
    EXPECT_EQ((back<std::uint64_t>(recorded, r.max_bits, groups)),
              (back<std::uint64_t>(plain, p.max_bits, groups)));
    EXPECT_EQ((back<std::uint64_t>(recorded, r.total, kTails)),
              (back<std::uint64_t>(plain, p.total, kTails)));
}

}  // namespace
}  // namespace rodsea
