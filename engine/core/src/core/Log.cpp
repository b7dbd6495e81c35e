#include "tessera/core/Log.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace tessera::log {
namespace {
std::atomic<Level> sLevel{Level::Info};
std::mutex sMutex;
} // namespace

void setLevel(Level level) { sLevel = level; }

void write(Level level, std::string_view message) {
    if (level < sLevel.load()) return;
    static constexpr const char* kPrefix[] = {"debug", "info", "warning", "error"};
    // One fprintf under a lock so lines from worker threads never interleave.
    std::lock_guard lock(sMutex);
    std::fprintf(stderr, "tessera: %s: %.*s\n", kPrefix[static_cast<int>(level)],
                 static_cast<int>(message.size()), message.data());
}

} // namespace tessera::log
