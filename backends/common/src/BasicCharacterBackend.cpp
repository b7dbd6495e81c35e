#include "common/BasicCharacterBackend.h"

#include "common/CommandHelpers.h"
#include "common/CrowdTierCounts.h"
#include "tessera/shaders/CrowdLod.h"
#include "tessera/shaders/FrameUniforms.h"
#include "tessera/shaders/ShadowCascades.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/tessellator/Tessellator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessera::backends {
namespace {

// The world sphere around a character placed by `world`: its asset's box
// (the compressed cage's, bind pose) with a quarter more radius for the
// limbs an animation swings out of it.
glm::vec4 boundingSphere(const GpuCharacter& character, const glm::mat4& world) {
    const glm::vec3 centre = 0.5f * (character.boxMin() + character.boxMax());
    const float scale = std::max({glm::length(glm::vec3(world[0])), glm::length(glm::vec3(world[1])),
                                  glm::length(glm::vec3(world[2]))});
    const float radius = 1.25f * 0.5f * glm::length(character.boxMax() - character.boxMin()) * scale;
    return glm::vec4(glm::vec3(world * glm::vec4(centre, 1.0f)), radius);
}

} // namespace

gpu::PipelineLayout characterLayout(gpu::Device& device, CharacterBindings bindings, VkShaderStageFlags stages,
                                    VkDescriptorType cageType, uint32_t pushConstantBytes,
                                    VkShaderStageFlags pushConstantStages, std::string name,
                                    std::initializer_list<gpu::BindingDesc> extra) {
    std::vector<gpu::BindingDesc> layout = {{TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                            {TS_BINDING_CHARACTER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                            {TS_BINDING_CHARACTER_PALETTE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages}};
    if (cageType != VK_DESCRIPTOR_TYPE_MAX_ENUM) {
        layout.push_back({TS_BINDING_CAGE_VERTICES, cageType, stages});
        layout.push_back({TS_BINDING_COMPRESSED, cageType, stages});
    }
    if (bindings == CharacterBindings::Draw) {
        for (uint32_t binding : {TS_BINDING_BASE_COLOR, TS_BINDING_NORMAL_MAP, TS_BINDING_DISPLACEMENT})
            layout.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages});
        // The cascaded shadow maps the characters receive (CascadedShadowMaps).
        layout.push_back({TS_BINDING_SHADOW_CASCADES, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages});
        layout.push_back({TS_BINDING_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages});
    }
    layout.insert(layout.end(), extra.begin(), extra.end());
    return gpu::PipelineLayout(device, layout, pushConstantBytes, pushConstantStages, std::move(name));
}

Result<backend::CharacterHandle> BasicCharacterBackend::createCharacter(const backend::CharacterDesc& desc) {
    auto created = GpuCharacter::create(*mDevice, desc, compressedCageUsage());
    if (!created) return created.error();
    return mCharacters.add(*mDevice, std::move(created.value()), [this](GpuCharacter& character, auto) {
        return attachCharacterResources(character);
    });
}

void BasicCharacterBackend::destroyCharacter(backend::CharacterHandle handle) {
    if (mDevice) mCharacters.destroy(*mDevice, handle);
}

void BasicCharacterBackend::releaseObjects() {
    mCrowds.clear();
    mCharacters.clear();
    BasicSubdivBackend::releaseObjects();
}

