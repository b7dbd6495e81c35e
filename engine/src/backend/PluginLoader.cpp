#include "tessera/backend/PluginLoader.h"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>

namespace tessera::backend {
namespace {

constexpr const char* kPrefix = "tessera_backend_";
constexpr const char* kSuffix = ".so";

std::filesystem::path executableDirectory() {
    std::error_code ec;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : exe.parent_path();
}

std::string joinPaths(const std::vector<std::filesystem::path>& dirs) {
    std::string out;
    for (const auto& d : dirs) out += (out.empty() ? "" : ", ") + d.string();
    return out;
}

} // namespace

PluginLoader::PluginLoader() {
    if (const char* env = std::getenv("TESSERA_PLUGIN_PATH")) {
        std::stringstream stream(env);
        std::string item;
        while (std::getline(stream, item, ':'))
            if (!item.empty()) mDefaultDirs.emplace_back(item);
    }
    if (auto exeDir = executableDirectory(); !exeDir.empty())
        mDefaultDirs.push_back((exeDir / ".." / "lib" / "tessera").lexically_normal());
}

void PluginLoader::addSearchDirectory(std::filesystem::path dir) { mUserDirs.push_back(std::move(dir)); }

std::vector<std::filesystem::path> PluginLoader::searchDirectories() const {
    auto dirs = mUserDirs;
    dirs.insert(dirs.end(), mDefaultDirs.begin(), mDefaultDirs.end());
    return dirs;
}

std::string PluginLoader::moduleFileName(const std::string& backendName) {
    return kPrefix + backendName + kSuffix;
}

std::vector<std::filesystem::path> PluginLoader::discover() const {
    std::vector<std::filesystem::path> found;
    std::set<std::string> seen;
    for (const auto& dir : searchDirectories()) {
        std::error_code ec;
        std::vector<std::filesystem::path> inDir;
        for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
            const std::string file = entry.path().filename().string();
            if (file.rfind(kPrefix, 0) == 0 && file.size() > 3 && file.ends_with(kSuffix)) inDir.push_back(entry.path());
        }
        std::sort(inDir.begin(), inDir.end()); // directory order is unspecified
        for (auto& p : inDir)
            if (seen.insert(p.filename().string()).second) found.push_back(p);
    }
    return found;
}

Status PluginLoader::loadBackend(const std::string& name, BackendRegistry& registry) const {
    if (registry.contains(name)) return {};
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
    for (const auto& p : discover()) {
        std::string stem = p.filename().string();
        stem = stem.substr(std::string(kPrefix).size(), stem.size() - std::string(kPrefix).size() - 3);
        available += (available.empty() ? "" : ", ") + stem;
    }
    return fail("unknown backend \"", name, "\": no ", file, " in ", joinPaths(searchDirectories()),
                "; available backends: ", available.empty() ? "(none found)" : available);
}

std::vector<Error> PluginLoader::loadAll(BackendRegistry& registry) const {
    std::vector<Error> errors;
    for (const auto& path : discover()) {
        auto library = PluginLibrary::open(path);
        if (!library) {
            errors.push_back(library.error());
            continue;
        }
        if (auto added = registry.addPlugin(*library); !added) errors.push_back(added.error());
    }
    return errors;
}

} // namespace tessera::backend
