#include "tessera/runtime/CharacterAssets.h"

#include "world/ContentLocator.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/character/AnimatedBounds.h"
#include "tessera/character/ImpostorBaker.h"
#include "tessera/character/ImpostorFile.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <glm/geometric.hpp>

namespace tessera::runtime {
namespace {

float meanEdgeLength(const character::CageMesh& cage) {
    double sum = 0.0;
    const size_t n = cage.indices.size();
    for (size_t t = 0; t + 2 < n; t += 3)
        for (int e = 0; e < 3; ++e)
            sum += glm::distance(cage.vertices[cage.indices[t + e]].position,
                                 cage.vertices[cage.indices[t + (e + 1) % 3]].position);
    return n ? float(sum / double(n)) : 0.0f;
}

// The impostor file the content build writes beside a character: its path
// with the extension .impostor, for .glb and .gltf files; empty otherwise.
std::filesystem::path impostorFileOf(const std::string& file) {
    std::filesystem::path path(file);
    std::string extension = path.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".glb" && extension != ".gltf") return {};
    return path.replace_extension(".impostor");
}

// Whether `atlas` (read from `path`) was baked from `entry` as it loaded:
// the file checks the layout itself; the layers follow the clips and the
// sphere follows the animated box, so a file left from another version of
// the character is found stale.
Status matches(const character::ImpostorAtlas& atlas, const CrowdAsset& entry, const std::filesystem::path& path) {
    const uint32_t layers = character::impostorLayerCount(uint32_t(entry.asset.clips.size()));
    if (atlas.layers != layers)
        return fail(path.string(), ": ", std::to_string(atlas.layers), " layers, the character's ",
                    std::to_string(entry.asset.clips.size()), " clips need ", std::to_string(layers));
    const character::ImpostorSphere sphere = character::impostorSphere(entry.box);
    if (atlas.centreY != sphere.centreY || atlas.radius != sphere.radius)
        return fail(path.string(), ": framed for another sphere than the character's (a stale file)");
    return {};
}

character::ImpostorAtlas loadImpostors(const CrowdAsset& entry) {
    TESSERA_CPU_SCOPE("load.impostors");
    const std::filesystem::path path = impostorFileOf(entry.file);
    std::error_code ec;
    if (!path.empty() && std::filesystem::exists(path, ec)) {
        auto read = character::readImpostorFile(path);
        Status usable = read ? matches(read.value(), entry, path) : Status(read.error());
        if (usable) return std::move(read.value());
        log::warning(usable.error().message + "; baking the impostors at load instead");
    }
    return character::bakeImpostors(entry.asset);
}

} // namespace

int findClip(const character::CharacterAsset& asset, const char* name) {
    for (size_t i = 0; i < asset.clips.size(); ++i)
        if (asset.clips[i].name == name) return int(i);
    return asset.clips.empty() ? -1 : 0;
}

Status CharacterAssets::add(const std::string& file) {
    TESSERA_CPU_SCOPE("load.character");
    auto loaded = assets::loadCharacter(file);
    if (!loaded) return loaded.error();
    CrowdAsset entry;
    entry.file = file;
    entry.asset = std::move(loaded.value());
    if (entry.asset.cage.indices.empty()) return fail(file, ": has no triangles to draw");
    entry.box = character::animatedBounds(entry.asset);
    entry.meanEdge = meanEdgeLength(entry.asset.cage);
    entry.impostor = loadImpostors(entry);
    mAssets.push_back(std::move(entry));
    return {};
}

Status CharacterAssets::addFroblins(const std::string& contentDir, uint32_t count) {
    for (uint32_t seed = 1; seed <= std::min(count, kFroblinSeeds); ++seed) {
        auto file = locateContent(contentDir, "characters/froblin_" + std::to_string(seed) + ".glb");
        if (!file) return file.error();
        if (Status ok = add(file.value().string()); !ok) return ok;
    }
    return {};
}

} // namespace tessera::runtime
