#include "common/TerrainBindings.h"

#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/ShadowCascades.h"
#include "tessera/shaders/TerrainUniforms.h"

namespace tessera::backends {

std::vector<gpu::BindingDesc> terrainBindings(VkShaderStageFlags stages,
                                              std::initializer_list<gpu::BindingDesc> extra) {
    constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    std::vector<gpu::BindingDesc> bindings = {{TS_BINDING_FRAME, kUniform, stages},
                                              {TS_BINDING_TERRAIN, kUniform, stages},
                                              {TS_BINDING_HEIGHTMAP, kSampled, stages},
                                              {TS_BINDING_SUN_VISIBILITY, kSampled, stages},
                                              {TS_BINDING_DETAIL, kSampled, stages},
                                              {TS_BINDING_CHARACTER_SHADOW, kSampled, stages},
                                              {TS_BINDING_SHADOW_CASCADES, kUniform, stages},
                                              {TS_BINDING_SHADOW_MAP, kSampled, stages}};
    bindings.insert(bindings.end(), extra.begin(), extra.end());
    return bindings;
}

gpu::PipelineLayout terrainLayout(gpu::Device& device, VkShaderStageFlags stages,
                                  std::initializer_list<gpu::BindingDesc> extra, uint32_t pushConstantBytes,
                                  VkShaderStageFlags pushConstantStages, std::string name) {
    return gpu::PipelineLayout(device, terrainBindings(stages, extra), pushConstantBytes, pushConstantStages,
                               std::move(name));
}

} // namespace tessera::backends
