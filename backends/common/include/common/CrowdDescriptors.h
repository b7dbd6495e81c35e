#pragma once
/// @file CrowdDescriptors.h
/// The push-descriptor writes of an instanced crowd's draws (the bindings of
/// CrowdInstance.h plus the frame's and a creature's maps) and the pipeline
/// layout that matches them. Two sets: `Storage` (hulldomain: instances,
/// lists, clips, state, commands and near slots as storage buffers, for its
/// compute passes and draws) and `Texels` (the emulated backends' draws:
/// instances, clips, near cages, near slot records and indices as texel
/// buffers, as D3D9 vertex texture fetch and D3D10 Buffer.Load read them).
/// Both bind a creature's maps and the crowd's impostor atlases
/// (GpuImpostorAtlas), and end with the cascaded shadow maps' two bindings
/// (ShadowCascades.h).

#include "common/GpuCrowd.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <array>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace tessera::backends {

class CrowdDescriptors {
public:
    enum class Mode { Storage, Texels };

    /// The layout of `mode`'s bindings, visible to `stages`, plus a
    /// technique's `extra` bindings and push constants (meshshader's
    /// meshlets and pattern tables).
    static gpu::PipelineLayout layout(gpu::Device& device, Mode mode, VkShaderStageFlags stages, std::string name,
                                      std::initializer_list<gpu::BindingDesc> extra = {},
                                      uint32_t pushConstantBytes = 0, VkShaderStageFlags pushConstantStages = 0);

    /// Writes for `crowd` in frame slot `slot` with this frame's uniforms
    /// and the cascaded shadow maps' bindings (CascadedShadowMaps::writes,
    /// which must outlive this object).
    CrowdDescriptors(Mode mode, GpuCrowd& crowd, uint32_t slot, const gpu::UniformSlice& frame,
                     const gpu::UniformSlice& uniforms, std::span<const VkWriteDescriptorSet> shadows);
    CrowdDescriptors(const CrowdDescriptors&) = delete;
    CrowdDescriptors& operator=(const CrowdDescriptors&) = delete;

    /// Every write, with creature `creature`'s maps.
    std::span<const VkWriteDescriptorSet> writes(uint32_t creature);

private:
    static constexpr size_t kMaxBuffers = 10;
    static constexpr size_t kMaxTexels = 9;
    static constexpr size_t kImages = 5;
    GpuCrowd& mCrowd;
    std::array<VkDescriptorBufferInfo, kMaxBuffers> mBuffers{};
    std::array<VkBufferView, kMaxTexels> mTexels{};
    std::array<VkDescriptorImageInfo, kImages> mImages{};
    std::vector<VkWriteDescriptorSet> mWrites;
    size_t mFirstImage = 0;
};

} // namespace tessera::backends
