// The null backend: the whole frame logic with no GPU (bgfx's and sokol's
// noop renderer). It validates every call the way a real backend would use
// it and counts what a real backend would draw, so tests of the data model
// (scene, culling, tessellation levels, splats) run anywhere, CI included.
#include "tessera/shaders/CrowdLod.h"
#include "NullCrowd.h"
#include "tessera/backend/CrowdChecks.h"
#include "tessera/backend/SubdivChecks.h"
#include "tessera/character/BakedAnimation.h"
#include "tessera/backend/PluginApi.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/tessellator/ContinuousLevel.h"
#include "tessera/terrain/Terrain.h"
#include "tessera/terrain/TessLevels.h"
#include "tessera/tessellator/Tessellator.h"
#include "tessera/subdiv/SubdivGpuMesh.h"
#include "tessera/subdiv/SubdivLod.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tessera::backends {
namespace {

constexpr float kMaxTessFactor = 64.0f;

// Triangles the GPU backends' tessellator makes for one terrain patch: a quad
// with fractional_odd spacing, counted exactly by the emulated tessellator
// (the paper's ComputeNumTessellatedPrimitives).
uint64_t quadTriangles(const std::array<float, 4>& outer, const std::array<float, 2>& inner) {
    tessellator::TessFactors factors;
    factors.outer = outer;
    factors.inner = inner;
    return tessellator::Tessellator::countTriangles(tessellator::Domain::Quad, tessellator::Partitioning::FractionalOdd,
                                                    factors);
}

// Triangles one cage triangle becomes at a continuous level: the triangle
// domain with fractional_odd spacing, as every GPU backend draws characters.
uint64_t characterTriangles(float level) {
    return tessellator::Tessellator::countTriangles(tessellator::Domain::Triangle,
                                                    tessellator::Partitioning::FractionalOdd,
                                                    tessellator::ContinuousLevel::factors(level));
}

class NullBackend final : public backend::Backend {
public:
    backend::BackendCapabilities capabilities(const device::DeviceFeatures*) override {
        backend::BackendCapabilities caps;
        caps.name = "null";
        caps.description = "no GPU: runs the frame logic and counts what would be drawn";
        caps.requiresGpu = false;
        caps.maxTessFactor = kMaxTessFactor;
        caps.crowd = true;
        caps.subdiv = true;
        caps.terrainModes = (1u << uint32_t(terrain::TerrainMode::LowRes)) |
                            (1u << uint32_t(terrain::TerrainMode::Continuous)) |
                            (1u << uint32_t(terrain::TerrainMode::Adaptive));
        return caps;
    }

    Status initialize(const backend::BackendInitInfo&) override {
        mInitialized = true;
        return {};
    }

    void shutdown() override {
        mTerrains.clear();
        mCharacters.clear();
        mCrowds.clear();
        mInitialized = false;
    }

    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc& desc) override {
        if (!mInitialized) return fail("null backend: createTerrain before initialize");
        if (!desc.terrain) return fail("createTerrain: no terrain");
        mTerrains.push_back(desc.terrain);
        return backend::TerrainHandle{static_cast<uint32_t>(mTerrains.size() - 1)};
    }

    void destroyTerrain(backend::TerrainHandle terrain) override {
        if (terrain.valid() && terrain.id < mTerrains.size()) mTerrains[terrain.id] = nullptr;
    }

    Result<backend::CharacterHandle> createCharacter(const backend::CharacterDesc& desc) override {
        if (!mInitialized) return fail("null backend: createCharacter before initialize");
        if (!desc.asset) return fail("createCharacter: no asset");
        if (desc.asset->cage.triangleCount() == 0) return fail(desc.asset->name, ": the cage has no triangles");
        mCharacters.push_back(desc.asset);
        return backend::CharacterHandle{static_cast<uint32_t>(mCharacters.size() - 1)};
    }

    void destroyCharacter(backend::CharacterHandle handle) override {
        if (handle.valid() && handle.id < mCharacters.size()) mCharacters[handle.id] = nullptr;
    }

