#include "tessera/runtime/InstancedCrowd.h"

#include "world/ShadowCasters.h"

#include "tessera/core/JsonWriter.h"
#include "tessera/profiler/CpuScope.h"

#include <algorithm>
#include <fstream>

namespace tessera::runtime {

Result<std::unique_ptr<InstancedCrowd>> InstancedCrowd::create(const CharacterAssets& assets) {
    TESSERA_CPU_SCOPE("load.crowdBake");
    std::unique_ptr<InstancedCrowd> crowd(new InstancedCrowd());
    std::vector<character::BakedAnimation> parts;
    for (const CrowdAsset& asset : assets.all()) {
        if (!asset.asset.farMesh)
            return Error{asset.file + ": no far mesh for the crowd's far tier (the loader makes one for every glTF)"};
        parts.push_back(character::bakeAnimation(asset.asset));
    }
    crowd->mBaked = character::combine(parts);
    // A million agents' lists cost milliseconds a frame, and the horizon
    // test of the impostors most of the manager's time; only --crowd-tiers
    // reads them (the backends cull the impostors themselves).
    crowd->keepLists(false);
    return crowd;
}

backend::CrowdDesc InstancedCrowd::desc(const CharacterAssets& assets, uint32_t maxAgents,
                                        const lod::LodPolicy& policy) {
    mCharacters.clear();
    mCosts.clear();
    mFarMeshes.clear();
    mSimplifiedFar.clear();
    mSimplifiedFar.reserve(assets.size());
    for (size_t i = 0; i < assets.size(); ++i) {
        // The policy may want a coarser far mesh than the content's (a CPU
        // rasterizer pays for every far triangle): simplified once, here.
        const character::CageMesh& far = *assets[i].asset.farMesh;
        if (policy.farMeshTriangles > 0 && far.triangleCount() > policy.farMeshTriangles) {
            auto coarser = character::simplifyCage(far, {policy.farMeshTriangles});
            if (coarser) {
                mSimplifiedFar.push_back(std::move(coarser.value().mesh));
                mFarMeshes.push_back(&mSimplifiedFar.back());
                continue;
            }
        }
        mFarMeshes.push_back(&far);
    }
    mMiddleIndices.assign(assets.size(), {});
    for (size_t i = 0; i < assets.size(); ++i) {
        // The middle tier may draw fewer of the cage's triangles over the
        // same vertices (and baked animation): a CPU rasterizer pays per
        // triangle, and at the middle tier's sizes the normal map carries
        // the surface's detail. Seam-preserving where meshoptimizer can.
        const character::CageMesh& cage = assets[i].asset.cage;
        if (policy.middleMeshTriangles == 0 || cage.triangleCount() <= policy.middleMeshTriangles) continue;
        auto coarser = character::simplifyCage(cage, {policy.middleMeshTriangles, 0.05f});
        if (coarser) mMiddleIndices[i] = std::move(coarser.value().cageIndices);
    }
    mFarCasterIndices.assign(assets.size(), {});
    for (size_t i = 0; i < assets.size(); ++i) {
        // The far tier's shadow casters: depth only, so neither seams nor
        // normals bind the simplification; a silhouette a few texels wide
        // keeps its shape within a tenth of the creature's extent.
        const character::CageMesh& far = *mFarMeshes[i];
        if (policy.farCasterTriangles == 0 || far.triangleCount() <= policy.farCasterTriangles) continue;
        auto coarser = character::simplifyCage(far, {policy.farCasterTriangles, 0.1f});
        if (coarser) mFarCasterIndices[i] = std::move(coarser.value().cageIndices);
    }
    for (size_t i = 0; i < assets.size(); ++i) {
        const CrowdAsset& asset = assets[i];
        // The instance's sphere is the box's around its centre: levels per
        // pixel of that sphere give an edge of about targetEdgePixels.
        const float radius = std::max(glm::length(asset.box.extents()), 1e-6f);
        lod::LodCharacter cost;
        cost.levelPerPixel = lod::LodCharacter::levelPerPixelFor(asset.meanEdge, radius, policy.targetEdgePixels);
        cost.cageTriangles = asset.asset.cage.triangleCount();
        cost.middleTriangles = mMiddleIndices[i].empty() ? cost.cageTriangles : uint32_t(mMiddleIndices[i].size() / 3);
        cost.farTriangles = mFarMeshes[i]->triangleCount();
        mCosts.push_back(cost);
        backend::CrowdCharacterDesc character;
        character.character = assets.handle(i);
        character.cage = &asset.asset.cage;
        character.farMesh = mFarMeshes[i];
        character.middleIndices = mMiddleIndices[i];
        character.farCasterIndices = mFarCasterIndices[i];
        character.impostor = &asset.impostor;
        character.levelPerPixel = cost.levelPerPixel;
        mCharacters.push_back(character);
    }
    const uint32_t nearSlots = policy.budget.maxNearInstances;
    backend::CrowdDesc desc;
    desc.characters = mCharacters;
    desc.animation = &mBaked;
    desc.maxInstances = maxAgents;
    desc.maxIds = maxAgents;
    desc.nearSlots = std::min(nearSlots, maxAgents);
    return desc;
}

uint32_t InstancedCrowd::bakedClip(uint32_t asset, int clip) const {
    return mBaked.globalClip(asset, clip >= 0 ? character::bakedClipIndex(uint32_t(clip)) : character::kBakedRestPose);
}

void InstancedCrowd::begin(size_t count) {
    mInstances.resize(count);
    mLodInstances.resize(count);
}

void InstancedCrowd::set(size_t i, const shader::CrowdInstance& instance) {
    mInstances[i] = instance;
    mLodInstances[i] = {instance.sphere, instance.ids.x, instance.ids.y};
}

void InstancedCrowd::setHorizon(const terrain::Terrain& terrain) {
    mOccluderGrid = terrain.bounds().horizonGrid(TS_CROWD_MAX_OCCLUDER_CELLS, mOccluders);
}

const lod::LodFrame& InstancedCrowd::select(const lod::LodView& view, const lod::LodPolicy& policy) {
    TESSERA_CPU_SCOPE("crowd.lod");
    mLod.setPolicy(policy);
    lod::LodView withHorizon = view;
    if (policy.horizonCulling) {
        withHorizon.occluders = mOccluders;
        withHorizon.occluderGrid = mOccluderGrid;
    }
    return mLod.update(mLodInstances, mCosts, withHorizon);
}

backend::CrowdDrawInfo InstancedCrowd::drawInfo(bool displacement, bool lodColors) const {
    backend::CrowdDrawInfo draw;
    draw.instances = mInstances;
    draw.lod = mLod.frame().params;
    draw.occluders = mOccluders;
    draw.displacement = displacement;
    draw.lodColors = lodColors;
    return draw;
}

} // namespace tessera::runtime

