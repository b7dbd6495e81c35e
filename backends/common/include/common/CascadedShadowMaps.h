#pragma once
/// @file CascadedShadowMaps.h
/// A backend's cascaded shadow maps for one frame (docs/LOOKS.md, "Cascaded
/// shadow maps"): the depth layers (gpu::ShadowMapArray), this frame's
/// cascades as shader::ShadowCascadeUniforms, and the order of the writes.
/// The casters' depth-only passes run outside the main pass, after each
/// backend's skinning and culling: the frame's first write clears the
/// layers, later ones (a crowd after the characters) keep and add to them.
/// Every terrain, character and crowd layout binds the uniforms and the map
/// (TS_BINDING_SHADOW_CASCADES, TS_BINDING_SHADOW_MAP); in a frame without
/// cascaded shadows the uniforms' cascade count is 0 and the shaders read
/// "lit" without sampling.

#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/ShadowMapArray.h"
#include "tessera/scene/ShadowCascade.h"

#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <string>

namespace tessera::backends {

class CascadedShadowMaps {
public:
    /// One cascade's casters: draw into the open depth-only layer `layer`
    /// with `viewProjection` (world to the cascade's clip space) as the
    /// depth-only pipelines' push constant.
    using DrawCasters = std::function<void(uint32_t layer, const glm::mat4& viewProjection)>;

    CascadedShadowMaps() = default;
    /// The layers, as many as scene::ShadowCascadeFit makes at its default
    /// resolution, named after the backend.
    CascadedShadowMaps(gpu::Device& device, const std::string& backendName);

    /// Starts a frame: `cascades` (empty: no cascaded shadows this frame)
    /// into this frame's uniforms.
    void beginFrame(gpu::FrameContext& frame, std::span<const scene::ShadowCascade> cascades);
    /// This frame draws cascaded shadows.
    bool active() const { return !mCascades.empty(); }

    /// Outside any rendering: one depth-only pass per cascade (one profiler
    /// scope `passName` around them all, a RenderDoc label per cascade:
    /// `draw` must open no pass of its own), `draw` recording each one's
    /// casters, then hands the layers to the receivers' shaders.
    void record(gpu::FrameContext& frame, const char* passName, const DrawCasters& draw);
    /// Outside any rendering: clears the layers if no caster wrote them this
    /// frame, so the receivers never read an earlier frame's casters.
    void finishFrame(gpu::FrameContext& frame);

    /// The two receiver bindings' writes (valid while this object lives and
    /// until the next beginFrame).
    std::span<const VkWriteDescriptorSet> writes() const { return mWrites; }
    /// Device bytes of the depth layers.
    uint64_t bytes() const { return mMap.bytes(); }

private:
    gpu::Device* mDevice = nullptr;
    gpu::ShadowMapArray mMap;
    std::span<const scene::ShadowCascade> mCascades;
    bool mWritten = false;
    VkDescriptorBufferInfo mUniformInfo{};
    VkDescriptorImageInfo mMapInfo{};
    std::array<VkWriteDescriptorSet, 2> mWrites{};
};

} // namespace tessera::backends
