#pragma once
/// @file MeshshaderCrowdResources.h
/// What the meshshader backend keeps per crowd beside GpuCrowd: every
/// creature's cage (the middle tier) and far mesh cut into meshlets at
/// creation (meshoptimizer), each with a bounding sphere and a normal cone
/// that hold for every baked frame of the creature's clips
/// (CrowdMeshlet.h), and the task-shader command of every tier list, which
/// meshshader_crowd_args.comp rewrites each frame from the lists' counts.

#include "common/GpuCrowd.h"
#include "common/TechniqueExtension.h"
#include "tessera/backend/CrowdDesc.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"

#include <array>
#include <memory>
#include <vector>

namespace tessera::backends {

class MeshshaderCrowdResources final : public TechniqueExtension {
public:
    /// Where one mesh's meshlets lie in the meshlet table.
    struct MeshletRange {
        uint32_t first = 0, count = 0;
    };

    /// Builds the meshlets of every creature of `crowd` from `desc` (the
    /// meshes and clips the crowd was made from), named after crowd `id`.
    static Result<std::unique_ptr<MeshshaderCrowdResources>> create(gpu::Device& device, GpuCrowd& crowd,
                                                                    const backend::CrowdDesc& desc, uint32_t id);

    /// Creature `creature`'s meshlets of tier `tier` (TS_LOD_MIDDLE: its
    /// cage, TS_LOD_FAR: its far mesh).
    MeshletRange meshlets(uint32_t tier, uint32_t creature) const;
    /// Creature `creature`'s shadow casters' meshlets for tier `tier`, over
    /// its far mesh's vertices: the far mesh's own (TS_LOD_MIDDLE) or the
    /// far casters' triangles (TS_LOD_FAR, CrowdCharacterDesc::farCasterIndices).
    MeshletRange casterMeshlets(uint32_t tier, uint32_t creature) const;
    /// Meshlets of every mesh, and those whose normal cone can cull them.
    uint32_t meshletCount() const { return mMeshletCount; }
    uint32_t conedMeshletCount() const { return mConed; }

    gpu::Buffer& meshletBuffer() { return mMeshlets; }
    gpu::Buffer& meshletVertices() { return mVertices; }
    gpu::Buffer& meshletTriangles() { return mTriangles; }
    /// A CrowdMeshCommand per list (tier * TS_CROWD_MAX_CHARACTERS + creature),
    /// then per creature for its far casters (tsCrowdFarCasterCommand).
    gpu::Buffer& meshArgs() { return mArgs; }

    uint64_t bytes() const override;

private:
    std::vector<std::array<MeshletRange, 3>> mRanges; ///< per creature: cage, far mesh, far casters
    uint32_t mMeshletCount = 0, mConed = 0;
    gpu::Buffer mMeshlets, mVertices, mTriangles, mArgs;
};

} // namespace tessera::backends