    void drawCharacters(const backend::CharacterDrawInfo& draw) override {
        for (const backend::CharacterDrawItem& item : draw.items) {
            if (!item.character.valid() || item.character.id >= mCharacters.size()) continue;
            const character::CharacterAsset* asset = mCharacters[item.character.id];
            if (!asset || item.palette.size() < asset->cage.bindings.size()) continue;
            const uint64_t cage = asset->cage.triangleCount();
            ++mReport.charactersDrawn;
            mReport.characterCageTriangles += cage;
            // Only the near LOD tier is tessellated (CharacterDrawItem::tier).
            const float level = item.tier == TS_LOD_NEAR ? std::clamp(std::isnan(item.tessLevel) ? 1.0f : item.tessLevel,
                                                                      1.0f, kMaxTessFactor)
                                                         : 1.0f;
            const uint64_t triangles = cage * characterTriangles(level);
            mReport.characterTriangles += triangles;
            mReport.trianglesSubmitted += triangles;
        }
        if (!draw.items.empty()) ++mReport.passes;
    }

    Result<backend::CrowdHandle> createCrowd(const backend::CrowdDesc& desc) override {
        if (!mInitialized) return fail("null backend: createCrowd before initialize");
        if (Status ok = backend::checkCrowdDesc(desc); !ok) return ok.error();
        std::vector<NullCrowd::Creature> creatures;
        for (const backend::CrowdCharacterDesc& c : desc.characters) {
            const character::CharacterAsset* asset = c.character.id < mCharacters.size() ? mCharacters[c.character.id]
                                                                                         : nullptr;
            if (!asset) return fail("createCrowd: character ", std::to_string(c.character.id), " does not exist");
            const uint32_t middle = c.middleIndices.empty() ? asset->cage.triangleCount()
                                                            : uint32_t(c.middleIndices.size() / 3);
            creatures.push_back({asset->cage.triangleCount(), middle, c.farMesh->triangleCount(), c.levelPerPixel});
        }
        mCrowds.push_back(std::make_unique<NullCrowd>(std::move(creatures), uint32_t(desc.animation->clips.size()),
                                                      desc.maxInstances, desc.maxIds));
        return backend::CrowdHandle{static_cast<uint32_t>(mCrowds.size() - 1)};
    }

    void destroyCrowd(backend::CrowdHandle crowd) override {
        if (crowd.valid() && crowd.id < mCrowds.size()) mCrowds[crowd.id].reset();
    }

    void drawCrowd(backend::CrowdHandle handle, const backend::CrowdDrawInfo& draw) override {
        NullCrowd* crowd = handle.valid() && handle.id < mCrowds.size() ? mCrowds[handle.id].get() : nullptr;
        if (!crowd) return;
        const backend::CrowdTierCounts counts = crowd->draw(draw);
        for (uint32_t t = 0; t < TS_LOD_TIERS; ++t) {
            mReport.crowdInstances[t] += counts.instances[t];
            mReport.crowdTriangles[t] += counts.triangles[t];
            mReport.trianglesSubmitted += counts.triangles[t];
        }
        mReport.passes += 1 + TS_LOD_TIERS;
    }

    Result<backend::CrowdTiers> readCrowdTiers(backend::CrowdHandle handle) override {
        NullCrowd* crowd = handle.valid() && handle.id < mCrowds.size() ? mCrowds[handle.id].get() : nullptr;
        if (!crowd) return fail("readCrowdTiers: no such crowd");
        return crowd->tiers();
    }

    Result<backend::SubdivHandle> createSubdiv(const backend::SubdivDesc& desc) override {
        if (!mInitialized) return fail("null backend: createSubdiv before initialize");
        if (Status ok = backend::checkSubdivDesc(desc); !ok) return ok.error();
        auto surface = std::make_unique<NullSubdiv>();
        static_cast<backend::SubdivMeshData&>(surface->mesh) = *desc.mesh;
        surface->cage = desc.mesh->restPositions;
        mSubdivs.push_back(std::move(surface));
        return backend::SubdivHandle{static_cast<uint32_t>(mSubdivs.size() - 1)};
    }

    void destroySubdiv(backend::SubdivHandle handle) override {
        if (handle.valid() && handle.id < mSubdivs.size()) mSubdivs[handle.id].reset();
    }

    void updateSubdivTiles(backend::SubdivHandle, const backend::SubdivTileData&, std::span<const glm::uvec4>) override {}

