#pragma once
// Runs the data-parallel step's kernels on a CUDA device: HostExecutor's interface
// (engine/parallel/host_executor.hpp) over device memory, one kernel launch per launch(), CUB's
// radix sort, scan and reductions (deterministic: no floating-point atomics). Every call is
// ordered on the default stream; the few values the host needs (sums, flags, the colour ranges)
// are copied back synchronously.
#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_reduce.cuh>
#include <cub/device/device_scan.cuh>
#include <cub/device/device_segmented_reduce.cuh>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rodsea::cuda {

inline void check(cudaError_t status, const char* what) {
    if (status != cudaSuccess)
        throw std::runtime_error(std::string("rodsea GPU backend: ") + what + ": " +
                                 cudaGetErrorString(status));
}

template <class Kernel>
__global__ void run_kernel(Kernel kernel, std::uint32_t n) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) kernel(i);
}

template <class T>
__global__ void fill_kernel(T* data, std::uint32_t n, T value) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) data[i] = value;
}

class CudaExecutor {
  public:
    // Device memory; resize() drops the contents when it grows.
    template <class T>
    class Array {
      public:
        Array() = default;
        Array(const Array&) = delete;
        Array& operator=(const Array&) = delete;
        Array(Array&& o) noexcept
            : data_(std::exchange(o.data_, nullptr)),
              size_(std::exchange(o.size_, 0)),
              capacity_(std::exchange(o.capacity_, 0)) {}
        Array& operator=(Array&& o) noexcept {
            std::swap(data_, o.data_);
            std::swap(size_, o.size_);
            std::swap(capacity_, o.capacity_);
            return *this;
        }
        ~Array() { cudaFree(data_); }

        void resize(std::size_t n) {
            if (n <= capacity_) {
                size_ = n;
                return;
            }
            T* grown = nullptr;
            check(cudaMalloc(&grown, n * sizeof(T)), "cudaMalloc");
            cudaFree(data_);
            data_ = grown;
            size_ = capacity_ = n;
        }
        std::size_t size() const { return size_; }
        T* data() { return data_; }
        const T* data() const { return data_; }

      private:
        T* data_ = nullptr;
        std::size_t size_ = 0, capacity_ = 0;
    };

    CudaExecutor() = default;
    CudaExecutor(CudaExecutor&& o) noexcept
        : scratch_(std::exchange(o.scratch_, nullptr)),
          scratch_bytes_(std::exchange(o.scratch_bytes_, 0)),
          sorted_keys_(std::move(o.sorted_keys_)),
          sorted_values_(std::move(o.sorted_values_)),
          segment_offsets_(std::move(o.segment_offsets_)),
          uploaded_offsets_(std::move(o.uploaded_offsets_)),
          segment_max_(std::move(o.segment_max_)),
          segment_sum_(std::move(o.segment_sum_)) {}
    CudaExecutor& operator=(CudaExecutor&&) = delete;
    ~CudaExecutor() { cudaFree(scratch_); }

    void set_threads(int) {}  // the device's threads are not the host's

    template <class Kernel>
    void launch(std::size_t n, const Kernel& kernel) const {
        if (n == 0) return;
        const auto count = static_cast<std::uint32_t>(n);
        run_kernel<<<(count + kBlock - 1) / kBlock, kBlock>>>(kernel, count);
        check(cudaGetLastError(), "kernel launch");
    }

    void finish() const { check(cudaDeviceSynchronize(), "kernel"); }

    template <class T>
    void fill(Array<T>& a, std::size_t n, const T& value) const {
        if (n == 0) return;
        const auto count = static_cast<std::uint32_t>(n);
        fill_kernel<<<(count + kBlock - 1) / kBlock, kBlock>>>(a.data(), count, value);
        check(cudaGetLastError(), "fill");
    }

