#pragma once
// The engine's threads are OpenMP's. Every parallel stage splits its work into contiguous chunks
// in index order and writes each chunk's output where the serial loop would, so a step gives the
// same bits on any number of threads. These wrappers keep <omp.h> out of the stages.
#include <cstddef>

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

}  // namespace rodsea::cpu
