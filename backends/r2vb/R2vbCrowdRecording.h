#pragma once
/// @file R2vbCrowdRecording.h
/// Recording helpers r2vb's crowd passes share: their one descriptor layout
/// and push constants, rendering into a target or a region of one, layout
/// changes between rendering, sampling and copying, and the exact R2VB copy
/// (a run of a target's texels to a buffer, texel i to element i).

#include "common/GpuCrowd.h"
#include "R2vbCrowdTargets.h"
#include "shaders/R2vbCrowdLayout.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/PipelineLayout.h"

#include <vulkan/vulkan.h>

#include <span>
#include <string>
#include <vector>

namespace tessera::backends::r2vb::crowd {

/// What every crowd pass of one drawCrowd reads.
struct FrameInputs {
    GpuCrowd* crowd = nullptr;
    R2vbCrowdTargets* targets = nullptr;
    uint32_t instanceCount = 0;              ///< instances uploaded this frame
    uint32_t slot = 0;                       ///< the frame slot (GpuCrowd's per-slot ranges and commands)
    VkDescriptorBufferInfo uniforms{};       ///< shader::CrowdUniforms
    VkBufferView instances = VK_NULL_HANDLE; ///< the frame slot's instances (RGBA32UI texels)
    VkBufferView occluders = VK_NULL_HANDLE; ///< the frame slot's horizon grid (R32F texels)
    shader::R2vbCrowdConstants constants{};  ///< pyramid and ranges; each pass sets target
};

/// The layout of every crowd pass: the crowd's uniforms and texel buffers
/// (instances, baked matrices, clips, near slot records), the state target,
/// the pyramid's atlases and a reduction's source (R2vbCrowdLayout.h), and
/// R2vbCrowdConstants for the vertex and fragment stages. Each pass pushes
/// only what its shaders read.
gpu::PipelineLayout layout(gpu::Device& device, std::string name);

/// Pushes `writes` (set 0) and `constants` for `layout`.
void push(gpu::Device& device, VkCommandBuffer cmd, const gpu::PipelineLayout& layout,
          std::span<const VkWriteDescriptorSet> writes, const shader::R2vbCrowdConstants& constants);

/// Begins rendering into `area` of `targets` (COLOR_ATTACHMENT_OPTIMAL, all
/// at least that large), clearing it to `clear`; the viewport is the area,
/// so texel (x, y) of the area is where r2vb_crowd.glsl puts it.
void beginArea(VkCommandBuffer cmd, std::span<gpu::Image* const> targets, VkRect2D area, VkClearColorValue clear);
/// beginArea over a whole target (the first's size), cleared to zero.
void beginWhole(VkCommandBuffer cmd, std::span<gpu::Image* const> targets);

/// Layout changes, each waiting for the stages that last used the image.
/// Rewritten from scratch: whatever it held is dropped.
void toTarget(VkCommandBuffer cmd, const gpu::Image& image, VkPipelineStageFlags2 lastUse);
/// Rendered, to be sampled by vertex and fragment shaders.
void renderedToSampled(VkCommandBuffer cmd, const gpu::Image& image);
/// Sampled by fragment shaders, to be rendered into again (contents kept).
void sampledToTarget(VkCommandBuffer cmd, const gpu::Image& image);
/// Rendered, to be copied from.
void renderedToCopy(VkCommandBuffer cmd, const gpu::Image& image);

/// The exact R2VB copy of `texels` texels from row `firstRow` of `image`
/// (TRANSFER_SRC_OPTIMAL) to `buffer` at `offset`: whole rows, then the rest
/// of the last one, appended to `regions` for one vkCmdCopyImageToBuffer.
void appendCopy(std::vector<VkBufferImageCopy>& regions, const gpu::Image& image, uint32_t firstRow, uint64_t texels,
                VkDeviceSize offset);
void copy(VkCommandBuffer cmd, const gpu::Image& image, const gpu::Buffer& buffer,
          std::span<const VkBufferImageCopy> regions);

/// Makes this pass's copies visible to the draws and passes that read the
/// copied buffers: indirect commands, vertex streams, texel fetches, copies.
void copiesToReaders(VkCommandBuffer cmd);

} // namespace tessera::backends::r2vb::crowd
