#pragma once
/// @file MeshshaderPatternTables.h
/// One pattern library on the GPU: the key table and the packed triangles a
/// mesh-shader tessellation draw reads (TS_BINDING_MESH_KEYS and
/// TS_BINDING_MESH_TRIANGLES, mesh_tess.glsl), and for uniform-level
/// triangle patches the group table (TS_BINDING_MESH_GROUPS), uploaded once
/// at start-up.

#include "tessera/gpu/Buffer.h"
#include "tessera/shaders/TessMeshPattern.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace tessera::backends {

class MeshshaderPatternTables {
public:
    MeshshaderPatternTables() = default;
    /// Uploads `keys` and `triangles` as "`name`.patternKeys" and "`name`.patternTriangles".
    MeshshaderPatternTables(gpu::Device& device, std::span<const shader::TsMeshKey> keys,
                            std::span<const uint32_t> triangles, const std::string& name,
                            std::span<const glm::uvec4> groups = {});

    /// The two tables' descriptors, in binding order (keys, triangles).
    std::array<VkDescriptorBufferInfo, 2> descriptors() const;
    /// The group table's descriptor (only for tables made with groups).
    VkDescriptorBufferInfo groupsDescriptor() const { return {mGroups.handle(), 0, VK_WHOLE_SIZE}; }
    uint64_t bytes() const { return mKeys.size() + mTriangles.size() + mGroups.size(); }

private:
    gpu::Buffer mKeys;
    gpu::Buffer mTriangles;
    gpu::Buffer mGroups;
};

} // namespace tessera::backends
