#pragma once
// The engine's threads are OpenMP's. Every parallel stage splits its work into contiguous chunks
// in index order and writes each chunk's output where the serial loop would, so a step gives the
// same bits on any number of threads. These wrappers keep <omp.h> out of the stages.
#include <cstddef>
#include <cstdint>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace rodsea::cpu {

inline int team_size() {
#ifdef _OPENMP
    return omp_get_num_threads();
#else
    return 1;
#endif
}

inline int thread_index() {
#ifdef _OPENMP
    return omp_get_thread_num();
#else
    return 0;
#endif
}

// The t-th of `parts` contiguous, nearly equal chunks of [0, n).
struct Chunk {
    std::size_t begin, end;
};
inline Chunk chunk_of(std::size_t n, int t, int parts) {
    const auto p = static_cast<std::size_t>(parts), i = static_cast<std::size_t>(t);
    return {n * i / p, n * (i + 1) / p};
}

// body(i) for every i in [0, n) on up to `threads` threads, item i on the same thread of the
// team at every call (a static schedule: its data tends to stay in that thread's caches). Only
// for items whose results do not depend on the thread that computes them, such as independent
// systems, and whose own parallel regions (if any) then run on their one thread: libgomp starts
// new threads for every nested team. The body must not throw.
template <class Body>
void for_each_in_parallel(std::size_t n, int threads, const Body& body) {
#ifdef _OPENMP
    if (threads <= 1 || n <= 1) {  // no team to start
        for (std::size_t i = 0; i < n; ++i)
            body(i);
        return;
    }
    const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::int64_t i = 0; i < count; ++i)
        body(static_cast<std::size_t>(i));
#else
    (void)threads;
    for (std::size_t i = 0; i < n; ++i)
        body(i);
#endif
}

}  // namespace rodsea::cpu