void BasicCharacterBackend::drawCharacters(const backend::CharacterDrawInfo& draw) {
    const float maxLevel = capabilities(nullptr).maxTessFactor;
    std::vector<CharacterInstance> instances;
    instances.reserve(draw.items.size());
    // Instances of one character in this frame each need their own compressed cage.
    std::vector<uint32_t> seen(mCharacters.size(), 0);
    for (const backend::CharacterDrawItem& item : draw.items) {
        GpuCharacter* character = mCharacters.find(item.character);
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
        instance.sphere = boundingSphere(*character, item.world);
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
    // The casters' depths before any receiver reads them (the characters
    // below, the crowds and the terrain after).
    if (mCascadedShadows) {
        suspendMainPass();
        mShadowMaps.record(*mFrame, "shadows.characters", [&](uint32_t, const shader::ShadowCasterPush& caster) {
            for (const CharacterInstance& instance : instances) {
                // The cull per cascade, on the CPU: the crowds' casters run
                // the same test in their shaders.
                const float viewDepth = -(mFrameInfo.view * glm::vec4(glm::vec3(instance.sphere), 1.0f)).z;
                if (!shader::tsShadowCasterOutside(instance.sphere, viewDepth, caster.viewProjection, caster.cull))
                    drawCharacterShadow(instance, draw.path, caster);
            }
        });
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

Result<backend::CrowdHandle> BasicCharacterBackend::createCrowd(const backend::CrowdDesc& desc) {
    if (!capabilities(nullptr).crowd)
        return fail("backend ", capabilities(nullptr).name,
                    " draws no instanced crowds (BackendCapabilities::crowd); draw the crowd with drawCharacters");
    if (!mDevice) return fail("createCrowd before initialize");
    auto created = GpuCrowd::create(
        *mDevice, desc, [this](backend::CharacterHandle h) { return mCharacters.find(h); }, crowdWriteUsage());
    if (!created) return created.error();
    return mCrowds.add(*mDevice, std::move(created.value()),
                       [this, &desc](GpuCrowd& crowd, backend::CrowdHandle handle) {
                           return attachCrowdResources(crowd, handle, desc);
                       });
}

void BasicCharacterBackend::destroyCrowd(backend::CrowdHandle handle) {
    if (mDevice) mCrowds.destroy(*mDevice, handle);
}

void BasicCharacterBackend::drawCrowd(backend::CrowdHandle handle, const backend::CrowdDrawInfo& draw) {
    GpuCrowd* crowd = mCrowds.find(handle);
    if (!crowd) return;
    CrowdFrame frame;
    frame.slot = mFrame->slot();
    // The counts this slot's previous frame wrote: its fence has signalled.
    reportCrowdCounts(*crowd, frame.slot, mReport);
    frame.instanceCount = crowd->uploadInstances(frame.slot, draw.instances);
    // The horizon's grid; one the buffers cannot hold, or shorter than its
    // size says, turns occlusion off rather than read past it.
    backend::CrowdDrawInfo checked = draw;
    const size_t cells = size_t(draw.lod.occluder.w) * size_t(draw.lod.occluder.w);
    if (cells != 0 &&
        (draw.occluders.size() < cells || !crowd->uploadOccluders(frame.slot, draw.occluders.first(cells))))
        checked.lod.occluder = glm::vec4(0.0f);
    frame.uniforms = mFrame->pushUniform(crowd->uniforms(checked, frame.instanceCount));
    suspendMainPass();
    recordCrowdPasses(*crowd, frame);
    recordCrowdCountsCopy(mFrame->cmd(), *crowd, frame.slot);
    if (mCascadedShadows) {
        prepareCrowdShadow(*crowd);
        mShadowMaps.record(*mFrame, "shadows.crowd", [&](uint32_t, const shader::ShadowCasterPush& caster) {
            recordCrowdShadow(*crowd, frame, caster);
        });
        ++mReport.passes;
    }
    ensureMainPass();
    recordCrowdDraws(*crowd, frame);
    const uint64_t bytes = crowd->bytes() + crowd->extensionBytes();
    mReport.passes += crowdPassCount();
    mReport.intermediateBytes += bytes;
    mReport.crowdBytes += bytes;
}

Result<backend::CrowdTiers> BasicCharacterBackend::readCrowdTiers(backend::CrowdHandle handle) {
    if (!capabilities(nullptr).crowd) return fail("backend ", capabilities(nullptr).name, " draws no instanced crowds");
    GpuCrowd* crowd = mCrowds.find(handle);
    if (!crowd) return fail("readCrowdTiers: no such crowd");
    return backends::readCrowdTiers(*mDevice, *crowd);
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
    writes.reserve(8 + extra.size());
    for (int i = 0; i < 3; ++i) writes.push_back(bufferWrite(bufferBindings[i], VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &buffers[i]));
    if (bindings == CharacterBindings::Draw) {
        for (int i = 0; i < 3; ++i) writes.push_back(imageWrite(imageBindings[i], &images[i]));
        writes.insert(writes.end(), mShadowMaps.writes().begin(), mShadowMaps.writes().end());
    }
    writes.insert(writes.end(), extra.begin(), extra.end());
    mDevice->fn().cmdPushDescriptorSet(mFrame->cmd(), bindPoint, layout.handle(), 0,
                                       static_cast<uint32_t>(writes.size()), writes.data());
}

} // namespace tessera::backends
