#pragma once
/// @file CrowdImpostorPass.h
/// The impostor tier of an instanced crowd on the backends with a vertex
/// stage (r2vb, streamout, hulldomain): per creature one indexed indirect
/// draw of the card (GpuCrowd's TS_CROWD_IMPOSTOR_INDICES indices) instanced
/// over its impostor list's entries (the per-instance stream), placed in
/// crowd_impostor.vert and shaded from the baked atlases in
/// crowd_impostor.frag; as CrowdMeshPass draws the middle and far tiers.
/// The cards cast no cascaded shadow (no caster pipeline): the creatures
/// drawn as cards are a few texels of a shadow cascade, and the casters
/// would need a depth image of their own per baked view; the terrain's blob
/// shadows come from every agent in the shadow region whatever its tier.

#include "common/CrowdDescriptors.h"
#include "common/CrowdPipeline.h"
#include "common/GpuCrowd.h"

#include <cstdint>
#include <span>
#include <string>

namespace tessera::backends {

/// The impostor cards' fragment shader for `device`: crowd_impostor.frag
/// `blended` (the two phases around the instance's, blended) on a GPU, its
/// TS_IMPOSTOR_NEAREST_PHASE variant `nearest` (the nearer phase: two
/// samples instead of four) on a CPU device, where the samples are most of
/// the tier's time and the frames step between phases anyway
/// (docs/CROWD.md, 6.10).
std::span<const uint32_t> crowdImpostorFragment(const gpu::Device& device, std::span<const uint32_t> blended,
                                                std::span<const uint32_t> nearest);

class CrowdImpostorPass {
public:
    CrowdImpostorPass() = default;
    /// `vertex` and `fragment` are the backend's crowd_impostor.vert and
    /// crowd_impostor.frag, reading the bindings of `mode`.
    CrowdImpostorPass(gpu::Device& device, CrowdDescriptors::Mode mode, std::span<const uint32_t> vertex,
                      std::span<const uint32_t> fragment, VkFormat colorFormat, VkFormat depthFormat,
                      const std::string& name);

    /// Inside the main pass, after the far tier: GPU pass crowd.impostor.
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors);

private:
    CrowdPipeline mPipeline;
};

} // namespace tessera::backends
