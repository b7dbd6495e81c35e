#pragma once
/// @file ProcessMemory.h
/// What the soak tests measure of the process's own memory.

#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <malloc.h>

namespace tessera::test {

/// Heap bytes in use (malloc's own count: allocated and not freed, whatever
/// the allocator keeps mapped), the measure of a leak; the resident set
/// also moves with fragmentation and the driver's caches.
inline uint64_t heapBytes() {
    const struct mallinfo2 info = mallinfo2();
    return uint64_t(info.uordblks) + uint64_t(info.hblkhd);
}

/// The resident set (/proc/self/statm), in bytes.
inline uint64_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    uint64_t size = 0, resident = 0;
    statm >> size >> resident;
    return resident * uint64_t(sysconf(_SC_PAGESIZE));
}

} // namespace tessera::test
