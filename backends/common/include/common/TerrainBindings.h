#pragma once
/// @file TerrainBindings.h
/// The descriptor bindings every terrain pass shares (set 0, TerrainUniforms.h
/// and FrameUniforms.h): the frame, the terrain's uniforms, its height map,
/// sun-visibility map and detail array, the characters' shadow mask, and the
/// cascaded shadow maps' uniforms and layers (ShadowCascades.h).
/// Each pass builds its layout from them plus its own bindings
/// (terrainLayout); BasicTerrainBackend::pushTerrainDescriptors fills them,
/// and pass objects reach it through a PushTerrainBindings.

#include "tessera/gpu/PipelineLayout.h"

#include <functional>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace tessera::backends {

/// Pushes set 0 for `layout`: the terrain's shared bindings plus `extra`
/// (the pass's own bindings, which `layout` declares after them).
using PushTerrainBindings = std::function<void(VkPipelineBindPoint bindPoint, const gpu::PipelineLayout& layout,
                                               std::span<const VkWriteDescriptorSet> extra)>;

/// The eight shared bindings, each visible to `stages`, the frame's first,
/// followed by `extra`.
std::vector<gpu::BindingDesc> terrainBindings(VkShaderStageFlags stages,
                                              std::initializer_list<gpu::BindingDesc> extra = {});

/// A pipeline layout of terrainBindings(stages, extra) with the given push
/// constants, named `name`.
gpu::PipelineLayout terrainLayout(gpu::Device& device, VkShaderStageFlags stages,
                                  std::initializer_list<gpu::BindingDesc> extra, uint32_t pushConstantBytes,
                                  VkShaderStageFlags pushConstantStages, std::string name);

} // namespace tessera::backends
