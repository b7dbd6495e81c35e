#include "tessera/backend/CrowdChecks.h"

#include "tessera/character/BakedAnimation.h"
#include "tessera/character/CageMesh.h"
#include "tessera/character/ImpostorAtlas.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace tessera::backend {
namespace {

// An index list over `mesh` (a tier's own triangles over its vertices):
// whole triangles of vertices it has.
Status checkIndices(std::span<const uint32_t> indices, const std::string& whose, const char* meshName,
                    const character::CageMesh& mesh) {
    auto bad = [](const std::string& what) { return Error{"createCrowd: " + what}; };
    if (indices.size() % 3 != 0)
        return bad(whose + " index count (" + std::to_string(indices.size()) + ") is not a multiple of 3");
    for (uint32_t index : indices)
        if (index >= mesh.vertices.size())
            return bad(whose + " index " + std::to_string(index) + " is past its " + meshName + "'s " +
                       std::to_string(mesh.vertices.size()) + " vertices");
    return {};
}

// Creature `index`'s impostor atlas: complete, in this build's layout, with
// a layer per phase of each of its clips in the baked animation (its
// records past the rest pose; the rest pose alone for a creature without
// clips).
Status checkImpostor(const CrowdDesc& desc, size_t index, const std::string& name) {
    auto bad = [](const std::string& what) { return Error{"createCrowd: " + what}; };
    const character::ImpostorAtlas* atlas = desc.characters[index].impostor;
    if (!atlas || atlas->empty()) return bad(name + " has no impostor atlas (character::bakeImpostors)");
    if (atlas->size != TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL)
        return bad(name + ": its impostor atlas's layers are " + std::to_string(atlas->size) +
                   " texels a side, the layout's " + std::to_string(TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL));
    const std::vector<uint32_t>& bases = desc.animation->characterClipBase;
    const size_t first = bases[index];
    const size_t end = index + 1 < bases.size() ? bases[index + 1] : desc.animation->clips.size();
    const size_t clips = end > first + 1 ? end - first - 1 : 0;
    const uint64_t layers = uint64_t(std::max<size_t>(clips, 1)) * TS_IMPOSTOR_PHASES;
    if (atlas->layers != layers)
        return bad(name + ": its impostor atlas has " + std::to_string(atlas->layers) + " layers, its " +
                   std::to_string(clips) + " clips need " + std::to_string(layers) + " (" +
                   std::to_string(TS_IMPOSTOR_PHASES) + " phases each)");
    if (atlas->albedo.size() != TS_IMPOSTOR_MIPS || atlas->normal.size() != TS_IMPOSTOR_MIPS)
        return bad(name + ": its impostor atlas has " + std::to_string(atlas->albedo.size()) + " albedo and " +
                   std::to_string(atlas->normal.size()) + " normal mip levels, the layout " +
                   std::to_string(TS_IMPOSTOR_MIPS));
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m)
        if (atlas->albedo[m].size() != atlas->layerBytes(m) * atlas->layers ||
            atlas->normal[m].size() != atlas->layerBytes(m) * atlas->layers)
            return bad(name + ": its impostor atlas's mip " + std::to_string(m) + " holds " +
                       std::to_string(atlas->albedo[m].size()) + " albedo and " +
                       std::to_string(atlas->normal[m].size()) + " normal bytes, its layers need " +
                       std::to_string(atlas->layerBytes(m) * atlas->layers));
    if (!(atlas->radius > 0.0f) || !std::isfinite(atlas->radius) || !std::isfinite(atlas->centreY))
        return bad(name + ": its impostor atlas's sphere is not finite with a positive radius");
    return {};
}

} // namespace

Status checkCrowdDesc(const CrowdDesc& desc) {
    auto bad = [](const std::string& what) { return Error{"createCrowd: " + what}; };
    if (desc.characters.empty()) return bad("a crowd needs at least one character");
    if (desc.characters.size() > TS_CROWD_MAX_CHARACTERS)
        return bad(std::to_string(desc.characters.size()) + " characters; a crowd mixes at most " +
                   std::to_string(TS_CROWD_MAX_CHARACTERS));
    if (!desc.animation) return bad("no baked animation (character::bakeAnimation, combine)");
    if (desc.animation->characterClipBase.size() != desc.characters.size())
        return bad("the baked animation has " + std::to_string(desc.animation->characterClipBase.size()) +
                   " characters, the crowd " + std::to_string(desc.characters.size()));
    for (size_t i = 0; i < desc.characters.size(); ++i) {
        const CrowdCharacterDesc& c = desc.characters[i];
        const std::string name = "character " + std::to_string(i);
        if (!c.character.valid()) return bad(name + " has no character handle");
        if (!c.cage || c.cage->triangleCount() == 0) return bad(name + " has no cage");
        if (!c.farMesh || c.farMesh->triangleCount() == 0) return bad(name + " has no far mesh");
        if (c.farMesh->bindings.size() != c.cage->bindings.size())
            return bad(name + ": its far mesh has " + std::to_string(c.farMesh->bindings.size()) +
                       " skinning matrices, its cage " + std::to_string(c.cage->bindings.size()));
        if (Status ok = checkIndices(c.middleIndices, name + ": its middle tier's", "cage", *c.cage); !ok) return ok;
        if (Status ok = checkIndices(c.farCasterIndices, name + ": its far casters'", "far mesh", *c.farMesh); !ok)
            return ok;
        if (!(c.levelPerPixel > 0.0f) || !std::isfinite(c.levelPerPixel))
            return bad(name + ": levels per pixel must be a positive number");
        if (Status ok = checkImpostor(desc, i, name); !ok) return ok;
    }
    if (desc.maxInstances == 0) return bad("maxInstances is 0");
    if (desc.maxIds < desc.maxInstances) return bad("maxIds is below maxInstances");
    return {};
}

bool crowdInstanceValid(const shader::CrowdInstance& instance, uint32_t maxIds, uint32_t characters, uint32_t clips) {
    const bool finite = std::isfinite(instance.sphere.x) && std::isfinite(instance.sphere.y) &&
                        std::isfinite(instance.sphere.z) && std::isfinite(instance.sphere.w) &&
                        std::isfinite(instance.animation.x) && std::isfinite(instance.animation.y);
    return finite && instance.sphere.w >= 0.0f && instance.ids.x < maxIds && instance.ids.y < characters &&
           instance.ids.z < clips;
}

} // namespace tessera::backend
