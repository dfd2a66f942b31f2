#pragma once
// Runs the data-parallel step's kernels on the host: each launch a loop over the elements (an
// OpenMP loop on several threads), a launch's tail after it. It is the GPU backend's
// algorithm without a device: what tests run everywhere, and what a device's results are
// checked against. The CUDA executor (engine/cuda/) has the same interface.
#include <algorithm>
#include <cstddef>
#include <cstdint>
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

    // A recorded run of launches to replay: the host records none (begin_capture says no).
    struct Graph {};

    explicit HostExecutor(int threads = 1) : threads_(threads) {}
    void set_threads(int threads) { threads_ = threads; }

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
    // kernel(i) for i below *count, a number in this executor's memory that earlier launches
    // wrote (at most max_n).
    template <class Kernel>
    void launch_counted(std::size_t /*max_n*/, const std::uint32_t* count,
                        const Kernel& kernel) const {
        launch(*count, kernel);
    }
    // kernel(i) for i < n, then, once every element is done, tail(j) for j < tail_n: the work
    // of a few elements that needs all of kernel's results (a step's decisions, a system's
    // counts), without a launch of its own.
    template <class Kernel, class Tail>
    void launch_then(std::size_t n, const Kernel& kernel, std::size_t tail_n,
                     const Tail& tail) const {
        launch(n, kernel);
        for (std::size_t j = 0; j < tail_n; ++j)
            tail(static_cast<std::uint32_t>(j));
    }

    // Waits for the launches so far: they are done when launch() returns.
    void finish() const {}

    template <class T>
    void fill(Array<T>& a, std::size_t n, const T& value) const {
        std::fill_n(a.data_.begin(), n, value);
    }
    template <class T>
    void copy(Array<T>& to, const Array<T>& from, std::size_t n) const {
        std::copy_n(from.data_.begin(), n, to.data_.begin());
    }

    bool begin_capture() const {
        return false;
    }
    bool end_capture(Graph&) const {
        return false;
    }
    void replay(const Graph&) const {}

    template <class T>
    void upload(Array<T>& a, const std::vector<T>& from) const {
        a.data_ = from;
    }
    // Into the first from.size() elements of a, which holds at least that many.
    template <class T>
    void upload_into(Array<T>& a, const std::vector<T>& from) const {
        std::copy(from.begin(), from.end(), a.data_.begin());
    }
    template <class T>
    void download(const Array<T>& a, std::size_t n, std::vector<T>& to) const {
        download(a, 0, n, to);
    }
    template <class T>
    void download(const Array<T>& a, std::size_t first, std::size_t n, std::vector<T>& to) const {
        to.assign(a.data_.begin() + to_end(first), a.data_.begin() + to_end(first + n));
    }
    template <class T>
    T read(const Array<T>& a, std::size_t i) const {
        return a.data_[i];
    }

  private:
    static std::ptrdiff_t to_end(std::size_t n) {
        return static_cast<std::ptrdiff_t>(n);
    }

    int threads_;
};

}  // namespace rodsea::parallel
