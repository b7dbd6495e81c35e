#pragma once
/// @file DeviceFeatures.h
/// What a device offers, in the engine's words and without Vulkan: the
/// shared Vulkan layer (gpu::Instance, gpu::Device) fills it from the
/// physical device, and the backend contract's capability query reads it,
/// so neither the contract nor the null backend needs Vulkan to reason
/// about a device. FeatureMask.h hides features from it.

#include <cstdint>
#include <string>

namespace tessera::device {

struct DeviceFeatures {
    std::string deviceName;          ///< e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string driverName;          ///< e.g. "llvmpipe" or "NVIDIA"
    std::string driverInfo;          ///< driver version text
    bool isCpu = false;              ///< a software rasterizer such as lavapipe
    bool tessellationShader = false; ///< tessellation control/evaluation stages
    bool geometryShader = false;
    bool transformFeedback = false;  ///< VK_EXT_transform_feedback with draw-indirect-byte-count
    bool pipelineStatistics = false; ///< pipeline statistics queries
    bool timestamps = false;         ///< timestamp queries on the graphics queue
    bool fillModeNonSolid = false;   ///< wireframe
    bool vertexStores = false;       ///< storage writes from vertex/tess/geometry stages
    bool multiDrawIndirect = false;  ///< indirect draws of many commands with a first instance (emulated tessellator)
    uint32_t maxTessellationLevel = 0;
    /// VK_EXT_mesh_shader with both stages: task (amplification) and mesh.
    bool meshShader = false;
    /// The extension's queries: task and mesh shader invocations in the
    /// pipeline statistics, and the mesh primitives generated query.
    bool meshShaderQueries = false;
    /// One mesh workgroup's limits (0 without mesh shaders): what a patch's
    /// pattern must be split by, and what a task workgroup may hand on.
    uint32_t maxMeshOutputVertices = 0;
    uint32_t maxMeshOutputPrimitives = 0;
    uint32_t maxMeshWorkGroupInvocations = 0;
    uint32_t maxTaskPayloadSize = 0; ///< bytes
};

} // namespace tessera::device
