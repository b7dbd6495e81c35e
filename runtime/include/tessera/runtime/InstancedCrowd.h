#pragma once
/// @file InstancedCrowd.h
/// A population drawn as one instanced crowd (Backend::drawCrowd): the
/// crowd scene's agents, or the characters scene's (CharacterCrowd); the
/// creatures' clips baked once, every agent an instance each frame, and the
/// LOD manager's parameters (its budget's cuts) for the backend's GPU
/// culling and binning. No palette or pose per agent on the CPU.

#include "tessera/runtime/CharacterAssets.h"
#include "tessera/backend/CrowdDesc.h"
#include "tessera/character/BakedAnimation.h"
#include "tessera/character/FarMesh.h"
#include "tessera/core/Result.h"
#include "tessera/lod/LodManager.h"
#include "tessera/scene/Camera.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <span>
#include <vector>

namespace tessera::runtime {

class InstancedCrowd {
public:
    /// Bakes every asset's clips (character::bakeAnimation, combined). An
    /// asset without a far mesh is an error naming its file.
    static Result<std::unique_ptr<InstancedCrowd>> create(const CharacterAssets& assets);

    /// What Backend::createCrowd needs (the assets' handles must be bound),
    /// for up to `maxAgents` agents, with the policy's near slots and edge
    /// target (the near tier's level per pixel, the same on CPU and GPU) and
    /// each creature's impostor atlas (CrowdAsset::impostor; `assets` must
    /// outlive createCrowd).
    backend::CrowdDesc desc(const CharacterAssets& assets, uint32_t maxAgents, const lod::LodPolicy& policy);

    /// The global baked clip of asset `asset`'s clip `clip` (-1: rest pose).
    uint32_t bakedClip(uint32_t asset, int clip) const;
    /// The phase `seconds` into global baked clip `clip` (character::bakedPhase).
    float phase(uint32_t clip, float seconds) const { return character::bakedPhase(mBaked.clips[clip], seconds); }

    /// Starts a frame of `count` instances (set each with set()).
    void begin(size_t count);
    /// Instance `i` of the frame (CrowdInstance.h) and its LOD sphere; safe
    /// to call for different `i` from several threads.
    void set(size_t i, const shader::CrowdInstance& instance);
    /// Runs the LOD manager over the frame's instances (the CPU reference:
    /// the budget's cuts reach the GPU in the draw's parameters).
    const lod::LodFrame& select(const lod::LodView& view, const lod::LodPolicy& policy);
    /// The horizon the next select() and drawInfo() hide agents behind: the
    /// terrain's lowest drawn heights (MinMaxPyramid::horizonGrid, at most
    /// TS_CROWD_MAX_OCCLUDER_CELLS a side), taken again each frame (craters
    /// change them).
    void setHorizon(const terrain::Terrain& terrain);
    /// The frame's draw for the backend.
    backend::CrowdDrawInfo drawInfo(bool displacement, bool lodColors) const;

    const lod::LodFrame& lod() const { return mLod.frame(); }
    /// Whether select() is the whole CPU reference: its per-tier lists
    /// (LodFrame::tiers) and every agent in view tested against the horizon
    /// (LodManager::testEveryHorizon). Default: no; the cuts every backend
    /// reads and the mesh tiers' counts come without them, and the backends
    /// cull the impostors themselves. writeTiers needs them from the frame
    /// it writes.
    void keepLists(bool keep) {
        mLod.keepLists(keep);
        mLod.testEveryHorizon(keep);
    }
    /// The agents in view the terrain hides this frame, by the tier their
    /// size would take (the reference's count, whatever keepLists says;
    /// the horizon test of every agent in view: a report's figure).
    std::array<uint32_t, lod::kTierCount> countHidden() const { return mLod.countHidden(mLodInstances); }
    /// Writes `gpu` (a backend's lists, instance indices) and the CPU
    /// reference's last lists as agent ids per tier, sorted, to `path`
    /// (--crowd-tiers; keepLists must have been on); an error naming the
    /// file when it cannot.
    Status writeTiers(const std::string& path, const std::string& backend, const backend::CrowdTiers& gpu) const;
    size_t instanceCount() const { return mInstances.size(); }
    /// This frame's instances, as set().
    std::span<const shader::CrowdInstance> instances() const { return mInstances; }
    /// This frame's instances standing in `region` (x, y: min corner XZ, z:
    /// side) as shadow casters, appended to `out`: feet (xyz) and height (w:
    /// `heights[creature]`, in the creature's model units, times the
    /// instance's scale), metres (CharacterPopulation::shadowCasters).
    void shadowCasters(std::span<const float> heights, const glm::vec3& region, std::vector<glm::vec4>& out) const;

private:
    InstancedCrowd() = default;

    character::BakedAnimation mBaked;
    std::vector<lod::LodCharacter> mCosts;
    std::vector<backend::CrowdCharacterDesc> mCharacters;
    std::vector<const character::CageMesh*> mFarMeshes;
    std::vector<character::CageMesh> mSimplifiedFar; ///< reserved: mFarMeshes point into it
    /// Per creature: the middle tier's coarser triangles over its cage's
    /// vertices (LodPolicy::middleMeshTriangles; empty: the whole cage).
    std::vector<std::vector<uint32_t>> mMiddleIndices;
    /// Per creature: the far tier's shadow casters' triangles over its far
    /// mesh's vertices (LodPolicy::farCasterTriangles; empty: the far mesh).
    std::vector<std::vector<uint32_t>> mFarCasterIndices;
    std::vector<float> mOccluders;     ///< the horizon's lowest heights (setHorizon)
    glm::vec4 mOccluderGrid{0.0f};     ///< its corner, cell side and cells per side
    lod::LodManager mLod;
    std::vector<shader::CrowdInstance> mInstances;
    std::vector<lod::LodInstance> mLodInstances;
};

} // namespace tessera::runtime
