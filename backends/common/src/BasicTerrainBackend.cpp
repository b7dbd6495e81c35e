#include "common/BasicTerrainBackend.h"

#include "common/TerrainBindings.h"
#include "tessera/shaders/TessFactors.h"

#include "common/CommandHelpers.h"
#include "common/FrameUniformsBuilder.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Readback.h"
#include "tessera/gpu/RenderTarget.h"

#include "terrain_basic.frag.spv.h"
#include "terrain_basic.vert.spv.h"

#include <cmath>
#include <cstring>

namespace tessera::backends {

void BasicTerrainBackend::checkRequirements(const device::DeviceFeatures* device, backend::BackendCapabilities& caps) {
    if (!device) return;
    using backend::TessellationPath;
    if (caps.tessellation == TessellationPath::Hardware && !device->tessellationShader)
        caps.missing.push_back("tessellation shaders (tessellationShader)");
    if (caps.tessellation == TessellationPath::Hardware && device->tessellationShader &&
        float(device->maxTessellationLevel) < caps.maxTessFactor)
        caps.missing.push_back("tessellation level " + std::to_string(int(caps.maxTessFactor)) + " (device max " +
                               std::to_string(device->maxTessellationLevel) + ")");
    if (caps.usesGeometryShaders && !device->geometryShader) caps.missing.push_back("geometry shaders (geometryShader)");
    if (caps.usesTransformFeedback && !device->transformFeedback)
        caps.missing.push_back("transform feedback (VK_EXT_transform_feedback)");
    if (caps.usesMeshShaders && !device->meshShader)
        caps.missing.push_back("task and mesh shaders (VK_EXT_mesh_shader)");
    if (caps.tessellation == TessellationPath::Emulated && !device->multiDrawIndirect)
        caps.missing.push_back("indirect draws with many commands and a first instance (multiDrawIndirect, "
                               "drawIndirectFirstInstance)");
}

backend::BackendCapabilities BasicTerrainBackend::capabilities(const device::DeviceFeatures* device) {
    backend::BackendCapabilities caps = describeCapabilities();
    checkRequirements(device, caps);
    return caps;
}

Status BasicTerrainBackend::initialize(const backend::BackendInitInfo& info) {
    if (!info.device) return fail("this backend needs a Vulkan device");
    auto caps = capabilities(&info.features);
    if (!caps.supported()) {
        std::string missing;
        for (const auto& m : caps.missing) missing += (missing.empty() ? "" : ", ") + m;
        return fail("backend ", caps.name, " cannot run on ", info.features.deviceName, ": it lacks ", missing);
    }
    mDevice = info.device;
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    mLayout = terrainLayout(*mDevice, stages, {}, 0, 0, caps.name + ".terrainLowres.layout");

    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, terrain_basic_vert_spv}, {VK_SHADER_STAGE_FRAGMENT_BIT, terrain_basic_frag_spv}};
    // Binding 0: the patch quad (per vertex); binding 1: visible patch index
    // (per instance), the D3D9-era way of instancing a patch over a terrain.
    desc.vertexBindings = {{0, sizeof(glm::vec2), VK_VERTEX_INPUT_RATE_VERTEX}, {1, sizeof(uint32_t), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0}, {1, 1, VK_FORMAT_R32_UINT, 0}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.colorFormats = {static_cast<VkFormat>(info.colorFormat)};
    desc.depthFormat = static_cast<VkFormat>(info.depthFormat);
    mWireframeSupported = info.features.fillModeNonSolid;
    mPipelines = FillWirePipelines(*mDevice, desc, caps.name + ".terrainLowres", mWireframeSupported);
    // Auto defers where it pays (docs/LOOKS.md, measured on the H200): the
    // compute resolve on a GPU costs a tenth of the terrain's fragment
    // shading; a fullscreen fragment resolve costs more than shading the
    // terrain's own fragments, and on a CPU rasterizer neither beats forward.
    mDeferOnAuto = !info.features.isCpu && terrainResolveMode() == TerrainResolvePass::Mode::Compute;
    // Auto keeps the blobs (docs/LOOKS.md, "The cost and auto"): on lavapipe
    // the cascaded look still costs 1.2 to 1.9 times the blob look with its
    // settings, over the 25% budget on some backend in every round (and
    // auto decides alike for every backend, so the frames stay the same);
    // on an H200 the showcase's cascades cost 1.7 to 3.6 ms, but at 65,000
    // agents the far casters quadruple the frame on the vertex-stage
    // backends.
    mCascadedOnAuto = false;
    mSplatPass = TerrainSplatPass(*mDevice, caps.name);
    mSunPass = TerrainSunPass(*mDevice, caps.name);
    mShadowPass = CharacterShadowPass(*mDevice, caps.name);
    mShadowMaps = CascadedShadowMaps(
        *mDevice, caps.name,
        scene::ShadowCascadeFit::Settings::forDevice(info.features.isCpu ? lod::DeviceClass::Cpu : lod::DeviceClass::Gpu));
    mSkyPass = SkyPass(*mDevice, caps.name, static_cast<VkFormat>(info.colorFormat),
                       static_cast<VkFormat>(info.depthFormat));
    mResolvePass = TerrainResolvePass(*mDevice, caps.name, terrainResolveMode(), static_cast<VkFormat>(info.colorFormat),
                                      static_cast<VkFormat>(info.depthFormat));
    return initializeTechnique(info);
}

