// The memory this machine can still give a process, for refusing an input
// that announces more than it can hold before anything is allocated.
#pragma once

#include <cstdint>

namespace grainlab {

// MemAvailable of /proc/meminfo in bytes (what the kernel can give without
// swapping); 0 when it cannot be read (then callers check nothing).
std::uint64_t available_memory_bytes();

}  // namespace grainlab
