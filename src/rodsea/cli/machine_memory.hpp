#pragma once
// How much memory this process may still use: the kernel's estimate of memory available
// without swapping (/proc/meminfo MemAvailable), capped by a cgroup's limit (a batch job's
// allocation: cgroup v2 memory.max less memory.current). A run or an analysis that needs more is
// refused before it starts, instead of dying in std::bad_alloc or at the hands of the OOM killer.
#include <cstdint>
#include <optional>

namespace rodsea {

// Bytes available, or none where the system does not say (not Linux).
std::optional<std::uint64_t> available_memory_bytes();

}  // namespace rodsea
