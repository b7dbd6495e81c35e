#include "MeshshaderPatternTables.h"

namespace tessera::backends {
namespace {

template <class T>
gpu::Buffer uploadTable(gpu::Device& device, std::span<const T> items, std::string name) {
    gpu::Buffer buffer(device, items.size_bytes(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                       std::move(name));
    buffer.upload(items);
    return buffer;
}

} // namespace

MeshshaderPatternTables::MeshshaderPatternTables(gpu::Device& device, std::span<const shader::TsMeshKey> keys,
                                                 std::span<const uint32_t> triangles, const std::string& name,
                                                 std::span<const glm::uvec4> groups)
    : mKeys(uploadTable(device, keys, name + ".patternKeys")),
      mTriangles(uploadTable(device, triangles, name + ".patternTriangles")) {
    if (!groups.empty()) mGroups = uploadTable(device, groups, name + ".patternGroups");
}

std::array<VkDescriptorBufferInfo, 2> MeshshaderPatternTables::descriptors() const {
    return {VkDescriptorBufferInfo{mKeys.handle(), 0, VK_WHOLE_SIZE},
            VkDescriptorBufferInfo{mTriangles.handle(), 0, VK_WHOLE_SIZE}};
}

} // namespace tessera::backends
