#include "ContentLocator.h"

#include <cstdlib>
#include <vector>

namespace tessera::demo {

Result<std::filesystem::path> locateContent(const std::string& contentDir, const std::string& relative) {
    std::vector<std::filesystem::path> roots;
    if (!contentDir.empty()) roots.emplace_back(contentDir);
    if (const char* env = std::getenv("TESSERA_CONTENT_DIR")) roots.emplace_back(env);
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        roots.push_back(exe.parent_path() / ".." / "content");
        roots.push_back(exe.parent_path() / ".." / "share" / "tessera" / "content");
    }
    std::string searched;
    for (const auto& root : roots) {
        const auto candidate = (root / relative).lexically_normal();
        if (std::filesystem::exists(candidate, ec)) return candidate;
        searched += (searched.empty() ? "" : ", ") + candidate.string();
    }
    return fail("content file ", relative, " not found (looked in ", searched,
                "); build the content with ./tessera build, or pass --content DIR");
}

} // namespace tessera::demo
