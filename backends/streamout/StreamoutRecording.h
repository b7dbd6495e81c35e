#pragma once
/// @file StreamoutRecording.h
/// The attachment-less rendering scope streamout's transform-feedback
/// passes need, and their pipelines' common state (barriers and descriptor
/// writes: CommandHelpers.h).

#include "common/CommandHelpers.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::backends::streamout {

/// Opens rendering with no attachments and sets a 1x1 viewport: transform
/// feedback only exists inside rendering, and these passes rasterise nothing.
void beginStreamOut(VkCommandBuffer cmd);
void endStreamOut(VkCommandBuffer cmd);

/// A stream-out pass's pipeline: points in, captured by transform feedback,
/// nothing rasterised (no culling, no depth, rasterizer discard). Callers
/// add their vertex stream, if any.
gpu::GraphicsPipelineDesc streamOutPipelineDesc(std::string name, const gpu::PipelineLayout& layout,
                                                std::vector<gpu::ShaderStage> stages);

} // namespace tessera::backends::streamout
