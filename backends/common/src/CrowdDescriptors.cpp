#include "common/CrowdDescriptors.h"

#include "tessera/shaders/CharacterUniforms.h"
#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/ShadowCascades.h"

namespace tessera::backends {
namespace {

constexpr VkDescriptorType kUniform = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kTexel = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;

// Buffer bindings of each mode, in the order the constructor fills them.
constexpr std::pair<uint32_t, VkDescriptorType> kStorageBuffers[] = {
    {TS_BINDING_FRAME, kUniform},       {TS_BINDING_CROWD, kUniform},       {TS_BINDING_CROWD_INSTANCES, kStorage},
    {TS_BINDING_CROWD_LISTS, kStorage}, {TS_BINDING_CROWD_CLIPS, kStorage}, {TS_BINDING_CROWD_VERTICES, kStorage},
    {TS_BINDING_CROWD_STATE, kStorage}, {TS_BINDING_CROWD_ARGS, kStorage},  {TS_BINDING_CROWD_NEAR, kStorage},
    {TS_BINDING_CROWD_SLOTS, kStorage}};
constexpr uint32_t kStorageTexels[] = {TS_BINDING_CROWD_BAKED, TS_BINDING_CROWD_BAKED_VERTICES,
                                       TS_BINDING_CROWD_CLIP_MESHES, TS_BINDING_CROWD_OCCLUDERS};
constexpr std::pair<uint32_t, VkDescriptorType> kTexelBuffers[] = {{TS_BINDING_FRAME, kUniform},
                                                                   {TS_BINDING_CROWD, kUniform}};
constexpr uint32_t kTexelTexels[] = {
    TS_BINDING_CROWD_BAKED, TS_BINDING_CROWD_INSTANCES, TS_BINDING_CROWD_CLIPS,          TS_BINDING_CROWD_NEAR,
    TS_BINDING_CROWD_SLOTS, TS_BINDING_CROWD_INDICES,   TS_BINDING_CROWD_BAKED_VERTICES, TS_BINDING_CROWD_CLIP_MESHES,
    TS_BINDING_CROWD_OCCLUDERS};
// The creature's maps, then the crowd's impostor atlases.
constexpr uint32_t kImageBindings[] = {TS_BINDING_BASE_COLOR, TS_BINDING_NORMAL_MAP, TS_BINDING_DISPLACEMENT,
                                       TS_BINDING_CROWD_IMPOSTOR_ALBEDO, TS_BINDING_CROWD_IMPOSTOR_NORMAL};

std::span<const std::pair<uint32_t, VkDescriptorType>> buffersOf(CrowdDescriptors::Mode mode) {
    if (mode == CrowdDescriptors::Mode::Storage) return kStorageBuffers;
    return kTexelBuffers;
}

std::span<const uint32_t> texelsOf(CrowdDescriptors::Mode mode) {
    if (mode == CrowdDescriptors::Mode::Storage) return kStorageTexels;
    return kTexelTexels;
}

} // namespace

gpu::PipelineLayout CrowdDescriptors::layout(gpu::Device& device, Mode mode, VkShaderStageFlags stages,
                                             std::string name, std::initializer_list<gpu::BindingDesc> extra,
                                             uint32_t pushConstantBytes, VkShaderStageFlags pushConstantStages) {
    std::vector<gpu::BindingDesc> bindings;
    for (const auto& [binding, type] : buffersOf(mode)) bindings.push_back({binding, type, stages});
    for (uint32_t binding : texelsOf(mode)) bindings.push_back({binding, kTexel, stages});
    for (uint32_t binding : kImageBindings)
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages});
    bindings.push_back({TS_BINDING_SHADOW_CASCADES, kUniform, stages});
    bindings.push_back({TS_BINDING_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages});
    bindings.insert(bindings.end(), extra.begin(), extra.end());
    return gpu::PipelineLayout(device, bindings, pushConstantBytes, pushConstantStages, std::move(name));
}

CrowdDescriptors::CrowdDescriptors(Mode mode, GpuCrowd& crowd, uint32_t slot, const gpu::UniformSlice& frame,
                                   const gpu::UniformSlice& uniforms, std::span<const VkWriteDescriptorSet> shadows)
    : mCrowd(crowd) {
    auto whole = [](gpu::Buffer& b) { return VkDescriptorBufferInfo{b.handle(), 0, VK_WHOLE_SIZE}; };
    if (mode == Mode::Storage) {
        mBuffers = {frame.descriptor(),       uniforms.descriptor(), whole(crowd.instances(slot)),
                    whole(crowd.lists()),     whole(crowd.clips()),  whole(crowd.vertices()),
                    whole(crowd.state()),     whole(crowd.args()),   whole(crowd.nearCages()),
                    whole(crowd.nearOwners())};
        mTexels[0] = crowd.bakedView();
        mTexels[1] = crowd.bakedVerticesView();
        mTexels[2] = crowd.clipMeshesView();
        mTexels[3] = crowd.occludersView(slot);
    } else {
        mBuffers[0] = frame.descriptor();
        mBuffers[1] = uniforms.descriptor();
        mTexels = {crowd.bakedView(),     crowd.instancesView(slot), crowd.clipsView(),         crowd.nearCagesView(),
                   crowd.nearSlotsView(), crowd.indicesView(),       crowd.bakedVerticesView(), crowd.clipMeshesView(),
                   crowd.occludersView(slot)};
    }
    const auto buffers = buffersOf(mode);
    const auto texels = texelsOf(mode);
    for (size_t i = 0; i < buffers.size(); ++i)
        mWrites.push_back(bufferWrite(buffers[i].first, buffers[i].second, &mBuffers[i]));
    for (size_t i = 0; i < texels.size(); ++i) mWrites.push_back(texelWrite(texels[i], &mTexels[i]));
    mFirstImage = mWrites.size();
    for (size_t i = 0; i < kImages; ++i) mWrites.push_back(imageWrite(kImageBindings[i], &mImages[i]));
    mWrites.insert(mWrites.end(), shadows.begin(), shadows.end());
}

std::span<const VkWriteDescriptorSet> CrowdDescriptors::writes(uint32_t creature) {
    GpuCharacter& c = *mCrowd.creatures()[creature].character;
    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    mImages = {VkDescriptorImageInfo{c.sampler().handle(), c.baseColor().view(), read},
               VkDescriptorImageInfo{c.sampler().handle(), c.normalMap().view(), read},
               VkDescriptorImageInfo{c.sampler().handle(), c.displacementMap().view(), read},
               mCrowd.impostors().albedo(), mCrowd.impostors().normal()};
    return mWrites;
}

} // namespace tessera::backends
