#include "crowd/SystemInfo.h"

#include <fstream>
#include <sstream>

#include <unistd.h>

namespace tessera::runtime {
namespace {

/// The text after "key" and its colon on the first line of `file` that
/// starts with `key`, trimmed; empty when there is none.
std::string procField(const char* file, const std::string& key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(key, 0) != 0) continue;
        const size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        const size_t begin = line.find_first_not_of(" \t", colon + 1);
        return begin == std::string::npos ? std::string() : line.substr(begin);
    }
    return {};
}

} // namespace

uint64_t availableMemoryBytes() {
    // "MemAvailable:   23456789 kB": the kernel's estimate, page cache it can
    // drop included, which free pages alone would miss.
    std::istringstream field(procField("/proc/meminfo", "MemAvailable"));
    uint64_t kib = 0;
    if (field >> kib) return kib * 1024;
    const long pages = sysconf(_SC_AVPHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
    return pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : 0;
}

std::string cpuModelName() {
    const std::string name = procField("/proc/cpuinfo", "model name");
    return name.empty() ? "unknown" : name;
}

uint32_t onlineCpuCount() {
    const long count = sysconf(_SC_NPROCESSORS_ONLN);
    return count > 0 ? uint32_t(count) : 1u;
}

} // namespace tessera::runtime
