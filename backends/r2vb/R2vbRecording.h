#pragma once
/// @file R2vbRecording.h
/// Command-recording helpers every r2vb pass shares: rendering points into
/// render targets, and the R2VB step itself (a render target's first rows
/// copied to a buffer that later passes read as a vertex stream, texel
/// buffer or indirect buffer). Barriers go through the shared layer's
/// helpers (tessera/gpu/Barriers.h).

#include "common/CommandHelpers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <vulkan/vulkan.h>

#include <span>
#include <string>
#include <vector>

namespace tessera::backends::r2vb {

/// A pipeline that renders one-pixel points into colour targets of
/// `colorFormats`: no depth, no culling, viewport and scissor set by beginPoints.
gpu::GraphicsPipelineDesc pointPipeline(const std::string& name, const gpu::PipelineLayout& layout,
                                        std::span<const uint32_t> vertexSpirv, std::span<const uint32_t> fragmentSpirv,
                                        std::vector<VkFormat> colorFormats);

/// Begins rendering into `targets` (COLOR_ATTACHMENT_OPTIMAL, all at least
/// `area` large), clearing them to `clear` inside `area`, the render area
/// and scissor, with `viewport`.
void beginTargets(VkCommandBuffer cmd, std::span<gpu::Image* const> targets, const VkRect2D& area,
                  const VkViewport& viewport, VkClearColorValue clear);

/// Begins rendering into `targets` (all the same size, COLOR_ATTACHMENT_OPTIMAL),
/// clearing their first `rows` rows to zero and rendering only those. The
/// viewport is the whole target, so texel i is where r2vb_points.glsl puts
/// point i; the target's size goes to the shaders as push constants of `layout`.
void beginPoints(VkCommandBuffer cmd, std::span<gpu::Image* const> targets, uint32_t rows,
                 const gpu::PipelineLayout& layout);

/// The R2VB step: copies the first `rows` rows of `image` (TRANSFER_SRC_OPTIMAL)
/// to `buffer` at `offset`, tightly packed, so texel i lands at element i.
void copyRows(VkCommandBuffer cmd, const gpu::Image& image, uint32_t rows, const gpu::Buffer& buffer,
              VkDeviceSize offset);

} // namespace tessera::backends::r2vb
