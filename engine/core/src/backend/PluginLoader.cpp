#include "tessera/backend/PluginLoader.h"

#include "tessera/core/ModulePath.h"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>

#ifndef TESSERA_INSTALL_PLUGIN_DIR
#error "TESSERA_INSTALL_PLUGIN_DIR must be defined by the build (engine/CMakeLists.txt)"
#endif

namespace tessera::backend {
namespace {

constexpr const char* kPrefix = "tessera_backend_";
constexpr const char* kSuffix = ".so";
constexpr const char* kEnvironment = "TESSERA_PLUGIN_DIR";

std::string joinPaths(const std::vector<std::filesystem::path>& dirs) {
    std::string out;
    for (const auto& d : dirs) out += (out.empty() ? "" : ", ") + d.string();
    return out;
}

bool isPluginName(const std::string& file) {
    return file.rfind(kPrefix, 0) == 0 && file.size() > std::string(kPrefix).size() + 3 && file.ends_with(kSuffix);
}

std::string backendNameOf(const std::filesystem::path& module) {
    const std::string file = module.filename().string();
    return file.substr(std::string(kPrefix).size(), file.size() - std::string(kPrefix).size() - 3);
}

} // namespace

std::filesystem::path PluginLoader::libraryPluginDirectory() {
    // Any function defined in libtessera_core.so names its file.
    const std::filesystem::path dir = moduleDirectory(reinterpret_cast<const void*>(&PluginLoader::moduleFileName));
    return dir.empty() ? dir : dir / "tessera";
}

std::filesystem::path PluginLoader::installPluginDirectory() { return TESSERA_INSTALL_PLUGIN_DIR; }

PluginLoader::PluginLoader() {
    if (const char* env = std::getenv(kEnvironment)) {
        std::stringstream stream(env);
        std::string item;
        while (std::getline(stream, item, ':')) {
            if (item.empty()) continue;
            std::error_code ec;
            const std::filesystem::path path(item);
            if (std::filesystem::is_directory(path, ec)) mDefaultDirs.push_back(path);
            else if (std::filesystem::exists(path, ec)) mEnvFiles.push_back(path);
            else
                mEnvErrors.push_back(Error{std::string(kEnvironment) + " entry " + item +
                                           ": no such directory or plugin file"});
        }
    }
    if (auto dir = libraryPluginDirectory(); !dir.empty()) mDefaultDirs.push_back(dir);
    mDefaultDirs.push_back(installPluginDirectory());
}

void PluginLoader::addSearchDirectory(std::filesystem::path dir) { mUserDirs.push_back(std::move(dir)); }

std::vector<std::filesystem::path> PluginLoader::searchDirectories() const {
    std::vector<std::filesystem::path> dirs;
    std::set<std::filesystem::path> seen;
    auto add = [&](const std::filesystem::path& dir) {
        if (seen.insert(dir.lexically_normal()).second) dirs.push_back(dir);
    };
    for (const auto& d : mUserDirs) add(d);
    for (const auto& d : mDefaultDirs) add(d);
    return dirs;
}

std::string PluginLoader::moduleFileName(const std::string& backendName) {
    return kPrefix + backendName + kSuffix;
}

std::vector<std::filesystem::path> PluginLoader::discover() const {
    std::vector<std::filesystem::path> found = mEnvFiles;
    std::set<std::string> seen;
    for (const auto& file : mEnvFiles) seen.insert(file.filename().string());
    for (const auto& dir : searchDirectories()) {
        std::error_code ec;
        std::vector<std::filesystem::path> inDir;
        for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
            if (isPluginName(entry.path().filename().string())) inDir.push_back(entry.path());
        std::sort(inDir.begin(), inDir.end()); // directory order is unspecified
        for (auto& p : inDir)
            if (seen.insert(p.filename().string()).second) found.push_back(p);
    }
    return found;
}

Status PluginLoader::loadBackend(const std::string& name, BackendRegistry& registry) const {
    if (registry.contains(name)) return {};
    if (!mEnvErrors.empty()) return mEnvErrors.front();
    // Files named in the environment are loaded as they are: one that is not
    // a plugin is the user's mistake to hear about, whatever backend it holds.
    for (const auto& file : mEnvFiles) {
        auto library = PluginLibrary::open(file);
        if (!library) return fail(kEnvironment, ": ", library.error().message);
        if (auto added = registry.addPlugin(*library); !added) return added;
        if (registry.contains(name)) return {};
    }
    const std::string file = moduleFileName(name);
    for (const auto& dir : searchDirectories()) {
        std::error_code ec;
        const auto candidate = dir / file;
        if (!std::filesystem::exists(candidate, ec)) continue;
        auto library = PluginLibrary::open(candidate);
        if (!library) return library.error();
        if (auto added = registry.addPlugin(*library); !added) return added;
        if (!registry.contains(name))
            return fail("plugin ", candidate.string(), ": loaded, but it does not register a backend named \"", name, "\"");
        return {};
    }
    // Not found: say where we looked and what does exist.
    std::string available;
    for (const auto& p : discover())
        if (isPluginName(p.filename().string())) available += (available.empty() ? "" : ", ") + backendNameOf(p);
    return fail("unknown backend \"", name, "\": no ", file, " in ", joinPaths(searchDirectories()),
                "; available backends: ", available.empty() ? "(none found)" : available);
}

std::vector<Error> PluginLoader::loadAll(BackendRegistry& registry) const {
    std::vector<Error> errors = mEnvErrors;
    for (const auto& path : discover()) {
        auto library = PluginLibrary::open(path);
        if (!library) {
            const bool named = std::find(mEnvFiles.begin(), mEnvFiles.end(), path) != mEnvFiles.end();
            errors.push_back(named ? Error{std::string(kEnvironment) + ": " + library.error().message} : library.error());
            continue;
        }
        if (auto added = registry.addPlugin(*library); !added) errors.push_back(added.error());
    }
    return errors;
}

} // namespace tessera::backend
