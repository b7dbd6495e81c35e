#pragma once
/// @file Pipeline.h
/// Graphics pipelines for dynamic rendering, described by a plain struct.

#include "tessera/gpu/UniqueHandle.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tessera::gpu {

class Device;
class PipelineLayout;

/// SPIR-V for one stage, usually from a header generated at build time.
struct ShaderStage {
    VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
    std::span<const uint32_t> spirv;
};

struct GraphicsPipelineDesc {
    std::string name;
    const PipelineLayout* layout = nullptr;
    std::vector<ShaderStage> stages;
    std::vector<VkVertexInputBindingDescription> vertexBindings;
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    uint32_t patchControlPoints = 0; ///< > 0 with tessellation stages
    VkPolygonMode polygonMode = VK_POLYGON_MODE_FILL;
    VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthTest = true;
    bool depthWrite = true;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    /// Depth bias (both zero: none): a shadow map's casters pushed away from
    /// the sun by a constant (in the depth format's steps) and by their slope.
    float depthBiasConstant = 0.0f;
    float depthBiasSlope = 0.0f;
    /// Straight alpha blending (src alpha, one minus src alpha) on every
    /// colour target: overlays drawn over the frame.
    bool alphaBlend = false;
    /// With no fragment output (transform feedback, R2VB-to-buffer passes).
    bool rasterizerDiscard = false;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
};

class Pipeline {
public:
    Pipeline() = default;
    Pipeline(Device& device, const GraphicsPipelineDesc& desc);

    VkPipeline handle() const { return mPipeline.get(); }
    bool valid() const { return bool(mPipeline); }

private:
    UniqueHandle<VkPipeline, VK_OBJECT_TYPE_PIPELINE> mPipeline;
};

} // namespace tessera::gpu
