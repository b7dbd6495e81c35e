#pragma once
/// @file PluginLoader.h
/// Finds backend plugins on disk and loads them into a BackendRegistry.
///
/// A backend named `foo` lives in a module named `tessera_backend_foo.so`. The
/// loader searches, in order: directories added with addSearchDirectory (the
/// `--plugin-dir` flag), each entry of the TESSERA_PLUGIN_PATH environment
/// variable (colon-separated), and `<executable dir>/../lib/tessera`, which is
/// where both the build tree and an installed tree keep them.

#include "tessera/backend/BackendRegistry.h"
#include "tessera/core/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tessera::backend {

class PluginLoader {
public:
    /// Builds the default search path (environment, executable-relative).
    PluginLoader();

    /// Searched before the defaults, in the order added.
    void addSearchDirectory(std::filesystem::path dir);
    /// User directories first, then the defaults.
    std::vector<std::filesystem::path> searchDirectories() const;

    /// Every `tessera_backend_*.so` in the search path, first occurrence of
    /// each file name winning.
    std::vector<std::filesystem::path> discover() const;

    /// Loads the plugin that provides `name` into `registry`. The error names
    /// the backend, the directories searched and the backends that exist.
    Status loadBackend(const std::string& name, BackendRegistry& registry) const;

    /// Loads every discovered plugin. Plugins that fail are reported in the
    /// returned list (one message each) and skipped; the rest still load.
    std::vector<Error> loadAll(BackendRegistry& registry) const;

    /// The plugin file name for a backend name.
    static std::string moduleFileName(const std::string& backendName);

private:
    std::vector<std::filesystem::path> mUserDirs;
    std::vector<std::filesystem::path> mDefaultDirs;
};

} // namespace tessera::backend
