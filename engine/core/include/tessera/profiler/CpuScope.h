#pragma once
/// @file CpuScope.h
/// RAII timing of a CPU scope into a Profiler.
///
/// @code
/// void Terrain::update() {
///     TESSERA_CPU_SCOPE("terrain update");
///     ...
/// }
/// @endcode
///
/// The scope records a CpuEvent when it closes, stamped with the frame that
/// was current when it opened and its nesting depth on this thread. Depth
/// counts every CpuScope open on the thread, whichever profiler it targets.
/// When the profiler is disabled at construction the scope records nothing
/// and costs one relaxed atomic load (plus the call to Profiler::global()).

#include "tessera/profiler/Profiler.h"

#include <cstdint>

namespace tessera::profiler {

class CpuScope {
public:
    /// @param staticName  Must outlive the profiler; only the pointer is kept.
    explicit CpuScope(const char* staticName, Profiler& profiler = Profiler::global())
        : mName(staticName) {
        if (profiler.enabled()) open(profiler);
    }
    ~CpuScope() {
        if (mProfiler != nullptr) close();
    }
    CpuScope(const CpuScope&) = delete;
    CpuScope& operator=(const CpuScope&) = delete;

private:
    // Out of line: the disabled path above stays inlined and tiny.
    void open(Profiler& profiler);
    void close();

    const char* mName;
    Profiler* mProfiler = nullptr;
    uint64_t mFrame = 0;
    uint64_t mStartNs = 0;
    uint32_t mDepth = 0;
};

} // namespace tessera::profiler

#define TESSERA_PROFILER_CONCAT_INNER(a, b) a##b
#define TESSERA_PROFILER_CONCAT(a, b) TESSERA_PROFILER_CONCAT_INNER(a, b)

/// Times the rest of the enclosing block as `name` (a string literal) in
/// Profiler::global(). Several may appear in one block.
#define TESSERA_CPU_SCOPE(name)                                                              \
    ::tessera::profiler::CpuScope TESSERA_PROFILER_CONCAT(tesseraCpuScope, __COUNTER__)(name)
