#pragma once
/// @file CrowdMeshPass.h
/// The middle and far tiers of an instanced crowd, the same draws on every
/// backend: per (tier, creature) one indexed indirect draw of the cage or
/// the far mesh (the per-vertex stream), instanced over the list's entries
/// (the per-instance stream), skinned from the baked clips in
/// crowd_mesh.vert. What differs per backend is how the lists and their
/// instance counts were made (compute, transform feedback, render targets).

#include "common/CrowdDescriptors.h"
#include "common/CrowdPipeline.h"
#include "common/GpuCrowd.h"

#include <cstdint>
#include <span>
#include <string>

namespace tessera::backends {

class CrowdMeshPass {
public:
    CrowdMeshPass() = default;
    /// `vertex` and `fragment` are the backend's crowd_mesh.vert and
    /// character.frag crowd variants, reading the bindings of `mode`;
    /// `casterVertex` crowd_mesh.vert's TS_SHADOW_CASTER variant, for
    /// backends that draw cascaded shadows.
    CrowdMeshPass(gpu::Device& device, CrowdDescriptors::Mode mode, std::span<const uint32_t> vertex,
                  std::span<const uint32_t> fragment, VkFormat colorFormat, VkFormat depthFormat,
                  const std::string& name, std::span<const uint32_t> casterVertex = {});

    /// Inside the main pass: GPU passes crowd.middle and crowd.far.
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors);
    /// Both tiers' draws as casters into the open shadow layer of the
    /// cascade `caster` (CascadedShadowMaps::record).
    void recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                      const shader::ShadowCasterPush& caster);

private:
    CrowdPipeline mPipeline;
};

} // namespace tessera::backends
