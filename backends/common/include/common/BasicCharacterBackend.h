#pragma once
/// @file BasicCharacterBackend.h
/// The character and crowd commands of the contract, written once for
/// every GPU backend (the top of the shared chain, BasicTerrainBackend.h).
///
/// Characters: upload (GpuCharacter), per-instance uniforms and skinning
/// palettes, the order of the two passes and the descriptors every
/// character draw binds. Each backend supplies its own technique for the two
/// halves the paper's eras differ in:
///  - skinCharacter: pass 1 of the two-pass path, animating every cage vertex
///    once into the 128-bit compressed format with its era's recirculation
///    (compute, transform feedback, or a render target re-read as a stream);
///  - drawCharacter: the tessellated draw (hardware tessellation stages, or
///    the emulated tessellator's pattern through an evaluation vertex shader).
///
/// Instanced crowds: the crowds' table (GpuCrowd), the frame's order of a
/// draw (last time's counts reported, instances and uniforms uploaded, the
/// technique's culling and binning outside the main pass, the counts'
/// copy, the tier draws inside it, the report) and the blocking read of
/// the tiers; each backend supplies its culling, binning and draws.

#include "common/BasicSubdivBackend.h"
#include "common/GpuCharacter.h"
#include "common/GpuCrowd.h"
#include "common/GpuObjectTable.h"
#include "tessera/shaders/ShadowCascades.h"

#include <functional>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace tessera::backends {

/// What one drawn instance binds, for both passes.
struct CharacterInstance {
    GpuCharacter* character = nullptr;
    gpu::UniformSlice uniforms;  ///< shader::CharacterUniforms
    gpu::UniformSlice palette;   ///< shader::CharacterPalette
    CompressedCage* compressed = nullptr;  ///< pass 1's output (two-pass only)
    float level = 1.0f;          ///< clamped to the backend's maximum
    glm::vec4 sphere{0.0f};      ///< world bounding sphere (xyz centre, w radius), for the cull per cascade
};

/// Which of the shared bindings a character pipeline declares: pass 1 reads
/// the uniforms and palette only; pass 2 also samples the maps.
enum class CharacterBindings { Skin, Draw };

/// The descriptor layout of a character pipeline, defined next to the
/// pushes that fill it: the shared bindings of `bindings` (frame, character,
/// palette, and the maps for Draw) plus the cage and the compressed cage as
/// `cageType` when the technique reads them through descriptors
/// (VK_DESCRIPTOR_TYPE_MAX_ENUM when it takes the cage as a vertex stream).
/// `extra` follows them (the technique's own bindings).
gpu::PipelineLayout characterLayout(gpu::Device& device, CharacterBindings bindings, VkShaderStageFlags stages,
                                    VkDescriptorType cageType, uint32_t pushConstantBytes,
                                    VkShaderStageFlags pushConstantStages, std::string name,
                                    std::initializer_list<gpu::BindingDesc> extra = {});

/// How a backend's character pass objects push their descriptors through the
/// backend, so the pass classes stay separate from the backend class.
using CharacterPushFn = std::function<void(VkPipelineBindPoint, CharacterBindings, const gpu::PipelineLayout&,
                                           const CharacterInstance&, std::span<const VkWriteDescriptorSet>)>;

/// One crowd's frame, as the technique's passes and draws read it.
struct CrowdFrame {
    uint32_t slot = 0;           ///< the frame slot
    uint32_t instanceCount = 0;  ///< valid instances uploaded this frame (GpuCrowd::uploadInstances)
    gpu::UniformSlice uniforms;  ///< shader::CrowdUniforms
};

class BasicCharacterBackend : public BasicSubdivBackend {
public:
    Result<backend::CharacterHandle> createCharacter(const backend::CharacterDesc& desc) final;
    void destroyCharacter(backend::CharacterHandle character) final;
    void drawCharacters(const backend::CharacterDrawInfo& draw) final;

