#pragma once
/// @file MeshshaderCharacterPass.h
/// meshshader's pass 2 for characters: a task stage that launches one mesh
/// workgroup per piece of each cage triangle's pattern, and a mesh stage that
/// evaluates the piece's points (meshshader_character.task/.mesh), two-pass
/// (from the compressed cage) or single-pass (skinning every point). Owns the
/// triangle pattern tables (tessellator::MeshTrianglePatternLibrary).
/// Cascaded shadows: the same tasks as casters, the mesh stage's
/// TS_SHADOW_CASTER variant placing the points in the cascade.

#include "common/BasicCharacterBackend.h"
#include "common/ShadowCasterPipeline.h"
#include "common/FillWirePipelines.h"
#include "MeshshaderPatternTables.h"
#include "tessera/gpu/PipelineLayout.h"

#include <array>

namespace tessera::backends {

class MeshshaderCharacterPass {
public:
    MeshshaderCharacterPass() = default;
    MeshshaderCharacterPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat, bool wireframe);

    /// Records the draw of `instance` on `path` into the open main pass.
    void record(gpu::FrameContext& frame, const CharacterInstance& instance, backend::CharacterPath path,
                bool wireframe, const CharacterPushFn& push);
    /// Records `instance` as a caster into the open shadow layer of the
    /// cascade `caster` (outside the main pass).
    void recordShadow(gpu::FrameContext& frame, const CharacterInstance& instance, backend::CharacterPath path,
                      const shader::ShadowCasterPush& caster, const CharacterPushFn& push);

    /// Bytes of the pattern tables.
    uint64_t tableBytes() const { return mTables.bytes(); }

private:
    /// Pushes the instance's descriptors through `layout` and launches its
    /// tasks, the triangle count pushed for `pushStages`.
    void drawTasks(gpu::FrameContext& frame, const gpu::PipelineLayout& layout, VkShaderStageFlags pushStages,
                   const CharacterInstance& instance, const CharacterPushFn& push);

    gpu::PipelineLayout mLayout;
    std::array<FillWirePipelines, 2> mPipelines; ///< two-pass, single-pass
    std::array<ShadowCasterPipeline, 2> mShadow;  ///< two-pass, single-pass
    MeshshaderPatternTables mTables;
};

} // namespace tessera::backends
