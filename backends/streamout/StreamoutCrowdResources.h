#pragma once
/// @file StreamoutCrowdResources.h
/// What streamout's crowd culling and binning keep per crowd, beside the
/// shared GpuCrowd (whose lists, commands and near slots they write), as
/// the crowd's TechniqueExtension:
///  - the LOD state as two R32UI render targets, one texel per instance id,
///    read (Texture2D.Load) and written (a point per survivor) in turns:
///    each frame's cull pass loads last frame's target and rasterises into
///    the other, so no target is read and written by one pass;
///  - the survivors buffer the cull pass streams out, one region per
///    creature (its range of the creature-sorted instances), and the mesh
///    survivors the bin pass's split copies from it (those the near, middle
///    and far lists can take), in the same regions;
///  - a transform-feedback stream query per creature's survivors, per
///    creature's mesh survivors and per (tier, creature) list, and the buffer their results are copied to, from
///    which the counts reach the indirect commands (the lists' instance
///    counts, the later passes' draws) without the CPU waiting;
///  - per creature four indirect draws of the later passes: the bin pass's
///    over its survivors (a point each) and over its mesh survivors, the
///    slots pass's (a point per near entry) and the skin pass's (nearStride
///    points, instanced by the near entries).
///    They take the place of draw-auto (vkCmdDrawIndirectByteCountEXT): on
///    lavapipe 22.3 a draw-auto recorded after an indirect draw in the same
///    command buffer (here the terrain's pattern draws) draws the indirect
///    command's count instead (22.3.6: 7 vertices of 1,000 captured, in
///    tests/gpu/draw_auto_after_indirect_test.cpp); 25.0.7 draws 1,000. A
///    query's count copied into a command is right on both, and Debian 12
///    without backports still ships 22.3, so the copies stay;
///  - every creature's cage as an RGBA32UI texel buffer (5 texels per
///    CharacterVertex): crowd.vertices() is a vertex stream only, and the
///    skin pass pads each slot to nearStride vertices, past a cage's end.
/// One set serves every frame in flight: the GPU runs the frames in order and
/// each drawCrowd starts with a barrier on the previous one's reads.

#include "common/GpuCrowd.h"
#include "common/TechniqueExtension.h"
#include "tessera/core/Result.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/BufferView.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/UniqueHandle.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tessera::backends {

class StreamoutCrowdResources final : public TechniqueExtension {
public:
    /// Query (and result) of list (tier, creature), and of a creature's survivors.
    uint32_t listQuery(uint32_t tier, uint32_t creature) const { return tier * mCreatures + creature; }
    uint32_t survivorsQuery(uint32_t creature) const { return TS_LOD_TIERS * mCreatures + creature; }
    uint32_t meshSurvivorsQuery(uint32_t creature) const { return (TS_LOD_TIERS + 1) * mCreatures + creature; }
    /// Byte offsets in draws() of a creature's VkDrawIndirectCommand for the
    /// bin pass over its survivors and over its mesh survivors, and for the
    /// slots and skin passes.
    VkDeviceSize binDraw(uint32_t creature) const { return drawOffset(0, creature); }
    VkDeviceSize slotsDraw(uint32_t creature) const { return drawOffset(1, creature); }
    VkDeviceSize skinDraw(uint32_t creature) const { return drawOffset(2, creature); }
    VkDeviceSize meshBinDraw(uint32_t creature) const { return drawOffset(3, creature); }
    /// Bytes of a survivor record: (instance, next state).
    static constexpr VkDeviceSize kSurvivorBytes = 2 * sizeof(uint32_t);
    /// Bytes per query result in counts(): primitives written, then needed.
    static constexpr VkDeviceSize kResultBytes = 2 * sizeof(uint32_t);

    /// Fails, in words, when the crowd's ids do not fit a state target.
    static Result<std::unique_ptr<StreamoutCrowdResources>> create(gpu::Device& device, GpuCrowd& crowd);

    /// Last frame's state (SHADER_READ_ONLY_OPTIMAL between frames) and the
    /// target this frame writes; flipState() swaps them once it has.
    gpu::Image& stateRead() { return mState[mRead]; }
    gpu::Image& stateWrite() { return mState[1 - mRead]; }
    void flipState() { mRead = 1 - mRead; }

    gpu::Buffer& survivors() { return mSurvivors; }
    gpu::Buffer& meshSurvivors() { return mMeshSurvivors; }
    VkQueryPool queries() const { return mQueries.get(); }
    uint32_t queryCount() const { return mQueryCount; }
    gpu::Buffer& counts() { return mCounts; }
    gpu::Buffer& draws() { return mDraws; }
    VkBufferView cagesView() const { return mCagesView.handle(); }
    /// Creature c's first vertex in the cage texels.
    uint32_t cageBase(uint32_t creature) const { return mCageBase[creature]; }

    /// Copies queries [first, first + count)'s results into counts() (the GPU
    /// waits for them, the CPU never does) and makes them ready to copy on.
    void copyResults(VkCommandBuffer cmd, uint32_t first, uint32_t count);
    /// Copies the results of the per-creature queries from `firstQuery` on
    /// into the vertex counts of each creature's draw at (this->*draw)(c),
    /// leaving them ready for indirect draws.
    void countsToDraws(VkCommandBuffer cmd, uint32_t firstQuery, VkDeviceSize (StreamoutCrowdResources::*draw)(uint32_t) const);
    /// Where query `query`'s primitives-written count lies in counts().
    static VkDeviceSize resultOffset(uint32_t query) { return query * kResultBytes; }

    /// Device bytes of everything above.
    uint64_t bytes() const override;

private:
    StreamoutCrowdResources() = default;
    VkDeviceSize drawOffset(uint32_t pass, uint32_t creature) const {
        return VkDeviceSize(pass * mCreatures + creature) * sizeof(VkDrawIndirectCommand);
    }

    std::array<gpu::Image, 2> mState;
    uint32_t mRead = 0;
    uint32_t mCreatures = 0;
    gpu::Buffer mSurvivors, mMeshSurvivors, mCounts, mDraws, mCages;
    gpu::BufferView mCagesView;
    gpu::UniqueHandle<VkQueryPool, VK_OBJECT_TYPE_QUERY_POOL> mQueries;
    uint32_t mQueryCount = 0;
    std::vector<uint32_t> mCageBase;
};

} // namespace tessera::backends
