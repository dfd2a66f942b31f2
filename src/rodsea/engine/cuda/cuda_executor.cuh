#pragma once
// Runs the data-parallel step's kernels on a CUDA device: HostExecutor's interface
// (engine/parallel/host_executor.hpp) over device memory, one kernel launch per launch(), CUB's
// scans (deterministic: no floating-point atomics). Everything is queued on the executor's own
// stream, which a run of steps can be recorded from as a CUDA graph and replayed; the host waits
// only where it reads memory back (download, read).
#include <cuda_runtime.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cub/block/block_scan.cuh>
#include <cub/device/device_scan.cuh>
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

// kernel(i) for i < *count, a number an earlier kernel wrote: a grid sized for the most there
// can be, each thread taking every stride-th element.
template <class Kernel>
__global__ void run_counted_kernel(Kernel kernel, const std::uint32_t* count) {
    const std::uint32_t n = *count;
    const std::uint32_t stride = gridDim.x * blockDim.x;
    for (std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += stride)
        kernel(i);
}

template <class T>
__global__ void fill_kernel(T* data, std::uint32_t n, T value) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) data[i] = value;
}

// One block scans the cells' counts when the neighbour list is rebuilt (every few hundred
// steps): a block-wide scan per tile of kScanThreads × kScanItems counts, carried from tile to
// tile. When it is not rebuilt the block reads the flag and ends.
constexpr int kScanThreads = 1024;
constexpr int kScanItems = 4;
__global__ void __launch_bounds__(kScanThreads)
    flagged_scan_kernel(const std::uint32_t* flag, std::uint32_t* count, std::uint32_t* start,
                        std::uint32_t n) {
    if (*flag == 0) return;
    using Scan = cub::BlockScan<std::uint32_t, kScanThreads>;
    __shared__ typename Scan::TempStorage temp;
    std::uint32_t carried = 0;
    for (std::uint32_t tile = 0; tile < n; tile += kScanThreads * kScanItems) {
        std::uint32_t items[kScanItems];
        const std::uint32_t first = tile + threadIdx.x * kScanItems;
        for (int j = 0; j < kScanItems; ++j)
            items[j] = first + j < n ? count[first + j] : 0u;
        std::uint32_t tile_total = 0;
        Scan(temp).ExclusiveSum(items, items, tile_total);
        __syncthreads();  // the temporary storage is reused by the next tile
        for (int j = 0; j < kScanItems; ++j)
            if (first + j < n) {
                start[first + j] = carried + items[j];
                count[first + j] = 0;
            }
        carried += tile_total;
    }
    if (threadIdx.x == 0) start[n] = carried;
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

    // A recorded run of launches (a CUDA graph, instantiated), replayed as one launch.
    class Graph {
      public:
        Graph() = default;
        Graph(const Graph&) = delete;
        Graph& operator=(const Graph&) = delete;
        Graph(Graph&& o) noexcept : exec_(std::exchange(o.exec_, nullptr)) {}
        Graph& operator=(Graph&& o) noexcept {
            std::swap(exec_, o.exec_);
            return *this;
        }
        ~Graph() {
            if (exec_ != nullptr) cudaGraphExecDestroy(exec_);
        }

      private:
        friend class CudaExecutor;
        cudaGraphExec_t exec_ = nullptr;
    };

    CudaExecutor() {
        check(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking), "stream");
        int device = 0;
        check(cudaGetDevice(&device), "device");
        check(cudaDeviceGetAttribute(&multiprocessors_, cudaDevAttrMultiProcessorCount, device),
              "device attributes");
    }
    CudaExecutor(CudaExecutor&& o) noexcept
        : stream_(std::exchange(o.stream_, nullptr)),
          multiprocessors_(o.multiprocessors_),
          scratch_(std::exchange(o.scratch_, nullptr)),
          scratch_bytes_(std::exchange(o.scratch_bytes_, 0)) {}
    CudaExecutor& operator=(CudaExecutor&&) = delete;
    ~CudaExecutor() {
        cudaFree(scratch_);
        if (stream_ != nullptr) cudaStreamDestroy(stream_);
    }

    void set_threads(int) {}  // the device's threads are not the host's

    template <class Kernel>
    void launch(std::size_t n, const Kernel& kernel) const {
        if (n == 0) return;
        const auto count = static_cast<std::uint32_t>(n);
        run_kernel<<<(count + kBlock - 1) / kBlock, kBlock, 0, stream_>>>(kernel, count);
        check(cudaGetLastError(), "kernel launch");
    }
    template <class Kernel>
    void launch_counted(std::size_t max_n, const std::uint32_t* count, const Kernel& kernel) const {
        if (max_n == 0) return;
        // Enough blocks to fill the device several times over; more would mostly find no work.
        const std::size_t blocks =
            std::min<std::size_t>((max_n + kBlock - 1) / kBlock, 4 * std::size_t(multiprocessors_));
        run_counted_kernel<<<static_cast<unsigned>(blocks), kBlock, 0, stream_>>>(kernel, count);
        check(cudaGetLastError(), "kernel launch");
    }

    void finish() const { check(cudaStreamSynchronize(stream_), "kernel"); }

    template <class T>
    void fill(Array<T>& a, std::size_t n, const T& value) const {
        if (n == 0) return;
        const auto count = static_cast<std::uint32_t>(n);
        fill_kernel<<<(count + kBlock - 1) / kBlock, kBlock, 0, stream_>>>(a.data(), count, value);
        check(cudaGetLastError(), "fill");
    }
    template <class T>
    void copy(Array<T>& to, const Array<T>& from, std::size_t n) const {
        if (n == 0) return;
        check(cudaMemcpyAsync(to.data(), from.data(), n * sizeof(T), cudaMemcpyDeviceToDevice,
                              stream_),
              "copy");
    }

    // Its scratch is sized by the first call with a given n: a recorded graph's calls allocate
    // nothing (ParallelEnsemble takes a step before it records one).
    template <class T>
    void exclusive_scan(const Array<T>& in, Array<T>& out, std::size_t n) {
        if (n == 0) return;
        std::size_t bytes = 0;
        const auto count = static_cast<int>(n);
        check(cub::DeviceScan::ExclusiveSum(nullptr, bytes, in.data(), out.data(), count, stream_),
              "scan");
        check(cub::DeviceScan::ExclusiveSum(scratch(bytes), bytes, in.data(), out.data(), count,
                                            stream_),
              "scan");
    }
    void flagged_scan_and_clear(const std::uint32_t* flag, Array<std::uint32_t>& count,
                                Array<std::uint32_t>& start, std::size_t n) const {
        flagged_scan_kernel<<<1, kScanThreads, 0, stream_>>>(flag, count.data(), start.data(),
                                                             static_cast<std::uint32_t>(n));
        check(cudaGetLastError(), "scan");
    }

    // Records the launches from here to end_capture() instead of running them; false (and
    // nothing recorded) where the device cannot.
    bool begin_capture() const {
        if (cudaStreamBeginCapture(stream_, cudaStreamCaptureModeThreadLocal) == cudaSuccess)
            return true;
        cudaGetLastError();
        return false;
    }
    bool end_capture(Graph& graph) const {
        cudaGraph_t recorded = nullptr;
        if (cudaStreamEndCapture(stream_, &recorded) != cudaSuccess || recorded == nullptr) {
            cudaGetLastError();
            return false;
        }
        Graph made;
        const cudaError_t status = cudaGraphInstantiate(&made.exec_, recorded, 0);
        cudaGraphDestroy(recorded);
        if (status != cudaSuccess) {
            cudaGetLastError();
            return false;
        }
        graph = std::move(made);
        return true;
    }
    void replay(const Graph& graph) const {
        check(cudaGraphLaunch(graph.exec_, stream_), "graph launch");
    }

    template <class T>
    void upload(Array<T>& a, const std::vector<T>& from) const {
        a.resize(from.size());
        upload_into(a, from);
    }
    template <class T>
    void upload_into(Array<T>& a, const std::vector<T>& from) const {
        if (from.empty()) return;
        check(cudaMemcpyAsync(a.data(), from.data(), from.size() * sizeof(T),
                              cudaMemcpyHostToDevice, stream_),
              "upload");
        finish();  // `from` may go before the copy would otherwise have read it
    }
    template <class T>
    void download(const Array<T>& a, std::size_t n, std::vector<T>& to) const {
        download(a, 0, n, to);
    }
    template <class T>
    void download(const Array<T>& a, std::size_t first, std::size_t n, std::vector<T>& to) const {
        to.resize(n);
        if (n == 0) return;
        check(cudaMemcpyAsync(to.data(), a.data() + first, n * sizeof(T), cudaMemcpyDeviceToHost,
                              stream_),
              "download");
        finish();
    }
    template <class T>
    T read(const Array<T>& a, std::size_t i) const {
        T value;
        check(cudaMemcpyAsync(&value, a.data() + i, sizeof(T), cudaMemcpyDeviceToHost, stream_),
              "read");
        finish();
        return value;
    }

  private:
    static constexpr std::uint32_t kBlock = 256;

    // CUB's temporary storage. Never null: CUB takes a null pointer as a query for the size.
    void* scratch(std::size_t bytes) {
        bytes = bytes > 0 ? bytes : 1;
        if (bytes > scratch_bytes_) {
            finish();  // a scan queued earlier may still use the old storage
            cudaFree(scratch_);
            scratch_ = nullptr;
            check(cudaMalloc(&scratch_, bytes), "cudaMalloc");
            scratch_bytes_ = bytes;
        }
        return scratch_;
    }

    cudaStream_t stream_ = nullptr;
    int multiprocessors_ = 1;
    void* scratch_ = nullptr;
    std::size_t scratch_bytes_ = 0;
};

}  // namespace rodsea::cuda
