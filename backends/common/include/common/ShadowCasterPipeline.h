#pragma once
/// @file ShadowCasterPipeline.h
/// The depth-only variant of a caster pipeline (docs/LOOKS.md, "Cascaded
/// shadow maps"): the same draw over the same lists as the main pass, with
/// the stage that writes gl_Position replaced by its TS_SHADOW_CASTER
/// variant (shadow_caster.glsl: the cascade's matrix and its cull per
/// cascade as push constants, shader::ShadowCasterPush) and no fragment
/// stage, rendering into a CascadedShadowMaps layer.

#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/shaders/ShadowCascades.h"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace tessera::backends {

class ShadowCasterPipeline {
public:
    /// Push-constant bytes a caster layout declares: the cascade's matrix
    /// and cull (shader::ShadowCasterPush).
    static constexpr uint32_t kPushBytes = sizeof(shader::ShadowCasterPush);

    ShadowCasterPipeline() = default;
    /// From the main pass's `desc`: the stages of `casters` replaced by
    /// their SPIR-V (the stage writing gl_Position; meshshader's task stage
    /// too, which culls against the camera; hulldomain's crowd hull stage,
    /// which culls per cascade), the fragment stage dropped, no colour
    /// targets, the shadow map's depth format, no face culling (the sun's projection has no Y flip, and
    /// either side of a closed mesh casts), the casters' depth bias, through
    /// `layout` (the main layout's bindings and push constants for
    /// `pushStages`, with kPushBytes more at `pushOffset` for the push),
    /// named `desc.name` + ".shadow".
    ShadowCasterPipeline(gpu::Device& device, gpu::GraphicsPipelineDesc desc, gpu::PipelineLayout layout,
                         VkShaderStageFlags pushStages, const std::vector<gpu::ShaderStage>& casters,
                         uint32_t pushOffset = 0);

    bool valid() const { return mPipeline.valid(); }
    /// The layout the draws push their descriptors through.
    const gpu::PipelineLayout& layout() const { return mLayout; }
    /// The stages every push constant into layout() names.
    VkShaderStageFlags pushStages() const { return mPushStages; }
    /// Binds the pipeline and pushes the cascade's `caster` (its matrix and cull).
    void bind(VkCommandBuffer cmd, const shader::ShadowCasterPush& caster) const;

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
    VkShaderStageFlags mPushStages = 0;
    uint32_t mPushOffset = 0;
};

} // namespace tessera::backends
