#include "creature/CreatureGenerator.h"

#include "CageBuilder.h"
#include "CreatureRig.h"
#include "CreatureSculpt.h"
#include "CreatureSdf.h"
#include "CreatureTexture.h"
#include "MarchingTetrahedra.h"
#include "SkinDetail.h"
#include "SkinWeights.h"
#include "UvAtlas.h"
#include "UvTangents.h"
#include "creature/CreatureParams.h"
#include "tessera/character/FarMesh.h"

#include <string>

namespace tessera::creature {

namespace {

// Gutter between charts: 10 texels at 2048 (so at least 2 at 512).
constexpr float kAtlasGutter = 10.0f / 2048.0f;

character::CageMesh assembleCage(const IndexedMesh& welded, const UvAtlas& atlas,
                                 const std::vector<VertexWeights>& weights) {
    std::vector<glm::vec3> normals = areaWeightedNormals(welded);
    character::CageMesh cage;
    cage.vertices.resize(atlas.source.size());
    for (size_t i = 0; i < atlas.source.size(); ++i) {
        // Seam copies read the same welded vertex: identical position,
        // normal and skinning on both sides.
        uint32_t s = atlas.source[i];
        character::CageVertex& v = cage.vertices[i];
        v.position = welded.positions[s];
        v.normal = normals[s];
        v.uv = atlas.uvs[i];
        v.joints = weights[s].joints;
        v.weights = weights[s].weights;
    }
    cage.indices = atlas.indices;
    computeTangents(cage);
    return cage;
}

} // namespace

Creature generateCreature(const CreatureOptions& options, const ProgressFn& progress) {
    auto report = [&](const char* stage, float f) {
        if (progress) progress(stage, f);
    };
    CreatureParams params = makeCreatureParams(options.seed);
    CreatureSdf sdf(params);
    SkinDetail skin(params, sdf);

    // The cage comes from the coarse field (no teeth, lids or gear edges:
    // those reach the near tier through the sculpt and its maps).
    // A 7 mm grid resolves the ear tips and fingers for a 5K cage; small
    // cages (tests, previews) do with a coarser one. Where the arms or
    // fingers nearly touch, edge collapses can pinch the surface; a grid a
    // few percent finer or coarser changes the collapse order, so retry.
    float cell = options.cageTriangles >= 3000 ? 0.007f : 0.011f;
    IndexedMesh welded;
    for (float scale : {1.0f, 0.96f, 1.04f, 0.92f, 1.08f, 0.88f}) {
        IndexedMesh dense = marchTetrahedra([&sdf](const glm::vec3& p) { return sdf.coarseDistance(p); }, sdf.boundsMin(),
                                            sdf.boundsMax(), cell * scale, [&](float f) { report("shape", f); });
        report("cage", 0.0f);
        welded = simplifyMesh(keepLargestComponent(dense), options.cageTriangles);
        if (countTopologyDefects(welded) == 0) break;
    }
    report("cage", 0.7f);
    UvAtlas atlas = buildUvAtlas(welded, kAtlasGutter);
    std::vector<VertexWeights> weights = computeSkinWeights(sdf, welded.positions);
    report("cage", 1.0f);

    Creature creature;
    character::CharacterAsset& asset = creature.asset;
    asset.name = "froblin_" + std::to_string(options.seed);
    asset.cage = assembleCage(welded, atlas, weights);
    asset.skeleton = makeSkeleton(params);
    asset.cage.bindings = makeBindings(asset.skeleton);
    asset.clips.push_back(makeWalkClip(params));
    asset.clips.push_back(makeIdleClip(params));
    // The crowd's far tier: the cage simplified to a few hundred triangles
    // with the same palette, made here at content build time so the game
    // loads it instead of simplifying at startup. A generated cage is always
    // valid input; should it ever fail, the loader makes one instead.
    if (Result<character::FarMesh> far = character::simplifyCage(asset.cage); far.ok()) {
        creature.far = far.value();
        asset.farMesh = creature.far->mesh;
    }

    creature.sculpt = makeSculpt(welded, sdf, skin, options.sculptTriangles, [&](float f) { report("sculpt", f); });
    report("texture", 0.0f);
    asset.baseColor = paintBaseColor(asset.cage, sdf, skin, params, options.baseColorSize);
    report("texture", 1.0f);
    return creature;
}

} // namespace tessera::creature
