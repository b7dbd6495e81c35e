#pragma once
/// @file PluginLoader.h
/// Finds backend plugins on disk and loads them into a BackendRegistry.
///
/// A backend named `foo` lives in a module named `tessera_backend_foo.so`. The
/// loader searches, in order:
/// 1. directories the host adds with addSearchDirectory (tessera-demo's
///    `--plugin-dir`);
/// 2. each entry of the `TESSERA_PLUGIN_DIR` environment variable
///    (colon-separated): a directory of plugins, or one plugin file;
/// 3. `tessera/` next to the library that holds this loader
///    (libtessera_core.so, found with dladdr): the build tree's `lib/tessera`
///    and an install's `<libdir>/tessera` alike, wherever the game's
///    executable is;
/// 4. the plugin directory of the install this library was built for (the
///    package exports it as `TESSERA_PLUGIN_DIR`).
///
/// An entry of `TESSERA_PLUGIN_DIR` that does not exist, or a file in it that
/// is not a plugin, is an error naming the path, not a silent skip: a user who
/// set the variable meant it.

#include "tessera/backend/BackendRegistry.h"
#include "tessera/core/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tessera::backend {

class PluginLoader {
public:
    /// Builds the default search path (environment, library-relative, install).
    PluginLoader();

    /// Searched before the defaults, in the order added.
    void addSearchDirectory(std::filesystem::path dir);
    /// User directories first, then the defaults (duplicates removed).
    std::vector<std::filesystem::path> searchDirectories() const;

    /// Every `tessera_backend_*.so` in the search path, first occurrence of
    /// each file name winning, after the plugin files named in
    /// `TESSERA_PLUGIN_DIR`.
    std::vector<std::filesystem::path> discover() const;

    /// Loads the plugin that provides `name` into `registry`. The error names
    /// the backend, the directories searched and the backends that exist, or
    /// the `TESSERA_PLUGIN_DIR` entry that is wrong.
    Status loadBackend(const std::string& name, BackendRegistry& registry) const;

    /// Loads every discovered plugin. Plugins that fail, and wrong
    /// `TESSERA_PLUGIN_DIR` entries, are reported in the returned list (one
    /// message each) and skipped; the rest still load.
    std::vector<Error> loadAll(BackendRegistry& registry) const;

    /// The plugin file name for a backend name.
    static std::string moduleFileName(const std::string& backendName);

    /// The directory next to libtessera_core.so that holds its plugins.
    static std::filesystem::path libraryPluginDirectory();
    /// The plugin directory of the install this library was configured for.
    static std::filesystem::path installPluginDirectory();

private:
    std::vector<std::filesystem::path> mUserDirs;
    std::vector<std::filesystem::path> mDefaultDirs;
    std::vector<std::filesystem::path> mEnvFiles; ///< plugin files named in TESSERA_PLUGIN_DIR
    std::vector<Error> mEnvErrors;                ///< TESSERA_PLUGIN_DIR entries that do not exist
};

} // namespace tessera::backend
