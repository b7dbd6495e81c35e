#include "common/BasicCharacterBackend.h"

#include "common/CommandHelpers.h"
#include "tessera/shaders/CrowdLod.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/tessellator/Tessellator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessera::backends {

gpu::PipelineLayout characterLayout(gpu::Device& device, CharacterBindings bindings, VkShaderStageFlags stages,
                                    VkDescriptorType cageType, uint32_t pushConstantBytes,
                                    VkShaderStageFlags pushConstantStages, std::string name) {
    std::vector<gpu::BindingDesc> layout = {{TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                            {TS_BINDING_CHARACTER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                            {TS_BINDING_CHARACTER_PALETTE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages}};
    if (cageType != VK_DESCRIPTOR_TYPE_MAX_ENUM) {
        layout.push_back({TS_BINDING_CAGE_VERTICES, cageType, stages});
        layout.push_back({TS_BINDING_COMPRESSED, cageType, stages});
    }
    if (bindings == CharacterBindings::Draw)
        for (uint32_t binding : {TS_BINDING_BASE_COLOR, TS_BINDING_NORMAL_MAP, TS_BINDING_DISPLACEMENT})
            layout.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages});
    return gpu::PipelineLayout(device, layout, pushConstantBytes, pushConstantStages, std::move(name));
}

Result<backend::CharacterHandle> BasicCharacterBackend::createCharacter(const backend::CharacterDesc& desc) {
    auto created = GpuCharacter::create(*mDevice, desc, compressedCageUsage());
    if (!created) return created.error();
    mCharacters.push_back(std::move(created.value()));
    return backend::CharacterHandle{static_cast<uint32_t>(mCharacters.size() - 1)};
}

GpuCharacter* BasicCharacterBackend::findCharacter(backend::CharacterHandle handle) {
    if (!handle.valid() || handle.id >= mCharacters.size()) return nullptr;
    return mCharacters[handle.id].get();
}

void BasicCharacterBackend::destroyCharacter(backend::CharacterHandle handle) {
    if (!findCharacter(handle)) return;
    // A frame in flight may still read it; release after that frame.
    auto* released = mCharacters[handle.id].release();
    mDevice->deferDestroy([released] { delete released; });
}

void BasicCharacterBackend::shutdown() {
    if (mDevice) mDevice->waitIdle();
    mCharacters.clear();
    mSubdivs.clear();
    BasicTerrainBackend::shutdown();
}

void BasicCharacterBackend::drawCharacters(const backend::CharacterDrawInfo& draw) {
    const float maxLevel = capabilities(nullptr).maxTessFactor;
    std::vector<CharacterInstance> instances;
    instances.reserve(draw.items.size());
    // Instances of one character in this frame each need their own compressed cage.
    std::vector<uint32_t> seen(mCharacters.size(), 0);
    for (const backend::CharacterDrawItem& item : draw.items) {
        GpuCharacter* character = findCharacter(item.character);
        if (!character || item.palette.size() < character->paletteSize()) continue;
        CharacterInstance instance;
        instance.character = character;
        // Only the near tier is tessellated and displaced: the middle and far
        // tiers draw the cage itself (level 1) lit by the normal map.
        const bool near = item.tier == TS_LOD_NEAR;
        instance.level = near ? std::clamp(std::isnan(item.tessLevel) ? 1.0f : item.tessLevel, 1.0f, maxLevel) : 1.0f;
        const float coverage = std::isnan(item.coverage) ? 1.0f : std::clamp(item.coverage, 0.0f, 1.0f);
        const glm::vec4 lod(coverage, item.fadingOut ? 1.0f : 0.0f, float(std::min(item.tier, TS_LOD_FAR)),
                            draw.lodColors ? 1.0f : 0.0f);
        instance.uniforms =
            mFrame->pushUniform(character->uniforms(item.world, instance.level, draw.displacement && near, lod));
        // Only the used joints are bound: the shaders index the palette by the
        // cage's joints, all below paletteSize (GpuCharacter checks them), and
        // a 16 KiB block per instance would fill the frame's uniform ring.
        instance.palette = mFrame->allocateUniform(character->paletteSize() * sizeof(glm::mat4));
        std::memcpy(instance.palette.data, item.palette.data(), character->paletteSize() * sizeof(glm::mat4));
        if (draw.path == backend::CharacterPath::TwoPass)
            instance.compressed = &character->compressed(mFrame->slot(), seen[item.character.id]++);
        instances.push_back(instance);
    }
    if (instances.empty()) return;
    // The technique's intermediates, next to the terrain's in the report: the
    // compressed cages this frame writes (the paper's 16 B per cage vertex)
    // and the pass objects' own targets and streams.
    for (const CharacterInstance& instance : instances)
        if (instance.compressed) mReport.intermediateBytes += instance.compressed->buffer.size();
    mReport.intermediateBytes += characterPassBytes();

    if (draw.path == backend::CharacterPath::TwoPass) {
        suspendMainPass();
        gpu::PassScope pass(*mFrame, "character.skin");
        for (const CharacterInstance& instance : instances) skinCharacter(instance);
        ++mReport.passes;
    }
    ensureMainPass();
    gpu::PassScope pass(*mFrame, draw.path == backend::CharacterPath::TwoPass ? "character.tessellate"
                                                                               : "character.singlePass");
    for (const CharacterInstance& instance : instances) {
        drawCharacter(instance, draw.path);
        ++mReport.charactersDrawn;
        mReport.characterCageTriangles += instance.character->triangleCount();
        // Every backend tessellates the cage triangle with fractional-odd
        // spacing at the draw's level: the emulated tessellator counts it.
        tessellator::TessFactors factors;
        factors.outer = {instance.level, instance.level, instance.level, instance.level};
        factors.inner = {instance.level, instance.level};
        const uint64_t triangles =
            uint64_t(instance.character->triangleCount()) *
            tessellator::Tessellator::countTriangles(tessellator::Domain::Triangle,
                                                     tessellator::Partitioning::FractionalOdd, factors);
        mReport.characterTriangles += triangles;
        mReport.trianglesSubmitted += triangles;
    }
    ++mReport.passes;
}