    // Instanced crowds: a backend that sets BackendCapabilities::crowd culls
    // and bins them with its own technique (the crowd hooks below); one that
    // does not refuses createCrowd, and hosts draw its crowds through
    // drawCharacters.
    Result<backend::CrowdHandle> createCrowd(const backend::CrowdDesc& desc) final;
    void destroyCrowd(backend::CrowdHandle crowd) final;
    void drawCrowd(backend::CrowdHandle crowd, const backend::CrowdDrawInfo& draw) final;
    Result<backend::CrowdTiers> readCrowdTiers(backend::CrowdHandle crowd) final;

protected:
    // What a backend supplies for characters (its technique).
    /// Buffer usage pass 1 writes compressed cages with (storage for compute,
    /// transform feedback, transfer destination for a render-target copy).
    virtual VkBufferUsageFlags compressedCageUsage() const = 0;
    /// Attaches the technique's per-character resources (GpuCharacter::attach,
    /// a TechniqueExtension) once the character is made; an error refuses it.
    virtual Status attachCharacterResources(GpuCharacter& /*character*/) { return {}; }
    /// Pass 1, outside the main pass: writes `instance.compressed` and leaves
    /// it visible to vertex-shader reads.
    virtual void skinCharacter(const CharacterInstance& instance) = 0;
    /// Pass 2, inside the main pass.
    virtual void drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) = 0;
    /// Cascaded shadows (a backend that sets BackendCapabilities::
    /// cascadedShadows): pass 2 again as a caster, depth only, into the open
    /// layer of the cascade `caster` (matrix and cull per cascade)
    /// (ShadowCasterPipeline), after pass 1 and outside the main pass.
    virtual void drawCharacterShadow(const CharacterInstance& /*instance*/, backend::CharacterPath /*path*/,
                                     const shader::ShadowCasterPush& /*caster*/) {}
    /// Bytes of the technique's own character intermediates (render targets,
    /// pattern streams) beyond the compressed cages, for FrameReport.
    virtual uint64_t characterPassBytes() const { return 0; }

    // What a backend that draws crowds supplies (its technique).
    /// How its passes write a crowd's lists, commands and near slots (added
    /// to their buffers' usage: storage, transform feedback or transfer).
    virtual VkBufferUsageFlags crowdWriteUsage() const { return 0; }
    /// Attaches the technique's per-crowd resources (GpuCrowd::attach, a
    /// TechniqueExtension, named after `handle`) once the crowd is made, with
    /// the host's description (its meshes and clips are valid only during
    /// this call); an error refuses it.
    virtual Status attachCrowdResources(GpuCrowd& /*crowd*/, backend::CrowdHandle /*handle*/,
                                        const backend::CrowdDesc& /*desc*/) {
        return {};
    }
    /// Outside the main pass: culls and bins the frame's instances into the
    /// tier lists with their counts in the indirect commands (the shared
    /// rule of CrowdLod.h against the technique's LOD state), and fills and
    /// skins the near slots; leaves lists and commands final, ready for the
    /// counts' copy and for the draws.
    virtual void recordCrowdPasses(GpuCrowd& /*crowd*/, const CrowdFrame& /*frame*/) {}
    /// Inside the main pass: each tier's draws.
    virtual void recordCrowdDraws(GpuCrowd& /*crowd*/, const CrowdFrame& /*frame*/) {}
    /// Cascaded shadows: each tier's draws again as casters, depth only, over
    /// the lists recordCrowdPasses made, into the open layer of the cascade
    /// `caster` (its matrix, and its cull per cascade, which the shaders run
    /// per instance); outside the main pass.
    virtual void recordCrowdShadow(GpuCrowd& /*crowd*/, const CrowdFrame& /*frame*/,
                                   const shader::ShadowCasterPush& /*caster*/) {}
    /// Cascaded shadows, before the casters' passes (outside any rendering):
    /// what recordCrowdShadow's draws read and the binning did not write.
    /// By default the middle and far tiers' indexed caster commands
    /// (GpuCrowd::recordCasterArgs); a backend drawing its casters otherwise
    /// overrides it.
    virtual void prepareCrowdShadow(GpuCrowd& crowd) { crowd.recordCasterArgs(mFrame->cmd()); }
    /// GPU passes one drawCrowd records (passes and draws), for FrameReport::passes.
    virtual uint32_t crowdPassCount() const { return 0; }

    /// Pushes the bindings every character pipeline shares (frame, character,
    /// palette, and the maps for `Draw`) plus `extra` (the cage and
    /// compressed cage as the technique reads them).
    void pushCharacterDescriptors(VkPipelineBindPoint bindPoint, CharacterBindings bindings,
                                  const gpu::PipelineLayout& layout,
                                  const CharacterInstance& instance, std::span<const VkWriteDescriptorSet> extra);
    /// pushCharacterDescriptors as a callable for the pass objects.
    CharacterPushFn characterPush();

    void releaseObjects() override;

private:
    GpuObjectTable<GpuCharacter, backend::CharacterHandle> mCharacters;
    GpuObjectTable<GpuCrowd, backend::CrowdHandle> mCrowds;
};

} // namespace tessera::backends