void BasicTerrainBackend::shutdown() {
    if (mDevice) mDevice->waitIdle();
    releaseObjects();
    shutdownTechnique();
    mSplatPass = {};
    mSunPass = {};
    mShadowPass = {};
    mShadowMaps = {};
    mSkyPass = {};
    mResolvePass = {};
    mPipelines = {};
    mLayout = {};
    mDevice = nullptr;
}

Result<backend::TerrainHandle> BasicTerrainBackend::createTerrain(const backend::TerrainDesc& desc) {
    if (!desc.terrain) return fail("createTerrain: no terrain");
    if (Status supported = checkTerrain(desc); !supported) return supported.error();
    auto created = GpuTerrain::create(*mDevice, *desc.terrain, desc.detailTextures);
    if (!created) return created.error();
    return mTerrains.add(std::move(created.value()));
}

void BasicTerrainBackend::destroyTerrain(backend::TerrainHandle handle) {
    if (mDevice) mTerrains.destroy(*mDevice, handle);
}

void BasicTerrainBackend::beginFrame(const backend::FrameInfo& frame) {
    mFrameInfo = frame;
    mFrame = frame.gpu;
    mReport = {};
    mReport.frameIndex = frame.frameIndex;
    // Auto defers only where that pays (mDeferOnAuto). The wireframe stays
    // forward: a line's fragments take their attributes from the line, not
    // from the pixel centre's view ray the resolve reconstructs them on.
    const bool full = frame.look == backend::Look::Full && !frame.wireframe;
    mDeferTerrain = full && (frame.terrainShading == backend::TerrainShading::Deferred ||
                             (frame.terrainShading == backend::TerrainShading::Auto && mDeferOnAuto));
    const bool cascadedAsked = frame.shadows == backend::Shadows::Cascaded ||
                               (frame.shadows == backend::Shadows::Auto && mCascadedOnAuto);
    mCascadedShadows = full && cascadedAsked && capabilities(nullptr).cascadedShadows && !frame.shadowCascades.empty();
    // Cascaded shadows replace the blobs: no mask is drawn, none is read;
    // without shadows neither is.
    if (mCascadedShadows || frame.shadows == backend::Shadows::None) mFrameInfo.shadowCasters = {};
    mFrameUniforms = mFrame->pushUniform(buildFrameUniforms(mFrameInfo, mDeferTerrain));
    mShadowMaps.beginFrame(*mFrame, mCascadedShadows ? frame.shadowCascades : std::span<const scene::ShadowCascade>{},
                           frame.sunDirection);
    mMainPassOpen = false;
    mMainPassStarted = false;
    mResolveTerrain = nullptr;
    mPendingTerrains.clear();
    mMainPassDraws.clear();
    beginTechniqueFrame();
}

