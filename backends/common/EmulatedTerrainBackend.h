#pragma once
/// @file EmulatedTerrainBackend.h
/// What the r2vb and streamout backends share: the emulated fixed-function
/// tessellator's draw. Each backend produces, with its own era's means, one
/// record per visible superprimitive (its levels) and five tessellator
/// commands per record (indirect draws of pattern pieces, TessPattern.h);
/// this class then draws them all through the evaluation vertex shader
/// (terrain_emulated.vert), which places each pattern point from the
/// record's levels and displaces it from the height map.
///
/// Contract for the buffers a backend hands over (EmulatedDrawSource):
///  - records: an RGBA32F texel buffer of 2 * capacity texels. Texel r holds
///    record r's four outer levels (Vulkan quad order, clamped to the draw's
///    range), texel capacity + r holds (inner u, inner v, float(patch index), 0).
///  - commands: 5 * capacity VkDrawIndirectCommand (16 bytes each), in any
///    order; command c of record r is tsEmuCommand(outer, inner, c, r) from
///    emulated_tess.glsl (firstInstance = r * 5 + c). Unused commands must be
///    all zero (they draw nothing).

#include "BasicCharacterBackend.h"
#include "EmulatedCharacterPass.h"
#include "tessera/gpu/Buffer.h"

#include <cstdint>

namespace tessera::backends {

struct EmulatedDrawSource {
    VkBufferView records = VK_NULL_HANDLE;
    uint32_t capacity = 0;
    VkBuffer commands = VK_NULL_HANDLE;
    VkDeviceSize commandsOffset = 0;
};

class EmulatedTerrainBackend : public BasicCharacterBackend {
public:
    /// Also fails, naming the limit, when the terrain has more patches than
    /// a records texel buffer can hold on this device (2 texels per patch).
    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc& desc) override;
    void beginFrame(const backend::FrameInfo& frame) override;

protected:
    Status initializeTechnique(const backend::BackendInitInfo& info) final;
    void shutdownTechnique() final;
    void drawTessellated(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) final;
    /// Characters: the emulated tessellator's pattern per level, instanced per
    /// cage triangle (EmulatedCharacterPass); pass 1 is each backend's own.
    void drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) final;
    uint64_t characterPassBytes() const override;

    /// Creates the backend's own factor passes.
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
    /// BackendCapabilities::subdiv implements both, outside the main pass:
    /// refine `surface.points()` from the frame slot's cage with its era's
    /// means (the same tsSubdivRefinePoint of subdiv_refine.glsl), leaving
    /// them ready for VERTEX_SHADER reads; then, per domain, a record and
    /// five commands (the EmulatedDrawSource contract above; patch index =
    /// domain index) from tsSubdivLevels of subdiv_levels.glsl, levels
    /// clamped to [1, TS_EMU_MAX_LEVEL], culled domains all-zero commands.
    /// Per-surface buffers go in a GpuSubdiv::Extension.
    virtual void recordSubdivRefine(GpuSubdiv& /*surface*/) {}
    virtual EmulatedDrawSource recordSubdivFactorPasses(GpuSubdiv& /*surface*/,
                                                        const gpu::UniformSlice& /*subdivUniforms*/) {
        return {};
    }

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
    gpu::Pipeline mFillPipeline;
    gpu::Pipeline mWirePipeline;
    EmulatedCharacterPass mCharacterPass;
};

} // namespace tessera::backends
