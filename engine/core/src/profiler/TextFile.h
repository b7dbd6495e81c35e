#pragma once
// Private to the profiler's writers: writes a finished document to disk.

#include "tessera/core/Result.h"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace tessera::profiler::detail {

/// Creates or truncates `path` and writes `text`. Errors name the file and the
/// OS error. Parent directories are not created: a mistyped output folder
/// should fail loudly rather than scatter files.
inline Status writeTextFile(const std::filesystem::path& path, std::string_view text) {
    // fopen rather than ofstream: errno is the only portable way to say *why*
    // a file could not be written ("Permission denied", "No space left").
    auto osError = [] { return std::generic_category().message(errno); };
    std::FILE* file = std::fopen(path.string().c_str(), "wb");
    if (file == nullptr) return fail(path.string(), ": cannot open for writing: ", osError());
    bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    std::string writeError = written ? std::string() : osError();
    // fclose flushes, so a full disk may only show up here.
    bool closed = std::fclose(file) == 0;
    if (!written) return fail(path.string(), ": write failed: ", writeError);
    if (!closed) return fail(path.string(), ": write failed: ", osError());
    return {};
}

} // namespace tessera::profiler::detail