void BasicTerrainBackend::splatTerrain(backend::TerrainHandle handle, std::span<const terrain::CraterSplat> splats) {
    GpuTerrain* terrain = mTerrains.find(handle);
    if (!terrain || splats.empty()) return;
    // Splats render into the height map, so they must come before the main
    // pass (and before this frame's factor passes) reads it.
    suspendMainPass();
    mSplatPass.record(*mFrame, *terrain, splats);
    // The new craters cast and catch shadows.
    for (const auto& splat : splats)
        terrain->invalidateSunVisibility(glm::vec4(splat.center - splat.radius, splat.center + splat.radius));
    mReport.splatsApplied += static_cast<uint32_t>(splats.size());
}

void BasicTerrainBackend::ensureMainPass() {
    if (mMainPassOpen) return;
    if (mMainPassStarted) {
        mFrame->target().resumeRendering(mFrame->cmd());
    } else {
        // Deferred terrain: alpha 0 marks a pixel the terrain resolve or the
        // sky still has to shade (forward-shaded geometry writes 1), and
        // white, the largest distance the terrain stores, one nothing covered.
        const glm::vec4 color =
            mDeferTerrain ? glm::vec4(1.0f, 1.0f, 1.0f, 0.0f) : glm::vec4(glm::vec3(mFrameInfo.clearColor), 1.0f);
        const float clear[4] = {color.r, color.g, color.b, color.a};
        mFrame->target().beginRendering(mFrame->cmd(), clear);
    }
    mMainPassOpen = true;
    mMainPassStarted = true;
    // The draws that waited for it, in the order they came (each may call
    // ensureMainPass again: it is open now).
    std::vector<std::function<void()>> waiting;
    waiting.swap(mMainPassDraws);
    for (auto& draw : waiting) draw();
}

void BasicTerrainBackend::drawTerrainInMainPass(backend::TerrainMode mode, uint32_t patches,
                                                std::function<bool()> record) {
    auto draw = [this, mode, patches, record = std::move(record)] {
        ensureMainPass();
        gpu::PassScope pass(*mFrame, mode == backend::TerrainMode::Continuous ? "terrain.continuous" : "terrain.adaptive");
        if (patches == 0 || !record()) return;
        mReport.terrainPatchesDrawn += patches;
        ++mReport.passes;
    };
    // A GPU runs the passes between concurrently anyway: there the frame
    // keeps the order it is recorded in.
    if (mMainPassOpen || !mDevice->features().isCpu) draw();
    else mMainPassDraws.push_back(std::move(draw));
}

void BasicTerrainBackend::suspendMainPass() {
    if (!mMainPassOpen) return;
    mFrame->target().endRendering(mFrame->cmd());
    mMainPassOpen = false;
}

void BasicTerrainBackend::drawTerrain(backend::TerrainHandle handle, const backend::TerrainDrawInfo& draw) {
    GpuTerrain* terrain = mTerrains.find(handle);
    if (!terrain) return;
    // The sun-visibility map renders into its own target: before the main
    // pass and the backend's own passes, after this frame's splats. Kept
    // current in the plain look too, since every terrain layout binds it.
    suspendMainPass();
    mSunPass.update(*mFrame, *terrain, glm::normalize(mFrameInfo.sunDirection));
    // The characters' blob shadows on it, from where they stand this frame.
    if (mFrameInfo.look == backend::Look::Full && !mCascadedShadows)
        mShadowPass.record(*mFrame, mFrameInfo.shadowCasters, mFrameInfo.shadowRegion, mFrameInfo.sunDirection);
    if (mCascadedShadows) {
        // It receives the characters' shadows, whose depth passes come later
        // in the frame: its draw waits for endFrame.
        mPendingTerrains.push_back({terrain, {draw.visiblePatches.begin(), draw.visiblePatches.end()}, draw.tessellation});
        return;
    }
    recordTerrainDraw(*terrain, draw);
}

