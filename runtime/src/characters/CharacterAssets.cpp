#include "tessera/runtime/CharacterAssets.h"

#include "world/ContentLocator.h"
#include "tessera/assets/GltfLoader.h"
#include "tessera/character/AnimatedBounds.h"
#include "tessera/profiler/CpuScope.h"

#include <algorithm>

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