    std::uint64_t exclusive_scan(const Array<std::uint32_t>& in, Array<std::uint32_t>& out,
                                 std::size_t n) {
        if (n == 0) return 0;
        std::size_t bytes = 0;
        check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, in.data(), out.data(),
                                            static_cast<int>(n)),
              "scan");
        check(cub::DeviceScan::ExclusiveSum(scratch(bytes), bytes, in.data(), out.data(),
                                            static_cast<int>(n)),
              "scan");
        return std::uint64_t{read(out, n - 1)} + read(in, n - 1);
    }

    // LSD radix sort: stable, so equal keys keep their order.
    void sort_by_key(Array<std::uint32_t>& keys, Array<std::uint32_t>& values, std::size_t n,
                     int bits) {
        if (n == 0) return;
        sorted_keys_.resize(n);
        sorted_values_.resize(n);
        std::size_t bytes = 0;
        const auto count = static_cast<int>(n);
        check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, keys.data(), sorted_keys_.data(),
                                              values.data(), sorted_values_.data(), count, 0, bits),
              "sort");
        check(
            cub::DeviceRadixSort::SortPairs(scratch(bytes), bytes, keys.data(), sorted_keys_.data(),
                                            values.data(), sorted_values_.data(), count, 0, bits),
            "sort");
        check(cudaMemcpy(keys.data(), sorted_keys_.data(), n * sizeof(std::uint32_t),
                         cudaMemcpyDeviceToDevice),
              "sort copy");
        check(cudaMemcpy(values.data(), sorted_values_.data(), n * sizeof(std::uint32_t),
                         cudaMemcpyDeviceToDevice),
              "sort copy");
    }

    // out[s] = the largest of a[offsets[s] .. offsets[s + 1]), 0 for none (the values are >= 0).
    void segmented_max(const Array<double>& a, const std::vector<std::uint32_t>& offsets,
                       std::vector<double>& out) {
        segmented(a, offsets, out, segment_max_, [&](void* scratch, std::size_t& bytes) {
            return cub::DeviceSegmentedReduce::Max(scratch, bytes, a.data(), segment_max_.data(),
                                                   segments(offsets), segment_offsets_.data(),
                                                   segment_offsets_.data() + 1);
        });
        for (double& m : out)
            if (m < 0.0) m = 0.0;  // an empty segment's maximum is the lowest double
    }
    // out[s] = the sum of a[offsets[s] .. offsets[s + 1]); integers, exact in any order.
    void segmented_sum(const Array<std::uint32_t>& a, const std::vector<std::uint32_t>& offsets,
                       std::vector<std::uint64_t>& out) {
        std::vector<unsigned long long> sums;
        segmented(a, offsets, sums, segment_sum_, [&](void* scratch, std::size_t& bytes) {
            return cub::DeviceSegmentedReduce::Sum(scratch, bytes, a.data(), segment_sum_.data(),
                                                   segments(offsets), segment_offsets_.data(),
                                                   segment_offsets_.data() + 1);
        });
        out.assign(sums.begin(), sums.end());
    }

    template <class T>
    void upload(Array<T>& a, const std::vector<T>& from) const {
        a.resize(from.size());
        if (!from.empty())
            check(
                cudaMemcpy(a.data(), from.data(), from.size() * sizeof(T), cudaMemcpyHostToDevice),
                "upload");
    }
    template <class T>
    void download(const Array<T>& a, std::size_t n, std::vector<T>& to) const {
        download(a, 0, n, to);
    }
    template <class T>
    void download(const Array<T>& a, std::size_t first, std::size_t n, std::vector<T>& to) const {
        to.resize(n);
        if (n > 0)
            check(cudaMemcpy(to.data(), a.data() + first, n * sizeof(T), cudaMemcpyDeviceToHost),
                  "download");
    }
    template <class T>
    T read(const Array<T>& a, std::size_t i) const {
        T value;
        check(cudaMemcpy(&value, a.data() + i, sizeof(T), cudaMemcpyDeviceToHost), "read");
        return value;
    }

  private:
    static constexpr std::uint32_t kBlock = 256;

    // CUB's temporary storage. Never null: CUB takes a null pointer as a query for the size.
    void* scratch(std::size_t bytes) {
        bytes = bytes > 0 ? bytes : 1;
        if (bytes > scratch_bytes_) {
            cudaFree(scratch_);
            scratch_ = nullptr;
            check(cudaMalloc(&scratch_, bytes), "cudaMalloc");
            scratch_bytes_ = bytes;
        }
        return scratch_;
    }

    int segments(const std::vector<std::uint32_t>& offsets) {
        return static_cast<int>(offsets.size() - 1);
    }
    // Uploads the offsets, runs `reduce` (CUB's two calls: size, then work) into `result` and
    // copies the per-segment values back.
    template <class In, class T, class Reduce>
    void segmented(const Array<In>&, const std::vector<std::uint32_t>& offsets, std::vector<T>& out,
                   Array<T>& result, Reduce reduce) {
        out.clear();
        if (offsets.size() < 2) return;
        if (offsets != uploaded_offsets_) {  // a step's reductions share their segments
            upload(segment_offsets_, offsets);
            uploaded_offsets_ = offsets;
        }
        result.resize(offsets.size() - 1);
        std::size_t bytes = 0;
        check(reduce(nullptr, bytes), "segmented reduce");
        check(reduce(scratch(bytes), bytes), "segmented reduce");
        download(result, offsets.size() - 1, out);
    }

    void* scratch_ = nullptr;
    std::size_t scratch_bytes_ = 0;
    Array<std::uint32_t> sorted_keys_, sorted_values_;
    Array<std::uint32_t> segment_offsets_;
    std::vector<std::uint32_t> uploaded_offsets_;  // what segment_offsets_ holds
    Array<double> segment_max_;
    Array<unsigned long long> segment_sum_;
};

}  // namespace rodsea::cuda
