#pragma once
// Runs the data-parallel step's kernels on the host: each launch a loop over the elements (an
// OpenMP loop on several threads), sorts and scans from the standard library. It is the GPU
// backend's algorithm without a device: what tests run everywhere, and what a device's results
// are checked against. The CUDA executor (engine/cuda/) has the same interface.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace rodsea::parallel {

class HostExecutor {
  public:
    // Memory of this executor: a vector. resize() may drop the contents.
    template <class T>
    class Array {
      public:
        void resize(std::size_t n) { data_.resize(n); }
        std::size_t size() const { return data_.size(); }
        T* data() { return data_.data(); }
        const T* data() const { return data_.data(); }

      private:
        friend class HostExecutor;
        std::vector<T> data_;
    };

    explicit HostExecutor(int threads = 1) : threads_(threads) {}
    void set_threads(int threads) { threads_ = threads; }
    const char* device_name() const { return "host"; }

    template <class Kernel>
    void launch(std::size_t n, const Kernel& kernel) const {
        const auto count = static_cast<std::ptrdiff_t>(n);
        // Below this many elements a thread team costs more than the loop.
        [[maybe_unused]] constexpr std::ptrdiff_t kWorthThreads = 4096;
#pragma omp parallel for schedule(static) \
    num_threads(threads_) if (threads_ > 1 && count >= kWorthThreads)
        for (std::ptrdiff_t i = 0; i < count; ++i)
            kernel(static_cast<std::uint32_t>(i));
    }

    // Waits for the launches so far: they are done when launch() returns.
    void finish() const {}

    template <class T>
    void fill(Array<T>& a, std::size_t n, const T& value) const {
        std::fill_n(a.data_.begin(), n, value);
    }

    // out[i] = in[0] + ... + in[i − 1]; returns the sum of all n.
    std::uint64_t exclusive_scan(const Array<std::uint32_t>& in, Array<std::uint32_t>& out,
                                 std::size_t n) const {
        std::exclusive_scan(in.data_.begin(), in.data_.begin() + static_cast<std::ptrdiff_t>(n),
                            out.data_.begin(), std::uint32_t{0});
        return n == 0 ? 0 : std::uint64_t{out.data_[n - 1]} + in.data_[n - 1];
    }

    // Sorts the first n (key, value) pairs by key, keeping the order of equal keys; keys are
    // below 2^bits (the device's radix sort reads no more).
    void sort_by_key(Array<std::uint32_t>& keys, Array<std::uint32_t>& values, std::size_t n,
                     int /*bits*/) {
        order_.resize(n);
        std::iota(order_.begin(), order_.end(), std::uint32_t{0});
        const std::vector<std::uint32_t>& k = keys.data_;
        std::stable_sort(order_.begin(), order_.end(),
                         [&k](std::uint32_t x, std::uint32_t y) { return k[x] < k[y]; });
        gather(keys.data_, n);
        gather(values.data_, n);
    }

    // out[s] = the largest of a[offsets[s] .. offsets[s + 1]), 0 for none (the values are >= 0).
    void segmented_max(const Array<double>& a, const std::vector<std::uint32_t>& offsets,
                       std::vector<double>& out) const {
        out.assign(offsets.size() - 1, 0.0);
        for (std::size_t s = 0; s + 1 < offsets.size(); ++s)
            for (std::uint32_t i = offsets[s]; i < offsets[s + 1]; ++i)
                out[s] = std::max(out[s], a.data_[i]);
    }
    // out[s] = the sum of a[offsets[s] .. offsets[s + 1]).
    void segmented_sum(const Array<std::uint32_t>& a, const std::vector<std::uint32_t>& offsets,
                       std::vector<std::uint64_t>& out) const {
        out.assign(offsets.size() - 1, 0);
        for (std::size_t s = 0; s + 1 < offsets.size(); ++s)
            for (std::uint32_t i = offsets[s]; i < offsets[s + 1]; ++i)
                out[s] += a.data_[i];
    }

    template <class T>
    void upload(Array<T>& a, const std::vector<T>& from) const {
        a.data_ = from;
    }
    template <class T>
    void download(const Array<T>& a, std::size_t n, std::vector<T>& to) const {
        download(a, 0, n, to);
    }
    template <class T>
    void download(const Array<T>& a, std::size_t first, std::size_t n, std::vector<T>& to) const {
        to.assign(a.data_.begin() + to_end(first), a.data_.begin() + to_end(first + n));
    }

  private:
    static std::ptrdiff_t to_end(std::size_t n) {
        return static_cast<std::ptrdiff_t>(n);
    }
    void gather(std::vector<std::uint32_t>& v, std::size_t n) {
        scratch_.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            scratch_[i] = v[order_[i]];
        std::copy(scratch_.begin(), scratch_.end(), v.begin());
    }

    int threads_;
    std::vector<std::uint32_t> order_, scratch_;
};

}  // namespace rodsea::parallel
