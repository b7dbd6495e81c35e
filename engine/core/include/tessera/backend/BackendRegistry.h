#pragma once
/// @file BackendRegistry.h
/// Backends known to the host, by name, each with the plugin that provides it.

#include "tessera/backend/PluginApi.h"
#include "tessera/backend/PluginLibrary.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tessera::backend {

/// Owns a backend and keeps its plugin module loaded for as long as it lives.
class BackendDeleter {
public:
    BackendDeleter() = default;
    BackendDeleter(void (*destroy)(Backend*), std::shared_ptr<PluginLibrary> library)
        : mDestroy(destroy), mLibrary(std::move(library)) {}
    void operator()(Backend* backend) const;

private:
    void (*mDestroy)(Backend*) = nullptr;
    std::shared_ptr<PluginLibrary> mLibrary;
};

using BackendPtr = std::unique_ptr<Backend, BackendDeleter>;

class BackendRegistry final : public PluginRegistry {
public:
    /// Runs a plugin's entry point against this registry. Fails if the plugin
    /// registers a name that another plugin already registered (the message
    /// names both files), or registers nothing.
    Status addPlugin(const std::shared_ptr<PluginLibrary>& library);

    /// Registers a backend that is linked into the host (used by tests).
    Status addBuiltin(const BackendPluginDesc& desc);

    /// Creates the named backend; the error lists the available names.
    Result<BackendPtr> create(const std::string& name) const;

    bool contains(const std::string& name) const { return mEntries.count(name) != 0; }
    /// Registered names, sorted.
    std::vector<std::string> names() const;
    /// The file a backend came from ("(built in)" for builtins).
    std::string sourceOf(const std::string& name) const;

    void registerBackend(const BackendPluginDesc& desc) override;

private:
    struct Entry {
        BackendPluginDesc desc;
        std::shared_ptr<PluginLibrary> library;
    };
    std::map<std::string, Entry> mEntries;
    // Set while a plugin's entry point runs, so registerBackend knows the source.
    std::shared_ptr<PluginLibrary> mLoading;
    std::vector<std::string> mErrors;
    int mRegisteredByCurrent = 0;
};

} // namespace tessera::backend
