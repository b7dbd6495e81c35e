#pragma once
/// @file HulldomainCharacterPatchPass.h
/// hulldomain's tessellated character draw (D3D11 style): the cage triangles
/// as 3-point patches, a pass-through hull stage with the draw's continuous
/// level (up to 64), and the paper's Listing 8 evaluation in the domain stage.
/// Two-pass: control points are the compressed vertices pass 1 wrote;
/// single-pass: the domain stage skins all three corners at every point.
/// Cascaded shadows: the same patches as casters, depth only, the domain
/// stage's TS_SHADOW_CASTER variant placing them in the cascade.

#include "common/FillWirePipelines.h"
#include "common/BasicCharacterBackend.h"
#include "common/ShadowCasterPipeline.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class HulldomainCharacterPatchPass {
public:
    HulldomainCharacterPatchPass() = default;
    HulldomainCharacterPatchPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat, bool wireframe);

    /// Draws one instance inside the main pass.
    void record(gpu::FrameContext& frame, const CharacterInstance& instance, backend::CharacterPath path,
                bool wireframe, const CharacterPushFn& push);
    /// Draws one instance as a caster into the open shadow layer of the
    /// cascade `caster` (outside the main pass).
    void recordShadow(gpu::FrameContext& frame, const CharacterInstance& instance, backend::CharacterPath path,
                      const shader::ShadowCasterPush& caster, const CharacterPushFn& push);

private:
    /// Binds the cage and the instance's descriptors through `layout` and
    /// draws its patches.
    void drawPatches(VkCommandBuffer cmd, const gpu::PipelineLayout& layout, const CharacterInstance& instance,
                     const CharacterPushFn& push);

    gpu::PipelineLayout mLayout;
    // [path][wireframe]
    FillWirePipelines mPipelines[2]; ///< [single-pass]
    ShadowCasterPipeline mShadow[2]; ///< [single-pass]
};

} // namespace tessera::backends