namespace tessera::runtime {

Status InstancedCrowd::writeTiers(const std::string& path, const std::string& backend,
                                  const backend::CrowdTiers& gpu) const {
    auto ids = [this](auto indices) {
        std::vector<uint32_t> out;
        for (uint32_t i : indices) out.push_back(i < mInstances.size() ? mInstances[i].ids.x : UINT32_MAX);
        std::sort(out.begin(), out.end());
        return out;
    };
    JsonWriter json(true);
    json.beginObject();
    json.keyValue("backend", backend);
    json.keyValue("instances", uint64_t(mInstances.size()));
    // The reference's agents in the frustum and not behind the terrain
    // (every one is drawn, in some tier), and of those the ones drawn as
    // impostors only because the far tier's budget was spent.
    json.keyValue("inView", uint64_t(mLod.frame().inView));
    json.keyValue("pastFarBudget", uint64_t(mLod.frame().pastFarBudget));
    // The reference's agents in the frustum the terrain hides, by the tier
    // their size would have taken.
    json.key("hiddenByTerrain");
    json.beginObject();
    for (uint32_t t = 0; t < lod::kTierCount; ++t)
        json.keyValue(lod::toString(lod::Tier(t)), uint64_t(mLod.frame().hidden[t]));
    json.endObject();
    for (const char* source : {"backend", "reference"}) {
        json.key(std::string(source) + "Tiers");
        json.beginObject();
        for (uint32_t t = 0; t < lod::kTierCount; ++t) {
            std::vector<uint32_t> list;
            if (source == std::string("backend")) {
                list = ids(gpu.instances[t]);
            } else {
                std::vector<uint32_t> indices;
                for (const lod::LodDraw& d : mLod.frame().tiers[t]) indices.push_back(d.instance);
                list = ids(indices);
            }
            json.key(lod::toString(lod::Tier(t)));
            json.beginArray();
            for (uint32_t id : list) json.value(uint64_t(id));
            json.endArray();
        }
        json.endObject();
    }
    json.endObject();
    std::ofstream out(path, std::ios::binary);
    // Flushed before the check: a full disk shows only when the buffer goes out.
    if (!(out << json.str()) || !out.flush()) return Error{path + ": cannot write the crowd tiers"};
    return {};
}

void InstancedCrowd::shadowCasters(std::span<const float> heights, const glm::vec3& region,
                                   std::vector<glm::vec4>& out) const {
    for (const shader::CrowdInstance& instance : mInstances) {
        const glm::vec3 feet(instance.placement);
        if (instance.ids.y < heights.size() && insideRegion(region, feet))
            out.emplace_back(feet, heights[instance.ids.y] * instance.animation.y);
    }
}

} // namespace tessera::runtime
