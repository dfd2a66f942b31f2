#pragma once
// Runs the data-parallel step's kernels on a CUDA device: HostExecutor's interface
// (engine/parallel/host_executor.hpp) over device memory, one kernel launch per launch() (a
// launch's tail run by its last block). Everything is queued on the executor's own
// stream, which a run of steps can be recorded from as a CUDA graph and replayed; the host waits
// only where it reads memory back (download, read).
#include <cuda_runtime.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
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

// kernel(i) for i < n, then tail(j) for j < tail_n by the last block to finish: each block's
// first thread counts its block done after a fence (cooperative groups' grid barrier does the
// same), and the block that counts last fences again and runs the tail, which so sees every
// element's writes. It leaves the count at 0 for the next launch (the stream orders them).
template <class Kernel, class Tail>
__global__ void run_kernel_then(Kernel kernel, std::uint32_t n, Tail tail, std::uint32_t tail_n,
                                std::uint32_t* blocks_done) {
    const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) kernel(i);
    __shared__ bool last;
    __syncthreads();
    if (threadIdx.x == 0) {
        __threadfence();
        last = atomicAdd(blocks_done, 1u) == gridDim.x - 1;
        if (last) __threadfence();
    }
    __syncthreads();
    if (!last) return;
    for (std::uint32_t j = threadIdx.x; j < tail_n; j += blockDim.x)
        tail(j);
    if (threadIdx.x == 0) *blocks_done = 0;
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
        check(cudaMalloc(&blocks_done_, sizeof(std::uint32_t)), "cudaMalloc");
        check(cudaMemsetAsync(blocks_done_, 0, sizeof(std::uint32_t), stream_), "cudaMemset");
    }
    CudaExecutor(CudaExecutor&& o) noexcept
        : stream_(std::exchange(o.stream_, nullptr)),
          multiprocessors_(o.multiprocessors_),
          blocks_done_(std::exchange(o.blocks_done_, nullptr)) {}
    CudaExecutor& operator=(CudaExecutor&&) = delete;
    ~CudaExecutor() {
        cudaFree(blocks_done_);
        if (stream_ != nullptr) cudaStreamDestroy(stream_);
    }

    void set_threads(int) {}  // the device's threads are not the host's

    template <class Kernel>
    void launch(std::size_t n, const Kernel& kernel) const {
        if (n == 0) return;
        const auto count = static_cast<std::uint32_t>(n);
        start((count + kBlock - 1) / kBlock, run_kernel<Kernel>, kernel, count);
    }
    template <class Kernel>
    void launch_counted(std::size_t max_n, const std::uint32_t* count, const Kernel& kernel) const {
        if (max_n == 0) return;
        // Enough blocks to fill the device several times over; more would mostly find no work.
        const std::size_t blocks =
            std::min<std::size_t>((max_n + kBlock - 1) / kBlock, 4 * std::size_t(multiprocessors_));
        start(static_cast<std::uint32_t>(blocks), run_counted_kernel<Kernel>, kernel, count);
    }

    template <class Kernel, class Tail>
    void launch_then(std::size_t n, const Kernel& kernel, std::size_t tail_n,
                     const Tail& tail) const {
        const auto count = static_cast<std::uint32_t>(n);
        const std::uint32_t blocks = count > 0 ? (count + kBlock - 1) / kBlock : 1;
        start(blocks, run_kernel_then<Kernel, Tail>, kernel, count, tail,
              static_cast<std::uint32_t>(tail_n), blocks_done_);
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

    // One launch of a step's kernel on the executor's stream, its error checked.
    template <class... Parameters, class... Arguments>
    void start(std::uint32_t blocks, void (*kernel)(Parameters...),
               Arguments&&... arguments) const {
        kernel<<<blocks, kBlock, 0, stream_>>>(std::forward<Arguments>(arguments)...);
        check(cudaGetLastError(), "kernel launch");
    }

    cudaStream_t stream_ = nullptr;
    int multiprocessors_ = 1;
    std::uint32_t* blocks_done_ = nullptr;  // run_kernel_then's count of finished blocks
};

}  // namespace rodsea::cuda
