#pragma once
/// @file BasicCharacterBackend.h
/// What the three GPU backends share for characters: upload (GpuCharacter),
/// per-instance uniforms and skinning palettes, the order of the two passes
/// and the descriptors every character draw binds. Each backend supplies its
/// own technique for the two halves the paper's eras differ in:
///  - skinCharacter: pass 1 of the two-pass path, animating every cage vertex
///    once into the 128-bit compressed format with its era's recirculation
///    (compute, transform feedback, or a render target re-read as a stream);
///  - drawCharacter: the tessellated draw (hardware tessellation stages, or
///    the emulated tessellator's pattern through an evaluation vertex shader).

#include "common/BasicTerrainBackend.h"
#include "common/GpuCharacter.h"
#include "common/GpuSubdivSet.h"

#include <functional>
#include <memory>
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
};

/// Which of the shared bindings a character pipeline declares: pass 1 reads
/// the uniforms and palette only; pass 2 also samples the maps.
enum class CharacterBindings { Skin, Draw };

/// The descriptor layout of a character pipeline, defined next to the
/// pushes that fill it: the shared bindings of `bindings` (frame, character,
/// palette, and the maps for Draw) plus the cage and the compressed cage as
/// `cageType` when the technique reads them through descriptors
/// (VK_DESCRIPTOR_TYPE_MAX_ENUM when it takes the cage as a vertex stream).
gpu::PipelineLayout characterLayout(gpu::Device& device, CharacterBindings bindings, VkShaderStageFlags stages,
                                    VkDescriptorType cageType, uint32_t pushConstantBytes,
                                    VkShaderStageFlags pushConstantStages, std::string name);

/// How a backend's character pass objects push their descriptors through the
/// backend, so the pass classes stay separate from the backend class.
using CharacterPushFn = std::function<void(VkPipelineBindPoint, CharacterBindings, const gpu::PipelineLayout&,
                                           const CharacterInstance&, std::span<const VkWriteDescriptorSet>)>;

class BasicCharacterBackend : public BasicTerrainBackend {
public:
    Result<backend::CharacterHandle> createCharacter(const backend::CharacterDesc& desc) override;
    void destroyCharacter(backend::CharacterHandle character) override;
    void drawCharacters(const backend::CharacterDrawInfo& draw) override;
    void shutdown() override;

    // Instanced crowds: every GPU backend culls and bins them on the GPU
    // with its own technique and overrides these (and sets
    // BackendCapabilities::crowd); a backend derived from this class that
    // does not refuses, and hosts draw its crowds through drawCharacters.
    Result<backend::CrowdHandle> createCrowd(const backend::CrowdDesc& desc) override;
    void destroyCrowd(backend::CrowdHandle) override {}
    void drawCrowd(backend::CrowdHandle, const backend::CrowdDrawInfo&) override {}
    Result<backend::CrowdTiers> readCrowdTiers(backend::CrowdHandle crowd) override;

    // Subdivision surfaces: the handle table, uploads and the frame's order
    // are shared; a backend that sets BackendCapabilities::subdiv supplies
    // its refine (and level) passes and its tessellated draw.
    Result<backend::SubdivHandle> createSubdiv(const backend::SubdivDesc& desc) override;
    void destroySubdiv(backend::SubdivHandle surface) override;
    void updateSubdivTiles(backend::SubdivHandle surface, const backend::SubdivTileData& tiles,
                           std::span<const glm::uvec4> rects) override;
    void drawSubdiv(backend::SubdivHandle surface, const backend::SubdivDrawInfo& draw) override;
    Result<backend::SubdivPoints> readSubdivPoints(backend::SubdivHandle surface) override;

protected:
    /// Buffer usage pass 1 writes compressed cages with (storage for compute,
    /// transform feedback, transfer destination for a render-target copy).
    virtual VkBufferUsageFlags compressedCageUsage() const = 0;
    /// Pass 1, outside the main pass: writes `instance.compressed` and leaves
    /// it visible to vertex-shader reads.
    virtual void skinCharacter(const CharacterInstance& instance) = 0;
    /// Pass 2, inside the main pass.
    virtual void drawCharacter(const CharacterInstance& instance, backend::CharacterPath path) = 0;
    /// Bytes of the technique's own character intermediates (render targets,
    /// pattern streams) beyond the compressed cages, for FrameReport.
    virtual uint64_t characterPassBytes() const { return 0; }

    /// How the refine pass writes a surface's refined points (buffer usage).
    virtual VkBufferUsageFlags subdivWriteUsage() const { return 0; }
    /// Outside the main pass: refines `surface`'s points from the frame
    /// slot's cage (and whatever else the technique prepares: levels,
    /// records, commands), leaving them ready for the draw.
    virtual void subdivPrePasses(GpuSubdiv&, const gpu::UniformSlice& /*uniforms*/) {}
    /// Inside the main pass: tessellates, displaces and draws the surface.
    virtual void subdivDraw(GpuSubdiv&, const gpu::UniformSlice& /*uniforms*/) {}
    /// Makes the subdivision table (call from initializeTechnique of a
    /// backend that draws surfaces).
    void initializeSubdiv() { mSubdivs = GpuSubdivSet(*mDevice, subdivWriteUsage()); }
    /// The surface, or null for an unknown or destroyed handle.
    GpuSubdiv* findSubdiv(backend::SubdivHandle handle) { return mSubdivs.find(handle); }

    /// Pushes the bindings every character pipeline shares (frame, character,
    /// palette, and the maps for `Draw`) plus `extra` (the cage and
    /// compressed cage as the technique reads them).
    void pushCharacterDescriptors(VkPipelineBindPoint bindPoint, CharacterBindings bindings,
                                  const gpu::PipelineLayout& layout,
                                  const CharacterInstance& instance, std::span<const VkWriteDescriptorSet> extra);
    /// pushCharacterDescriptors as a callable for the pass objects.
    CharacterPushFn characterPush();

    GpuCharacter* findCharacter(backend::CharacterHandle handle);

private:
    std::vector<std::unique_ptr<GpuCharacter>> mCharacters;
    GpuSubdivSet mSubdivs;
};

} // namespace tessera::backends
