#include "common/EmulatedCharacterPass.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/tessellator/Tessellator.h"

#include "character.frag.spv.h"
#include "character_emulated.vert.spv.h"
#include "character_emulated.vert_shadow.spv.h"
#include "character_emulated.vert_single.spv.h"
#include "character_emulated.vert_single_shadow.spv.h"

#include <bit>
#include <cstring>

namespace tessera::backends {
namespace {

// The stream grows to the largest frame seen; a frame of a few dozen distinct
// levels needs well under this.
constexpr VkDeviceSize kInitialStreamBytes = 256 * 1024;

} // namespace

EmulatedCharacterPass::EmulatedCharacterPass(gpu::Device& device, const std::string& backendName,
                                             VkFormat colorFormat, VkFormat depthFormat, bool wireframe)
    : mDevice(&device), mName(backendName) {
    const VkShaderStageFlags graphics = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    mLayout = characterLayout(device, CharacterBindings::Draw, graphics, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 0, 0,
                              backendName + ".characterEmulated.layout");
    for (int single = 0; single < 2; ++single) {
        gpu::GraphicsPipelineDesc desc;
        desc.layout = &mLayout;
        const std::span<const uint32_t> vertex = single ? std::span<const uint32_t>(character_emulated_vert_single_spv)
                                                        : std::span<const uint32_t>(character_emulated_vert_spv);
        desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vertex},
                       {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_spv}};
        // Binding 0: the pattern's domain points (per vertex); binding 1: the
        // cage triangle's three vertex indices (per instance), read straight
        // from the cage's index buffer.
        desc.vertexBindings = {{0, sizeof(float) * 2, VK_VERTEX_INPUT_RATE_VERTEX},
                               {1, sizeof(uint32_t) * 3, VK_VERTEX_INPUT_RATE_INSTANCE}};
        desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32G32B32_UINT, 0}};
        // Back faces culled. Camera::projection flips Y for Vulkan's
        // framebuffer, which turns glTF's counter-clockwise front faces into
        // clockwise ones on screen.
        desc.cullMode = VK_CULL_MODE_BACK_BIT;
        desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
        desc.colorFormats = {colorFormat};
        desc.depthFormat = depthFormat;
        desc.name = backendName + ".character." + (single ? "singlePass" : "twoPass");
        mPipelines[single] = FillWirePipelines(device, desc, desc.name, wireframe);
        const VkShaderStageFlags vertexStage = VK_SHADER_STAGE_VERTEX_BIT;
        mShadow[single] = ShadowCasterPipeline(
            device, desc,
            characterLayout(device, CharacterBindings::Draw, vertexStage, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER,
                            ShadowCasterPipeline::kPushBytes, vertexStage, desc.name + ".shadow.layout"),
            vertexStage,
            {{VK_SHADER_STAGE_VERTEX_BIT, single ? std::span<const uint32_t>(character_emulated_vert_single_shadow_spv)
                                                 : std::span<const uint32_t>(character_emulated_vert_shadow_spv)}});
    }
}

void EmulatedCharacterPass::beginFrame(uint32_t slot) {
    mSlots[slot].used = 0;
    mSlots[slot].placed.clear();
}

uint64_t EmulatedCharacterPass::bytes() const {
    uint64_t total = 0;
    for (const Slot& s : mSlots) total += s.stream.size();
    return total;
}

EmulatedCharacterPass::Placed EmulatedCharacterPass::place(uint32_t slot, float level) {
    Slot& s = mSlots[slot];
    const uint32_t key = std::bit_cast<uint32_t>(level);
    if (auto it = s.placed.find(key); it != s.placed.end()) return it->second;

    tessellator::TessFactors factors;
    factors.outer = {level, level, level, level};
    factors.inner = {level, level};
    const tessellator::TessellatedPatch pattern = tessellator::Tessellator::tessellate(
        tessellator::Domain::Triangle, tessellator::Partitioning::FractionalOdd, factors);
    const VkDeviceSize pointBytes = pattern.uv.size() * sizeof(glm::vec2);
    const VkDeviceSize indexBytes = pattern.indices.size() * sizeof(uint32_t);
    const VkDeviceSize need = (s.used + pointBytes + indexBytes + 15) & ~VkDeviceSize(15);
    if (!s.stream.valid() || need > s.stream.size()) {
        // Growing mid-frame would invalidate offsets already recorded: keep
        // the old stream alive until this frame retires and start a new one.
        VkDeviceSize size = std::max(kInitialStreamBytes, s.stream.size() * 2);
        while (size < pointBytes + indexBytes) size *= 2;
        if (s.stream.valid()) s.stream.deferredReset();
        s.stream = gpu::Buffer(*mDevice, size, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                               gpu::MemoryUsage::CpuToGpu,
                               mName + ".characterPattern[" + std::to_string(slot) + "]");
        s.used = 0;
        s.placed.clear();
    }
    Placed p;
    p.vertexOffset = s.used;
    p.indexOffset = s.used + pointBytes;
    p.indexCount = static_cast<uint32_t>(pattern.indices.size());
    auto* base = static_cast<std::byte*>(s.stream.mapped());
    std::memcpy(base + p.vertexOffset, pattern.uv.data(), pointBytes);
    std::memcpy(base + p.indexOffset, pattern.indices.data(), indexBytes);
    s.used = (p.indexOffset + indexBytes + 15) & ~VkDeviceSize(15);
    s.placed.emplace(key, p);
    return p;
}

void EmulatedCharacterPass::record(gpu::FrameContext& frame, const CharacterInstance& instance,
                                   backend::CharacterPath path, bool wireframe, const CharacterPushFn& push) {
    const int single = path == backend::CharacterPath::SinglePass ? 1 : 0;
    vkCmdBindPipeline(frame.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines[single].get(wireframe).handle());
    drawPattern(frame, mLayout, instance, push);
}

void EmulatedCharacterPass::recordShadow(gpu::FrameContext& frame, const CharacterInstance& instance,
                                         backend::CharacterPath path, const shader::ShadowCasterPush& caster,
                                         const CharacterPushFn& push) {
    const ShadowCasterPipeline& shadow = mShadow[path == backend::CharacterPath::SinglePass ? 1 : 0];
    shadow.bind(frame.cmd(), caster);
    drawPattern(frame, shadow.layout(), instance, push);
}

void EmulatedCharacterPass::drawPattern(gpu::FrameContext& frame, const gpu::PipelineLayout& layout,
                                        const CharacterInstance& instance, const CharacterPushFn& push) {
    VkCommandBuffer cmd = frame.cmd();
    GpuCharacter& c = *instance.character;
    // The caster and the main draw place the same level: one pattern.
    const Placed pattern = place(frame.slot(), instance.level);
    const VkBufferView cage = c.vertexTexels();
    const VkBufferView compressed = instance.compressed ? instance.compressed->view.handle() : cage;
    const VkWriteDescriptorSet writes[2] = {texelWrite(TS_BINDING_CAGE_VERTICES, &cage),
                                            texelWrite(TS_BINDING_COMPRESSED, &compressed)};
    push(VK_PIPELINE_BIND_POINT_GRAPHICS, CharacterBindings::Draw, layout, instance, writes);
    const gpu::Buffer& stream = mSlots[frame.slot()].stream;
    const VkBuffer buffers[2] = {stream.handle(), c.indices().handle()};
    const VkDeviceSize offsets[2] = {pattern.vertexOffset, 0};
    vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
    vkCmdBindIndexBuffer(cmd, stream.handle(), pattern.indexOffset, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, pattern.indexCount, c.triangleCount(), 0, 0, 0);
}

} // namespace tessera::backends
