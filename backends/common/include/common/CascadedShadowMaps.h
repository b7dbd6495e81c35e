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
#include "tessera/scene/ShadowCascadeFit.h"
#include "tessera/shaders/ShadowCascades.h"

#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <string>

namespace tessera::backends {

class CascadedShadowMaps {
public:
    /// One cascade's casters: draw into the open depth-only layer `layer`
    /// with `caster` (the cascade's matrix and cull per cascade) as the
    /// depth-only pipelines' push constant.
    using DrawCasters = std::function<void(uint32_t layer, const shader::ShadowCasterPush& caster)>;

    CascadedShadowMaps() = default;
    /// The layers of `settings` (the device's: ShadowCascadeFit::Settings::
    /// forDevice, as the host fits them), named after the backend.
    CascadedShadowMaps(gpu::Device& device, const std::string& backendName,
                       const scene::ShadowCascadeFit::Settings& settings);

    /// Starts a frame: `cascades` (empty: no cascaded shadows this frame)
    /// into this frame's uniforms, and the casters' pushes for the sun
    /// towards `towardsSun`.
    void beginFrame(gpu::FrameContext& frame, std::span<const scene::ShadowCascade> cascades,
                    const glm::vec3& towardsSun);
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
    scene::ShadowCascadeFit::Settings mSettings;
    std::span<const scene::ShadowCascade> mCascades;
    std::array<shader::ShadowCasterPush, scene::ShadowCascadeFit::kMaxCascades> mPushes{};
    bool mWritten = false;
    VkDescriptorBufferInfo mUniformInfo{};
    VkDescriptorImageInfo mMapInfo{};
    std::array<VkWriteDescriptorSet, 2> mWrites{};
};

} // namespace tessera::backends
