#pragma once
/// @file EmulatedTerrainBackend.h
/// What the r2vb and streamout backends share: the emulated fixed-function
/// tessellator's draw. Each backend produces, with its own era's means, one
/// record per visible superprimitive (its levels) and five tessellator
/// commands per record (indirect draws of pattern pieces, TessPattern.h);
/// this class then draws them all through the evaluation vertex shader
/// (terrain_emulated.vert), which places each pattern point from the
/// record's levels and displaces it from the height map. The buffers a
/// backend hands over follow EmulatedDrawSource.h. Subdivision surfaces use
/// the same contract per tessellation domain (EmulatedSubdivPass), and the
/// crowds' tiers are drawn here too (recordCrowdDraws).

#include "common/FillWirePipelines.h"
#include "common/BasicCharacterBackend.h"
#include "common/CrowdImpostorPass.h"
#include "common/CrowdMeshPass.h"
#include "common/EmulatedCharacterPass.h"
#include "common/EmulatedCrowdNearPass.h"
#include "common/EmulatedDrawSource.h"
#include "common/EmulatedSubdivPass.h"
#include "tessera/gpu/Buffer.h"

#include <cstdint>

namespace tessera::backends {

class EmulatedTerrainBackend : public BasicCharacterBackend {
protected:
    Status initializeTechnique(const backend::BackendInitInfo& info) final;
    void shutdownTechnique() final;
    void beginTechniqueFrame() final;
    /// Refuses, naming the limit, a terrain with more patches than a records
    /// texel buffer can hold on this device (2 texels per patch).
    Status checkTerrain(const backend::TerrainDesc& desc) final;
    void drawTessellated(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) final;
    /// Characters: the emulated tessellator's pattern per level, instanced per
    /// cage triangle (EmulatedCharacterPass); pass 1 is each backend's own.
    void drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) final;
    /// Cascaded shadows: pass 2 again through the evaluation vertex shader's
    /// caster variant (EmulatedCharacterPass::recordShadow).
    void drawCharacterShadow(const CharacterInstance& instance, backend::CharacterPath path,
                             const shader::ShadowCasterPush& caster) final;
    uint64_t characterPassBytes() const final;

    /// Creates the backend's own factor passes (and the rest of its technique).
    virtual Status initializeFactorPasses(const backend::BackendInitInfo& info) = 0;
    virtual void shutdownFactorPasses() = 0;
    /// Records the backend's passes that turn `draw.visiblePatches` into
    /// records and commands for this frame, outside the main pass (which is
    /// not open yet). `tessUniforms` holds shader::TerrainTessUniforms, with
    /// levels clamped to [1, TS_EMU_MAX_LEVEL]. Must leave the buffers ready
    /// for VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT / VERTEX_SHADER reads.
    virtual EmulatedDrawSource recordFactorPasses(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw,
                                                  const gpu::UniformSlice& tessUniforms) = 0;
    /// Bytes of the backend's own intermediate render targets and buffers.
    virtual uint64_t factorPassBytes() const = 0;
    /// Bytes of the backend's own character pass 1 targets (r2vb's render target).
    virtual uint64_t characterSkinBytes() const { return 0; }

    /// Subdivision surfaces on the emulated tessellator. A backend that sets
    /// BackendCapabilities::subdiv implements these, outside the main pass:
    /// refine `surface.points()` from the frame slot's cage with its era's
    /// means (the same tsSubdivRefinePoint of subdiv_refine.glsl), leaving
    /// them ready for VERTEX_SHADER reads; then, per domain, a record and
    /// five commands (the EmulatedDrawSource contract; patch index =
    /// domain index) from tsSubdivLevels of subdiv_levels.glsl, levels
    /// clamped to [1, TS_EMU_MAX_LEVEL], culled domains all-zero commands.
    /// Per-surface buffers go in the surface's TechniqueExtension
    /// (attachSubdivResources).
    virtual void recordSubdivRefine(GpuSubdiv& /*surface*/) {}
    virtual EmulatedDrawSource recordSubdivFactorPasses(GpuSubdiv& /*surface*/,
                                                        const gpu::UniformSlice& /*subdivUniforms*/) {
        return {};
    }
    /// Also refuses a surface whose domains' records exceed a texel buffer
    /// (2 texels per domain).
    Status checkSubdiv(const backend::SubdivDesc& desc) final;
    /// The hooks above in order, keeping the source for recordSubdivDraw.
    void recordSubdivPasses(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) final;
    /// The pattern pieces of the source through EmulatedSubdivPass.
    void recordSubdivDraw(GpuSubdiv& surface, const gpu::UniformSlice& uniforms) final;

    /// Instanced crowds: the backend's recordCrowdPasses writes the lists,
    /// their commands, the near slot records, their commands
    /// (tsCrowdNearCommand) and the slots' compressed cages; the tiers are
    /// then drawn the same way on both emulated backends: the near tier
    /// through the triangle patterns (EmulatedCrowdNearPass), the middle and
    /// far tiers from the baked clips (CrowdMeshPass), the impostor tier as
    /// cards (CrowdImpostorPass), reading the crowd as texel buffers
    /// (CrowdDescriptors::Mode::Texels).
    void recordCrowdDraws(GpuCrowd& crowd, const CrowdFrame& frame) final;
    /// Cascaded shadows: the same tiers' draws as casters, depth only, their
    /// evaluation and mesh vertex shaders' TS_SHADOW_CASTER variants (no
    /// compute, no stages beyond vertex: what r2vb's generation has).
    void recordCrowdShadow(GpuCrowd& crowd, const CrowdFrame& frame, const shader::ShadowCasterPush& caster) final;

    /// Bytes of the pattern buffers (shared by every frame).
    uint64_t patternBytes() const;
    /// The pattern library's key table (shader::TsEmuKeyTable), a uniform
    /// buffer for the passes that write tessellator commands (binding
    /// TS_BINDING_EMU_KEYS, emulated_tess.glsl).
    gpu::Buffer& emuKeyTable() { return mKeyTable; }

private:
    gpu::Buffer mPatternVertices; ///< one packed point reference per pattern vertex
    gpu::Buffer mKeyTable;        ///< shader::TsEmuKeyTable
    gpu::PipelineLayout mLayout;
    FillWirePipelines mPipelines;
    EmulatedCharacterPass mCharacterPass;
    EmulatedSubdivPass mSubdivPass;
    EmulatedDrawSource mSubdivSource; ///< the last recordSubdivPasses' output
    EmulatedCrowdNearPass mCrowdNear;
    CrowdMeshPass mCrowdMesh;
    CrowdImpostorPass mCrowdImpostor;
};

} // namespace tessera::backends
