#pragma once
/// @file EmulatedCharacterPass.h
/// The r2vb and streamout backends' tessellated character draw, the paper's
/// D3D9/D3D10 technique: continuous tessellation sets one level per draw, so
/// the emulated tessellator (tessera::tessellator::Tessellator, triangle
/// domain, fractional-odd spacing, bit-identical with the hardware's points
/// and triangles) produces one pattern per level on the CPU; the draw
/// instances that pattern once per cage triangle, and the evaluation vertex
/// shader (character_emulated.vert) fetches the superprimitive's vertices by
/// index from a texel buffer (the compressed vertices of pass 1, or for the
/// single-pass path the bind-pose cage, skinned per tessellated vertex).

#include "common/FillWirePipelines.h"
#include "common/BasicCharacterBackend.h"
#include "common/ShadowCasterPipeline.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/tessellator/TessellationTypes.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>

namespace tessera::backends {

class EmulatedCharacterPass {
public:
    EmulatedCharacterPass() = default;
    EmulatedCharacterPass(gpu::Device& device, const std::string& backendName, VkFormat colorFormat,
                          VkFormat depthFormat, bool wireframe);

    /// Draws one instance inside the main pass. Call beginFrame first each frame.
    void record(gpu::FrameContext& frame, const CharacterInstance& instance, backend::CharacterPath path,
                bool wireframe, const CharacterPushFn& push);
    /// Draws one instance as a caster (the evaluation vertex shader's
    /// TS_SHADOW_CASTER variant, depth only) into the open shadow layer of
    /// the cascade `caster`, outside the main pass.
    void recordShadow(gpu::FrameContext& frame, const CharacterInstance& instance, backend::CharacterPath path,
                      const shader::ShadowCasterPush& caster, const CharacterPushFn& push);
    /// Starts this frame's pattern stream (the slot's previous contents have retired).
    void beginFrame(uint32_t slot);
    /// Bytes of the pattern streams, for the backend comparison.
    uint64_t bytes() const;

private:
    struct Placed {
        VkDeviceSize vertexOffset = 0;  ///< bytes into the slot's stream
        VkDeviceSize indexOffset = 0;
        uint32_t indexCount = 0;
    };
    /// The pattern of `level` in this frame's stream, tessellated once per level per frame.
    Placed place(uint32_t slot, float level);

    gpu::Device* mDevice = nullptr;
    std::string mName;
    /// Binds the instance's descriptors through `layout` and the pattern
    /// of its level, and draws it over every cage triangle.
    void drawPattern(gpu::FrameContext& frame, const gpu::PipelineLayout& layout, const CharacterInstance& instance,
                     const CharacterPushFn& push);

    gpu::PipelineLayout mLayout;
    FillWirePipelines mPipelines[2]; ///< [single-pass]
    ShadowCasterPipeline mShadow[2]; ///< [single-pass]
    struct Slot {
        gpu::Buffer stream;  ///< patterns of this frame: points (vec2) then indices (uint32)
        VkDeviceSize used = 0;
        std::map<uint32_t, Placed> placed;  ///< by the level's bits
    };
    std::array<Slot, gpu::kFramesInFlight> mSlots;
};

} // namespace tessera::backends