Result<backend::CrowdHandle> BasicCharacterBackend::createCrowd(const backend::CrowdDesc&) {
    return fail("backend ", capabilities(nullptr).name,
                " draws no instanced crowds (BackendCapabilities::crowd); draw the crowd with drawCharacters");
}

Result<backend::CrowdTiers> BasicCharacterBackend::readCrowdTiers(backend::CrowdHandle) {
    return fail("backend ", capabilities(nullptr).name, " draws no instanced crowds");
}

Result<backend::SubdivHandle> BasicCharacterBackend::createSubdiv(const backend::SubdivDesc& desc) {
    if (!capabilities(nullptr).subdiv)
        return fail("backend ", capabilities(nullptr).name,
                    " draws no subdivision surfaces (BackendCapabilities::subdiv)");
    return mSubdivs.create(desc);
}

void BasicCharacterBackend::destroySubdiv(backend::SubdivHandle surface) {
    mSubdivs.destroy(surface);
}

void BasicCharacterBackend::updateSubdivTiles(backend::SubdivHandle surface, const backend::SubdivTileData& tiles,
                                              std::span<const glm::uvec4> rects) {
    GpuSubdiv* s = mSubdivs.find(surface);
    if (!s || rects.empty()) return;
    suspendMainPass();
    if (Status updated = s->updateTiles(*mFrame, tiles, rects); !updated)
        log::error(updated.error().message);
}

void BasicCharacterBackend::drawSubdiv(backend::SubdivHandle surface, const backend::SubdivDrawInfo& draw) {
    GpuSubdiv* s = mSubdivs.find(surface);
    if (!s) return;
    s->uploadCage(mFrame->slot(), draw.cage);
    const gpu::UniformSlice uniforms = mFrame->pushUniform(draw.uniforms);
    suspendMainPass();
    subdivPrePasses(*s, uniforms);
    ensureMainPass();
    subdivDraw(*s, uniforms);
    mReport.subdivDomains += s->domainCount();
    mReport.intermediateBytes += s->bytes();
    mReport.passes += 2;
}

Result<backend::SubdivPoints> BasicCharacterBackend::readSubdivPoints(backend::SubdivHandle surface) {
    return mSubdivs.readPoints(surface);
}

CharacterPushFn BasicCharacterBackend::characterPush() {
    return [this](VkPipelineBindPoint point, CharacterBindings bindings, const gpu::PipelineLayout& layout,
                  const CharacterInstance& instance, std::span<const VkWriteDescriptorSet> extra) {
        pushCharacterDescriptors(point, bindings, layout, instance, extra);
    };
}

void BasicCharacterBackend::pushCharacterDescriptors(VkPipelineBindPoint bindPoint, CharacterBindings bindings,
                                                     const gpu::PipelineLayout& layout,
                                                     const CharacterInstance& instance,
                                                     std::span<const VkWriteDescriptorSet> extra) {
    GpuCharacter& c = *instance.character;
    const VkDescriptorBufferInfo buffers[3] = {mFrameUniforms.descriptor(), instance.uniforms.descriptor(),
                                               instance.palette.descriptor()};
    const uint32_t bufferBindings[3] = {TS_BINDING_FRAME, TS_BINDING_CHARACTER, TS_BINDING_CHARACTER_PALETTE};
    const VkDescriptorImageInfo images[3] = {
        {c.sampler().handle(), c.baseColor().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {c.sampler().handle(), c.normalMap().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {c.sampler().handle(), c.displacementMap().view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
    const uint32_t imageBindings[3] = {TS_BINDING_BASE_COLOR, TS_BINDING_NORMAL_MAP, TS_BINDING_DISPLACEMENT};
    std::vector<VkWriteDescriptorSet> writes;
    writes.reserve(6 + extra.size());
    for (int i = 0; i < 3; ++i) writes.push_back(bufferWrite(bufferBindings[i], VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &buffers[i]));
    if (bindings == CharacterBindings::Draw)
        for (int i = 0; i < 3; ++i) writes.push_back(imageWrite(imageBindings[i], &images[i]));
    writes.insert(writes.end(), extra.begin(), extra.end());
    mDevice->fn().cmdPushDescriptorSet(mFrame->cmd(), bindPoint, layout.handle(), 0,
                                       static_cast<uint32_t>(writes.size()), writes.data());
}

} // namespace tessera::backends