void BasicTerrainBackend::recordTerrainDraw(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw) {
    // A technique's factor passes reuse one set of buffers per frame slot:
    // an earlier terrain's draw still waiting for the main pass reads them,
    // so it is recorded before they are written again.
    if (!mMainPassDraws.empty()) {
        ensureMainPass();
        suspendMainPass();
    }
    // One terrain per frame is resolved (its pixels carry no terrain id);
    // from a second one on, terrains are shaded forward.
    if (mDeferTerrain && !mResolveTerrain)
        mResolveTerrain = &terrain;
    else if (mDeferTerrain && &terrain != mResolveTerrain)
        mFrameUniforms = mFrame->pushUniform(buildFrameUniforms(mFrameInfo, false));
    const auto mode = draw.tessellation.mode;
    if (mode == backend::TerrainMode::LowRes || !capabilities(nullptr).drawsTerrainMode(mode)) {
        drawControlMesh(terrain, draw.visiblePatches, "terrain.lowres");
        return;
    }
    backend::TerrainDrawInfo clamped = draw;
    clamped.tessellation.maxLevel = std::min(draw.tessellation.maxLevel, capabilities(nullptr).maxTessFactor);
    drawTessellated(terrain, clamped);
}

void BasicTerrainBackend::pushTerrainDescriptors(VkPipelineBindPoint bindPoint, const gpu::PipelineLayout& layout,
                                                 GpuTerrain& terrain, std::span<const VkWriteDescriptorSet> extra) {
    VkDescriptorBufferInfo frameInfo = mFrameUniforms.descriptor();
    VkDescriptorBufferInfo terrainInfo{terrain.uniformBuffer().handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo heightInfo{terrain.sampler().handle(), terrain.heightMap().view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo sunInfo{terrain.sampler().handle(), terrain.sunVisibility().view(),
                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo detailInfo{terrain.detailSampler().handle(), terrain.detailTextures().view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo shadowInfo = mShadowPass.descriptor();
    std::vector<VkWriteDescriptorSet> writes = {
        bufferWrite(TS_BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &frameInfo),
        bufferWrite(TS_BINDING_TERRAIN, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &terrainInfo),
        imageWrite(TS_BINDING_HEIGHTMAP, &heightInfo),
        imageWrite(TS_BINDING_SUN_VISIBILITY, &sunInfo),
        imageWrite(TS_BINDING_DETAIL, &detailInfo),
        imageWrite(TS_BINDING_CHARACTER_SHADOW, &shadowInfo)};
    writes.insert(writes.end(), mShadowMaps.writes().begin(), mShadowMaps.writes().end());
    writes.insert(writes.end(), extra.begin(), extra.end());
    mDevice->fn().cmdPushDescriptorSet(mFrame->cmd(), bindPoint, layout.handle(), 0, static_cast<uint32_t>(writes.size()),
                                       writes.data());
}

PushTerrainBindings BasicTerrainBackend::terrainPush(GpuTerrain& terrain) {
    return [this, &terrain](VkPipelineBindPoint bindPoint, const gpu::PipelineLayout& layout,
                            std::span<const VkWriteDescriptorSet> extra) {
        pushTerrainDescriptors(bindPoint, layout, terrain, extra);
    };
}

gpu::UniformSlice BasicTerrainBackend::pushTessUniforms(const GpuTerrain& terrain,
                                                       const terrain::TessellationSettings& settings, float maxLevel) {
    shader::TerrainTessUniforms tess{};
    const float top = std::clamp(settings.maxLevel, 1.0f, maxLevel);
    tess.levels = glm::vec4(std::clamp(settings.minLevel, 1.0f, top), top,
                            std::clamp(settings.continuousLevel, 1.0f, maxLevel), 0.0f);
    tess.metric = glm::vec4(settings.targetPixels, settings.farDistance, pixelsPerMetre(), 0.0f);
    tess.mode = glm::uvec4(uint32_t(settings.mode), uint32_t(settings.metric), terrain.patchesPerSide(),
                           terrain.edgeCount());
    return mFrame->pushUniform(tess);
}

float BasicTerrainBackend::pixelsPerMetre() const {
    return float(mFrameInfo.height) * std::abs(mFrameInfo.projection[1][1]) * 0.5f;
}

void BasicTerrainBackend::drawControlMesh(GpuTerrain& terrain, std::span<const uint32_t> patches, const char* passName) {
    ensureMainPass();
    gpu::PassScope pass(*mFrame, passName);
    if (patches.empty()) return;
    VkCommandBuffer cmd = mFrame->cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipelines.get(mFrameInfo.wireframe).handle());
    pushTerrainDescriptors(VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, terrain);

    gpu::Buffer& patchStream = terrain.writeVisiblePatches(mFrame->slot(), patches);
    VkBuffer vertexBuffers[2] = {terrain.quadVertices().handle(), patchStream.handle()};
    VkDeviceSize offsets[2] = {0, 0};
    vkCmdBindVertexBuffers(cmd, 0, 2, vertexBuffers, offsets);
    vkCmdBindIndexBuffer(cmd, terrain.quadIndices().handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, 6, static_cast<uint32_t>(patches.size()), 0, 0, 0);

    mReport.terrainPatchesDrawn += static_cast<uint32_t>(patches.size());
    mReport.trianglesSubmitted += uint64_t(2) * patches.size();
    ++mReport.passes;
}

Result<std::vector<uint16_t>> BasicTerrainBackend::readTerrainHeights(backend::TerrainHandle handle) {
    GpuTerrain* terrain = mTerrains.find(handle);
    if (!terrain) return fail("readTerrainHeights: unknown terrain handle");
    gpu::Image& heights = terrain->heightMap();
    const size_t count = size_t(heights.width()) * heights.height();
    const std::vector<std::byte> bytes = gpu::readBack(
        *mDevice, count * sizeof(uint16_t), "terrain.heightReadback", "terrain.readHeights",
        [&](VkCommandBuffer cmd, const gpu::Buffer& readback) {
            const VkImageAspectFlags color = VK_IMAGE_ASPECT_COLOR_BIT;
            gpu::transitionImage(cmd, heights.handle(), color, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                                 VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
            VkBufferImageCopy region{};
            region.imageSubresource = {color, 0, 0, 1};
            region.imageExtent = {heights.width(), heights.height(), 1};
            vkCmdCopyImageToBuffer(cmd, heights.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1,
                                   &region);
            gpu::transitionImage(cmd, heights.handle(), color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, 0,
                                 VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        });
    std::vector<uint16_t> samples(count);
    std::memcpy(samples.data(), bytes.data(), bytes.size());
    return samples;
}

void BasicTerrainBackend::endFrame() {
    // Every caster has written its depths; layers no caster wrote are
    // cleared before the terrain reads them.
    if (mCascadedShadows) {
        suspendMainPass();
        mShadowMaps.finishFrame(*mFrame);
        mReport.intermediateBytes += mShadowMaps.bytes();
    }
    for (const PendingTerrainDraw& pending : mPendingTerrains) {
        backend::TerrainDrawInfo draw;
        draw.visiblePatches = pending.patches;
        draw.tessellation = pending.tessellation;
        recordTerrainDraw(*pending.terrain, draw);
    }
    mPendingTerrains.clear();
    ensureMainPass(); // a frame with nothing drawn still clears the target
    const bool full = mFrameInfo.look == backend::Look::Full;
    const bool resolve = mDeferTerrain && mResolveTerrain;
    // The sky last, where nothing else drew (the depth test keeps the rest),
    // unless the compute resolve shades it with the terrain.
    if (full && !(resolve && mResolvePass.mode() == TerrainResolvePass::Mode::Compute))
        mSkyPass.record(*mFrame, mFrameUniforms);
    mFrame->target().endRendering(mFrame->cmd());
    mMainPassOpen = false;
    if (resolve) {
        mResolvePass.record(*mFrame, terrainPush(*mResolveTerrain));
        ++mReport.passes;
    }
    mLastReport = mReport;
    mFrame = nullptr;
}

} // namespace tessera::backends
