#pragma once
// How much memory this process may still use: the least of the memory the system has available
// (MemAvailable in /proc/meminfo), the cgroup's limit (containers, Slurm jobs) and the address
// space limit (ulimit -v). Used to refuse a model or a run that would not fit, with a message,
// instead of being killed by the kernel or aborting on std::bad_alloc.
#include <cstddef>
#include <optional>

namespace pound::io {

// Bytes, or nothing when the system does not say.
std::optional<std::size_t> available_memory_bytes();

}  // namespace pound::io
