#pragma once
/// @file SystemInfo.h
/// What the machine offers, for refusing work it cannot hold and for naming
/// it in benchmark reports (Linux: /proc, else POSIX sysconf).

#include <cstdint>
#include <string>

namespace tessera::runtime {

/// Bytes new allocations can take without swapping: /proc/meminfo's
/// MemAvailable, else the free physical pages (sysconf); 0 when unknown.
uint64_t availableMemoryBytes();

/// The CPU's model name (/proc/cpuinfo "model name"), or "unknown".
std::string cpuModelName();

/// Logical processors online (sysconf), at least 1.
uint32_t onlineCpuCount();

} // namespace tessera::runtime
