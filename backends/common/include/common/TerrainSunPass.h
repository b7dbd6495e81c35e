#pragma once
/// @file TerrainSunPass.h
/// Renders a terrain's sun-visibility (horizon) map from its GPU height map
/// (terrain_sun.frag): every texel marches the height field towards the sun
/// and stores how much of the sun stays above the terrain's horizon there.
/// The terrain's shading samples it bilinearly for soft self-shadowing
/// (docs/LOOKS.md). A fragment shader into a render target, so the
/// D3D9-style backend runs it too. The map is redrawn only when it is stale:
/// whole after the terrain's creation and when the sun moved, and after
/// craters only where their change can reach (the texels whose march
/// crosses them).

#include "common/GpuTerrain.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <glm/glm.hpp>
#include <string>

namespace tessera::backends {

class TerrainSunPass {
public:
    TerrainSunPass() = default;
    TerrainSunPass(gpu::Device& device, const std::string& backendName);

    /// Records a "terrain.sun" pass when `terrain`'s map is stale for
    /// `sunDirection` (unit, towards the sun) or craters changed part of it. Must run outside any
    /// rendering, after this frame's splats; leaves the map
    /// SHADER_READ_ONLY_OPTIMAL and visible to fragment shaders.
    void update(gpu::FrameContext& frame, GpuTerrain& terrain, const glm::vec3& sunDirection);

private:
    static VkRect2D affectedTexels(GpuTerrain& terrain, const glm::vec4& region, const glm::vec3& sun);

    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
