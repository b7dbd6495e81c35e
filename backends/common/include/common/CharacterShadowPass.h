#pragma once
/// @file CharacterShadowPass.h
/// The characters' shadows on the terrain: each frame, one soft ellipse per
/// character near the camera, cast away from the sun by the shadow's length,
/// is rendered into a terrain-space mask (R8 darkness over a square of the
/// ground around the view) that the terrain's shading multiplies into its
/// sunlight. A render-target pass with a vertex stream of casters, so every
/// backend, D3D9-style included, uses it. Characters are not in the terrain's
/// sun-visibility map (that comes from the height map alone); this is how
/// they shadow the ground.

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"

#include <array>
#include <glm/glm.hpp>
#include <span>
#include <string>

namespace tessera::backends {

class CharacterShadowPass {
public:
    /// Casters a frame draws at most (the nearest come first from the host).
    static constexpr uint32_t kMaxCasters = 8192;

    CharacterShadowPass() = default;
    CharacterShadowPass(gpu::Device& device, const std::string& backendName);

    /// Records "terrain.characterShadows": clears the mask and draws
    /// `casters` (xyz: feet, w: height, metres) over `region` (x, y: world
    /// XZ of the min corner, z: side in metres) lit from `sun`. Must run
    /// outside any rendering; leaves the mask SHADER_READ_ONLY_OPTIMAL for
    /// the fragment shaders. With no casters the mask is left as it was and
    /// the host's uniforms say it is unused.
    void record(gpu::FrameContext& frame, std::span<const glm::vec4> casters, const glm::vec3& region,
                const glm::vec3& sun);

    /// The mask and its sampler, for the terrain's descriptor set.
    VkDescriptorImageInfo descriptor() const;
    bool valid() const { return mPipeline.valid(); }

private:
    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
    gpu::Image mMask;
    gpu::Sampler mSampler;
    std::array<gpu::Buffer, gpu::kFramesInFlight> mCasters;
};

} // namespace tessera::backends
