#pragma once
/// @file UiRenderer.h
/// Draws an overlay's triangle lists over the frame: the demo's Dear ImGui
/// windows, converted by the host into plain vertex, index and clip-rect
/// lists, so the GPU layer does not depend on the UI library (and the UI
/// library's single copy lives with the host that builds the UI).

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"

#include <array>
#include <cstdint>
#include <span>

namespace tessera::gpu {

class FrameContext;

/// One overlay vertex: pixel position, font-atlas UV and RGBA8 colour, the
/// layout of Dear ImGui's ImDrawVert, so its buffers copy as they are.
struct UiVertex {
    float x = 0.0f, y = 0.0f;
    float u = 0.0f, v = 0.0f;
    uint32_t rgba = 0;
};
static_assert(sizeof(UiVertex) == 20, "UiVertex must match ImDrawVert");

/// A run of indices drawn under one clip rectangle (pixels, display space).
struct UiDrawCommand {
    float clipMinX = 0.0f, clipMinY = 0.0f, clipMaxX = 0.0f, clipMaxY = 0.0f;
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    int32_t vertexOffset = 0;
};

/// One frame's overlay: every list merged, indices relative to each
/// command's vertexOffset.
struct UiDrawData {
    std::span<const UiVertex> vertices;
    std::span<const uint16_t> indices;
    std::span<const UiDrawCommand> commands;
    float displayX = 0.0f, displayY = 0.0f;
    float displayWidth = 0.0f, displayHeight = 0.0f;
};

class UiRenderer {
public:
    UiRenderer() = default;
    /// Pipeline for the host's target formats, and the font atlas (RGBA8,
    /// `fontWidth` x `fontHeight`) uploaded once.
    UiRenderer(Device& device, VkFormat colorFormat, VkFormat depthFormat, uint32_t fontWidth, uint32_t fontHeight,
               std::span<const uint8_t> fontRgba);
    UiRenderer(UiRenderer&&) noexcept = default;
    UiRenderer& operator=(UiRenderer&&) noexcept = default;

    /// Records `data` over the frame's target after the backend's passes, as
    /// the marked pass "overlay" (timed like every other pass). Vertices and
    /// indices go into this frame slot's buffers, grown when too small.
    void record(FrameContext& frame, const UiDrawData& data);

    bool valid() const { return mPipeline.valid(); }

private:
    /// Makes `buffer` hold at least `bytes`, replacing it when it is smaller
    /// (the slot's previous frame has retired, so nothing reads it).
    void reserve(Buffer& buffer, VkDeviceSize bytes, VkBufferUsageFlags usage, const char* name);

    Device* mDevice = nullptr;
    PipelineLayout mLayout;
    Pipeline mPipeline;
    Image mFont;
    Sampler mSampler;
    std::array<Buffer, kFramesInFlight> mVertices;
    std::array<Buffer, kFramesInFlight> mIndices;
};

} // namespace tessera::gpu
