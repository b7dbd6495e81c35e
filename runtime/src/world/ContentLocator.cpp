#include "world/ContentLocator.h"

#include "tessera/core/ModulePath.h"

#include <cstdlib>

#if !defined(TESSERA_LIBRARY_TO_CONTENT) || !defined(TESSERA_INSTALL_CONTENT_DIR)
#error "the content locations must be defined by the build (runtime/CMakeLists.txt)"
#endif

namespace tessera::runtime {

std::vector<std::filesystem::path> contentRoots(const std::string& contentDir) {
    std::vector<std::filesystem::path> roots;
    if (!contentDir.empty()) roots.emplace_back(contentDir);
    if (const char* env = std::getenv("TESSERA_CONTENT_DIR"); env && *env) roots.emplace_back(env);
    // This library, not the executable: a game's executable can be anywhere.
    const std::filesystem::path library = moduleDirectory(reinterpret_cast<const void*>(&contentRoots));
    if (!library.empty()) {
        roots.push_back((library / ".." / "content").lexically_normal());
        roots.push_back((library / TESSERA_LIBRARY_TO_CONTENT).lexically_normal());
    }
    roots.emplace_back(TESSERA_INSTALL_CONTENT_DIR);
    return roots;
}

Result<std::filesystem::path> locateContent(const std::string& contentDir, const std::string& relative) {
    std::string searched;
    for (const auto& root : contentRoots(contentDir)) {
        const auto candidate = (root / relative).lexically_normal();
        std::error_code ec;
        if (std::filesystem::exists(candidate, ec)) return candidate;
        searched += (searched.empty() ? "" : ", ") + candidate.string();
    }
    return fail("content file ", relative, " not found (looked in ", searched,
                "); build the content with ./tessera build, or give the directory it is in");
}

} // namespace tessera::runtime
