#pragma once
/// @file CrowdPipeline.h
/// What the crowd's shared tier draws (CrowdMeshPass, EmulatedCrowdNearPass)
/// (and CrowdImpostorPass) are built from: a graphics pipeline over a
/// CrowdDescriptors layout, with a vertex and a fragment stage, one vertex
/// stream of one attribute and the faces it culls, and its recording: the pipeline, the stream and the
/// index buffer bound once, then per creature its descriptors pushed before
/// its indirect draws. Given its vertex stage's caster variant, also the
/// depth-only draws of cascaded shadows (ShadowCasterPipeline).

#include "common/CrowdDescriptors.h"
#include "common/GpuCrowd.h"
#include "common/ShadowCasterPipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace tessera::backends {

class CrowdPipeline {
public:
    /// The one vertex stream: per vertex or per instance, `stride` bytes,
    /// one attribute of `format` at offset 0.
    struct Stream {
        uint32_t stride = 0;
        VkVertexInputRate rate = VK_VERTEX_INPUT_RATE_VERTEX;
        VkFormat format = VK_FORMAT_UNDEFINED;
    };

    CrowdPipeline() = default;
    /// Named `name` (its layout `name`.layout), reading the bindings of
    /// `mode`; with `casterVertex` (the vertex stage's TS_SHADOW_CASTER
    /// variant) also the depth-only caster pipeline.
    CrowdPipeline(gpu::Device& device, CrowdDescriptors::Mode mode, std::span<const uint32_t> vertex,
                  std::span<const uint32_t> fragment, Stream stream, VkFrontFace frontFace, VkCullModeFlags cullMode,
                  VkFormat colorFormat, VkFormat depthFormat, const std::string& name,
                  std::span<const uint32_t> casterVertex = {});

    /// Records GPU pass `passName`: binds the pipeline, `stream` and
    /// `indices` (uint32), then for each creature pushes its descriptors and
    /// calls `draw(cmd, creature)`.
    void record(gpu::FrameContext& frame, const char* passName, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                VkBuffer stream, VkBuffer indices,
                const std::function<void(VkCommandBuffer cmd, uint32_t creature)>& draw) const;
    /// The same draws through the caster pipeline into the open shadow
    /// layer of the cascade `caster`, inside the caller's pass.
    void recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors, VkBuffer stream,
                      VkBuffer indices, const shader::ShadowCasterPush& caster,
                      const std::function<void(VkCommandBuffer cmd, uint32_t creature)>& draw) const;

private:
    /// Binds `stream` and `indices`, then per creature pushes its
    /// descriptors through `layout` and calls `draw`.
    void recordCreatures(VkCommandBuffer cmd, const gpu::PipelineLayout& layout, GpuCrowd& crowd,
                         CrowdDescriptors& descriptors, VkBuffer stream, VkBuffer indices,
                         const std::function<void(VkCommandBuffer cmd, uint32_t creature)>& draw) const;

    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
    ShadowCasterPipeline mShadow;
};

} // namespace tessera::backends