    void drawSubdiv(backend::SubdivHandle handle, const backend::SubdivDrawInfo& draw) override {
        NullSubdiv* surface = subdivOf(handle);
        if (!surface) return;
        if (draw.cage.size() == surface->cage.size())
            for (size_t v = 0; v < draw.cage.size(); ++v) surface->cage[v] = glm::vec3(draw.cage[v]);
        // What the GPU backends' refine pass and hull stage compute, on the CPU.
        const subdiv::SubdivPrediction predicted =
            subdiv::SubdivLod::predict(surface->mesh, surface->mesh.refine(surface->cage), draw.uniforms);
        mReport.subdivDomains += surface->mesh.domainCount();
        mReport.trianglesSubmitted += predicted.triangles;
        mReport.passes += 2;
    }

    Result<backend::SubdivPoints> readSubdivPoints(backend::SubdivHandle handle) override {
        NullSubdiv* surface = subdivOf(handle);
        if (!surface) return fail("readSubdivPoints: no such surface");
        return backend::SubdivPoints{surface->mesh.refine(surface->cage)};
    }

    void beginFrame(const backend::FrameInfo& frame) override {
        mReport = {};
        mReport.frameIndex = frame.frameIndex;
        mView.eye = frame.cameraPosition;
        mView.pixelsPerMetre = float(frame.height) * std::abs(frame.projection[1][1]) * 0.5f;
    }

    void splatTerrain(backend::TerrainHandle handle, std::span<const terrain::CraterSplat> splats) override {
        // The CPU copy is the terrain itself, already splatted by the host.
        if (terrainOf(handle)) mReport.splatsApplied += static_cast<uint32_t>(splats.size());
    }

    void drawTerrain(backend::TerrainHandle handle, const backend::TerrainDrawInfo& draw) override {
        const terrain::Terrain* t = terrainOf(handle);
        if (!t) return;
        const terrain::PatchGrid& grid = t->grid();
        const bool tessellated = draw.tessellation.mode != terrain::TerrainMode::LowRes;
        terrain::TessLevels levels;
        if (tessellated) levels = terrain::computeTessLevels(*t, draw.tessellation, mView, kMaxTessFactor);
        for (uint32_t patch : draw.visiblePatches) {
            if (patch >= grid.patchCount()) continue;
            ++mReport.terrainPatchesDrawn;
            if (!tessellated) {
                mReport.trianglesSubmitted += 2;
                continue;
            }
            const std::array<uint32_t, 4> edges = grid.patchEdges(patch);
            const std::array<float, 4> outer{levels.edges[edges[0]], levels.edges[edges[1]], levels.edges[edges[2]],
                                             levels.edges[edges[3]]};
            mReport.trianglesSubmitted += quadTriangles(outer, terrain::innerLevels(levels, grid, patch));
        }
        ++mReport.passes;
    }

    Result<std::vector<uint16_t>> readTerrainHeights(backend::TerrainHandle handle) override {
        // With no GPU copy, the terrain's CPU copy is what a readback would return.
        const terrain::Terrain* t = terrainOf(handle);
        if (!t) return fail("readTerrainHeights: no such terrain");
        return t->field().samples();
    }

    void endFrame() override { mLast = mReport; }

    backend::FrameReport lastFrameReport() override { return mLast; }

private:
    struct NullSubdiv {
        subdiv::SubdivGpuMesh mesh;
        std::vector<glm::vec3> cage;
    };
    NullSubdiv* subdivOf(backend::SubdivHandle handle) {
        return handle.valid() && handle.id < mSubdivs.size() ? mSubdivs[handle.id].get() : nullptr;
    }

    const terrain::Terrain* terrainOf(backend::TerrainHandle handle) const {
        return handle.valid() && handle.id < mTerrains.size() ? mTerrains[handle.id] : nullptr;
    }

    std::vector<const terrain::Terrain*> mTerrains; ///< null once destroyed
    std::vector<const character::CharacterAsset*> mCharacters; ///< null once destroyed
    std::vector<std::unique_ptr<NullCrowd>> mCrowds;           ///< null once destroyed
    std::vector<std::unique_ptr<NullSubdiv>> mSubdivs;         ///< null once destroyed
    terrain::TessView mView;
    backend::FrameReport mReport;
    backend::FrameReport mLast;
    bool mInitialized = false;
};

backend::Backend* createNull() { return new NullBackend(); }
void destroyNull(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"null", &tessera::backends::createNull, &tessera::backends::destroyNull});
}
