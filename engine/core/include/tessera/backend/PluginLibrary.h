#pragma once
/// @file PluginLibrary.h
/// An opened plugin module (dlopen handle). Closing happens when the last
/// owner lets go, after every backend it created has been destroyed.

#include "tessera/core/Result.h"

#include <filesystem>
#include <memory>

namespace tessera::backend {

class PluginLibrary {
public:
    /// Opens the module and resolves its entry point. On failure the message
    /// names the file and says why in plain words: missing file, not a shared
    /// library, a dependency that was not found (with dlerror's text), or an
    /// entry point for another ABI version.
    static Result<std::shared_ptr<PluginLibrary>> open(const std::filesystem::path& path);

    ~PluginLibrary();
    PluginLibrary(const PluginLibrary&) = delete;
    PluginLibrary& operator=(const PluginLibrary&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    /// The resolved `registerPlugin_v<N>` entry point.
    void* entryPoint() const { return mEntry; }

private:
    PluginLibrary(std::filesystem::path path, void* handle, void* entry)
        : mPath(std::move(path)), mHandle(handle), mEntry(entry) {}

    std::filesystem::path mPath;
    void* mHandle = nullptr;
    void* mEntry = nullptr;
};

} // namespace tessera::backend
