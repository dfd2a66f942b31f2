// The CUDA executor's collective operations against the host executor's, on random data: the
// parts of the GPU backend that only a device runs (warp-aggregated maxima, the one-block scan of
// the cells, launches counted by a number on the device, recorded graphs). Skips, saying why,
// where no CUDA device can be used.
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <cstdint>
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

// The inputs, on both executors.
template <class Exec>
struct Inputs {
    typename Exec::template Array<double> value;
    typename Exec::template Array<std::uint32_t> group, counts, starts, flag, n, out;
    typename Exec::template Array<std::uint64_t> max_bits, count, wide, wide_scan;
};

template <class Exec>
void fill(Exec& exec, Inputs<Exec>& in, std::uint32_t elements, std::uint32_t groups,
          std::uint32_t counted, std::uint32_t flag) {
    SplitMix64 rng(17);
    std::vector<double> value(elements);
    std::vector<std::uint32_t> group(elements), counts(elements);
    std::vector<std::uint64_t> wide(elements);
    std::uint32_t g = 0, left = 1;
    for (std::uint32_t i = 0; i < elements; ++i) {
        if (--left == 0 && g + 1 < groups) {
            ++g;
            left = 1 + static_cast<std::uint32_t>(rng.next() % 90);
        }
        group[i] = g;
        value[i] = i % 97 == 5 ? -0.0 : rng.uniform(0.0, 1e3);  // −0 counts as +0
        counts[i] = static_cast<std::uint32_t>(rng.next() % 7);
        wide[i] = (std::uint64_t{counts[i] % 3} << 32) | (rng.next() % 5);
    }
    exec.upload(in.value, value);
    exec.upload(in.group, group);
    exec.upload(in.counts, counts);
    exec.upload(in.wide, wide);
    in.starts.resize(elements + 1);
    in.wide_scan.resize(elements);
    in.out.resize(elements);
    exec.fill(in.out, elements, 0u);
    in.max_bits.resize(groups);
    in.count.resize(groups);
    exec.fill(in.max_bits, groups, std::uint64_t{0});
    exec.fill(in.count, groups, std::uint64_t{0});
    exec.upload(in.flag, std::vector<std::uint32_t>{flag});
    exec.upload(in.n, std::vector<std::uint32_t>{counted});
}

template <class Exec>
void run_all(Exec& exec, Inputs<Exec>& in, std::uint32_t elements) {
    exec.launch(elements,
                GroupMaxima{in.value.data(), in.group.data(), in.max_bits.data(), in.count.data()});
    exec.flagged_scan_and_clear(in.flag.data(), in.counts, in.starts, elements);
    exec.exclusive_scan(in.wide, in.wide_scan, elements);
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
    for (const std::uint32_t flag : {0u, 1u}) {
        SCOPED_TRACE(flag ? "flag set" : "flag clear");
        parallel::HostExecutor host;
        cuda::CudaExecutor device;
        Inputs<parallel::HostExecutor> h;
        Inputs<cuda::CudaExecutor> d;
        fill(host, h, elements, groups, counted, flag);
        fill(device, d, elements, groups, counted, flag);
        run_all(host, h, elements);
        run_all(device, d, elements);
        EXPECT_EQ((back<std::uint64_t>(device, d.max_bits, groups)),
                  (back<std::uint64_t>(host, h.max_bits, groups)));
        EXPECT_EQ((back<std::uint64_t>(device, d.count, groups)),
                  (back<std::uint64_t>(host, h.count, groups)));
        EXPECT_EQ((back<std::uint32_t>(device, d.counts, elements)),
                  (back<std::uint32_t>(host, h.counts, elements)));
        if (flag) {
            EXPECT_EQ((back<std::uint32_t>(device, d.starts, elements + 1)),
                      (back<std::uint32_t>(host, h.starts, elements + 1)));
        }
        EXPECT_EQ((back<std::uint64_t>(device, d.wide_scan, elements)),
                  (back<std::uint64_t>(host, h.wide_scan, elements)));
        EXPECT_EQ((back<std::uint32_t>(device, d.out, elements)),
                  (back<std::uint32_t>(host, h.out, elements)));
    }
}

// A recorded graph replays what it recorded: the same launches as run singly, to the bit.
TEST(ExecutorOnTheDevice, AReplayedGraphDoesWhatItsLaunchesDo) {
    std::string why;
    if (no_device(why)) GTEST_SKIP() << why;
    const std::uint32_t elements = 50'000, groups = 700, counted = 40'000;
    cuda::CudaExecutor plain, recorded;
    Inputs<cuda::CudaExecutor> p, r;
    fill(plain, p, elements, groups, counted, 1);
    fill(recorded, r, elements, groups, counted, 1);
    run_all(plain, p, elements);  // sizes the scans' scratch before anything is recorded
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
    EXPECT_EQ((back<std::uint32_t>(recorded, r.starts, elements + 1)),
              (back<std::uint32_t>(plain, p.starts, elements + 1)));
}

}  // namespace
}  // namespace rodsea
