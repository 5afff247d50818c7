// Reads MemAvailable (kB) from /proc/meminfo.
#include "core/available_memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace grainlab {

std::uint64_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream s(line.substr(13));
    std::uint64_t kib = 0;
    s >> kib;
    return kib * 1024;
  }
  return 0;
}

}  // namespace grainlab
