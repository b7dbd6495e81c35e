#pragma once
/// @file GpuSubdiv.h
/// A Catmull-Clark surface's GPU resources, shared by every backend's
/// subdivision draw (layouts in SubdivLayout.h and DisplacementTile.h): the
/// packed surface as texel buffers, the refined points the backend's own
/// refine pass writes each frame (through the usage it names at creation),
/// a ring of per-frame cage buffers, the displacement tiles as one R32F
/// texture with their records, and the descriptors subdiv_eval.glsl binds.

#include "common/TechniqueExtension.h"
#include "tessera/shaders/SubdivLayout.h"
#include "tessera/backend/SubdivDesc.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::backends {

/// The backend's own per-surface resources (its records, commands and
/// render targets) are its TechniqueExtension (ExtensionSlot).
class GpuSubdiv : public ExtensionSlot {
public:
    /// `writeUsage`: how the backend's refine pass writes the refined
    /// points (storage, transform feedback, or transfer from a target).
    /// Errors name the surface and the device limit it exceeds.
    static Result<std::unique_ptr<GpuSubdiv>> create(gpu::Device& device, const backend::SubdivDesc& desc,
                                                     VkBufferUsageFlags writeUsage);

    const std::string& name() const { return mName; }
    uint32_t baseVertexCount() const { return mBaseVertexCount; }
    uint32_t refinedPointCount() const { return mRefinedPointCount; }
    uint32_t domainCount() const { return mDomainCount; }
    /// No boundary: back faces may be culled (open surfaces draw both sides).
    bool closed() const { return mClosed; }

    /// Writes this frame's cage into the slot's buffer (`cage` empty: the
    /// last one given, the rest pose at first).
    void uploadCage(uint32_t slot, std::span<const glm::vec4> cage);
    VkBufferView cageView(uint32_t slot) const { return mCageViews[slot].handle(); }
    gpu::Buffer& cage(uint32_t slot) { return mCages[slot]; }

    /// The refine pass's inputs (per refined point a stencil record, and the
    /// entries) and its output.
    VkBufferView stencilsView() const { return mStencilsView.handle(); }
    VkBufferView entriesView() const { return mEntriesView.handle(); }
    gpu::Buffer& points() { return mPoints; }
    VkBufferView pointsView() const { return mPointsView.handle(); }
    /// The domains' records, for the passes that set levels.
    VkBufferView domainsView() const { return mDomainsView.handle(); }
    VkBufferView supportView() const { return mSupportView.handle(); }

    /// The bindings subdiv_eval.glsl declares, for a pipeline layout.
    static std::vector<gpu::BindingDesc> evalBindings(VkShaderStageFlags stages);
    /// Push-descriptor writes for those bindings, with `uniforms` holding
    /// shader::SubdivUniforms. Valid while this object and `uniforms` live.
    std::vector<VkWriteDescriptorSet> evalWrites(const gpu::UniformSlice& uniforms);
    /// evalBindings plus the domains' support (TS_BINDING_SUBDIV_SUPPORT),
    /// for the passes that set the domains' levels and cull them; and their
    /// writes, as evalWrites'.
    static std::vector<gpu::BindingDesc> levelBindings(VkShaderStageFlags stages);
    std::vector<VkWriteDescriptorSet> levelWrites(const gpu::UniformSlice& uniforms);
    /// The refine passes' inputs (subdiv_refine.glsl): the stencils, their
    /// entries and the cage, as texel buffers; and their writes for frame
    /// slot `slot`'s cage, valid while this object lives.
    static std::vector<gpu::BindingDesc> refineBindings(VkShaderStageFlags stages);
    std::vector<VkWriteDescriptorSet> refineWrites(uint32_t slot);

    /// Re-uploads texel rectangles (x, y, width, height) of `tiles`,
    /// recorded into the frame outside any render pass; leaves the texture
    /// ready for shader reads.
    Status updateTiles(gpu::FrameContext& frame, const backend::SubdivTileData& tiles,
                       std::span<const glm::uvec4> rects);

    /// Blocking copy of the refined points the last completed frame wrote
    /// (gpu::readBack: waits for the device to be idle).
    std::vector<glm::vec4> readPoints();

    /// Device bytes of everything above.
    uint64_t bytes() const;

private:
    GpuSubdiv() = default;

    std::string mName;
    gpu::Device* mDevice = nullptr;
    uint32_t mBaseVertexCount = 0, mRefinedPointCount = 0, mDomainCount = 0;
    bool mClosed = true;
    std::vector<glm::vec4> mLastCage;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mCages;
    std::array<gpu::BufferView, gpu::kFramesInFlight> mCageViews;
    gpu::Buffer mStencils, mEntries, mPoints, mDomains, mNodes, mPatches, mIndices, mSupport, mTileRecords;
    gpu::BufferView mStencilsView, mEntriesView, mPointsView, mDomainsView, mNodesView, mPatchesView, mIndicesView,
        mSupportView, mTileRecordsView;
    gpu::Image mTiles;
    gpu::Sampler mTileSampler;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mTileStaging;
    // Storage for the writes' descriptor infos.
    VkDescriptorBufferInfo mUniformInfo{};
    VkDescriptorImageInfo mTileInfo{};
    std::array<VkBufferView, 6> mViews{};
    VkBufferView mSupportHandle = VK_NULL_HANDLE;
    std::array<VkBufferView, 3> mRefineViews{};
};

} // namespace tessera::backends
