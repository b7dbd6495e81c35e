#include "common/GpuSubdiv.h"

#include "common/CommandHelpers.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Readback.h"
#include "tessera/backend/SubdivChecks.h"

#include <algorithm>
#include <cstring>

namespace tessera::backends {

namespace {

template <class T>
void uploadArray(gpu::Device& device, gpu::Buffer& buffer, gpu::BufferView& view, const std::vector<T>& items,
                 VkFormat format, const std::string& name) {
    // An empty array still gets one texel, so every binding is valid.
    const VkDeviceSize bytes = std::max<VkDeviceSize>(items.size() * sizeof(T), sizeof(T));
    buffer = gpu::Buffer(device, bytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, gpu::MemoryUsage::GpuOnly, name);
    if (!items.empty()) buffer.upload(std::span<const T>(items));
    view = gpu::BufferView(device, buffer, format, 0, bytes, name + ".texels");
}

std::string slotTag(uint32_t slot) {
    std::string tag = "[";
    tag += std::to_string(slot);
    tag += ']';
    return tag;
}

} // namespace

Result<std::unique_ptr<GpuSubdiv>> GpuSubdiv::create(gpu::Device& device, const backend::SubdivDesc& desc,
                                                     VkBufferUsageFlags writeUsage) {
    if (Status ok = backend::checkSubdivDesc(desc); !ok) return ok.error();
    const backend::SubdivMeshData& mesh = *desc.mesh;
    const VkPhysicalDeviceLimits& limits = device.properties().limits;
    const uint64_t texels[] = {mesh.stencilEntries.size(), mesh.refinedPointCount(), 4ull * mesh.domains.size(),
                               mesh.patchIndices.size(), mesh.nodes.size(), mesh.support.size()};
    for (uint64_t count : texels)
        if (count > limits.maxTexelBufferElements)
            return fail("createSubdiv: ", mesh.name, " needs a texel buffer of ", std::to_string(count),
                        " texels, more than this device's maxTexelBufferElements (",
                        std::to_string(limits.maxTexelBufferElements), ")");
    const uint32_t side = std::max(desc.tiles.width, desc.tiles.height);
    if (side > limits.maxImageDimension2D)
        return fail("createSubdiv: ", mesh.name, "'s displacement tiles need a ", std::to_string(side),
                    "-texel texture, more than this device's maxImageDimension2D (",
                    std::to_string(limits.maxImageDimension2D), ")");

    auto s = std::unique_ptr<GpuSubdiv>(new GpuSubdiv());
    s->mName = mesh.name;
    s->mDevice = &device;
    s->mBaseVertexCount = mesh.baseVertexCount;
    s->mRefinedPointCount = mesh.refinedPointCount();
    s->mDomainCount = mesh.domainCount();
    s->mClosed = mesh.closed;
    const std::string base = "subdiv." + mesh.name;

    uploadArray(device, s->mStencils, s->mStencilsView, mesh.stencils, VK_FORMAT_R32G32B32A32_UINT, base + ".stencils");
    uploadArray(device, s->mEntries, s->mEntriesView, mesh.stencilEntries, VK_FORMAT_R32G32_UINT,
                base + ".stencilEntries");
    uploadArray(device, s->mDomains, s->mDomainsView, mesh.domains, VK_FORMAT_R32G32B32A32_UINT, base + ".domains");
    uploadArray(device, s->mNodes, s->mNodesView, mesh.nodes, VK_FORMAT_R32G32B32A32_UINT, base + ".quadtree");
    uploadArray(device, s->mPatches, s->mPatchesView, mesh.patches, VK_FORMAT_R32G32B32A32_UINT, base + ".patches");
    uploadArray(device, s->mIndices, s->mIndicesView, mesh.patchIndices, VK_FORMAT_R32_UINT, base + ".patchIndices");
    uploadArray(device, s->mSupport, s->mSupportView, mesh.support, VK_FORMAT_R32_UINT, base + ".support");

    const VkDeviceSize pointBytes = VkDeviceSize(mesh.refinedPointCount()) * sizeof(glm::vec4);
    s->mPoints = gpu::Buffer(device, pointBytes,
                             writeUsage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                             gpu::MemoryUsage::GpuOnly, base + ".refinedPoints");
    s->mPointsView =
        gpu::BufferView(device, s->mPoints, VK_FORMAT_R32G32B32A32_SFLOAT, 0, pointBytes, base + ".refinedPoints.texels");

    // The rest pose is the cage until the host gives another.
    for (const glm::vec3& p : mesh.restPositions) s->mLastCage.emplace_back(p, 1.0f);
    const VkDeviceSize cageBytes = VkDeviceSize(mesh.baseVertexCount) * sizeof(glm::vec4);
    for (uint32_t slot = 0; slot < gpu::kFramesInFlight; ++slot) {
        s->mCages[slot] = gpu::Buffer(device, cageBytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                                                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                      gpu::MemoryUsage::CpuToGpu, base + ".cage" + slotTag(slot));
        s->mCageViews[slot] = gpu::BufferView(device, s->mCages[slot], VK_FORMAT_R32G32B32A32_SFLOAT, 0, cageBytes,
                                              base + ".cage.texels" + slotTag(slot));
    }

    // Tiles: the packed texture and one record per ptex face; a surface
    // without displacement binds one zero texel and zero records.
    std::vector<glm::uvec4> records(mesh.ptexFaceCount, glm::uvec4(0u));
    gpu::ImageDesc image;
    image.format = VK_FORMAT_R32_SFLOAT;
    image.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    image.name = base + ".displacementTiles";
    const std::vector<float> zero(1, 0.0f);
    std::span<const float> texelData = zero;
    if (!desc.tiles.texels.empty()) {
        image.width = desc.tiles.width;
        image.height = desc.tiles.height;
        texelData = desc.tiles.texels;
        records.assign(desc.tiles.records.begin(), desc.tiles.records.end());
    }
    s->mTiles = gpu::Image(device, image);
    s->mTiles.upload(std::as_bytes(texelData), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    s->mTileSampler = gpu::Sampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, base + ".tiles");
    uploadArray(device, s->mTileRecords, s->mTileRecordsView, records, VK_FORMAT_R32G32B32A32_UINT,
                base + ".tileRecords");
    return s;
}

void GpuSubdiv::uploadCage(uint32_t slot, std::span<const glm::vec4> cage) {
    if (!cage.empty() && cage.size() == mBaseVertexCount) mLastCage.assign(cage.begin(), cage.end());
    std::memcpy(mCages[slot].mapped(), mLastCage.data(), mLastCage.size() * sizeof(glm::vec4));
}

std::vector<gpu::BindingDesc> GpuSubdiv::evalBindings(VkShaderStageFlags stages) {
    std::vector<gpu::BindingDesc> bindings = {{TS_BINDING_SUBDIV_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                              {TS_BINDING_SUBDIV_TILES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, stages}};
    for (uint32_t binding : {TS_BINDING_SUBDIV_POINTS, TS_BINDING_SUBDIV_DOMAINS, TS_BINDING_SUBDIV_NODES,
                             TS_BINDING_SUBDIV_PATCHES, TS_BINDING_SUBDIV_INDICES, TS_BINDING_SUBDIV_TILE_RECORDS})
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, stages});
    return bindings;
}

std::vector<VkWriteDescriptorSet> GpuSubdiv::evalWrites(const gpu::UniformSlice& uniforms) {
    mUniformInfo = uniforms.descriptor();
    mTileInfo = {mTileSampler.handle(), mTiles.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    mViews = {mPointsView.handle(),  mDomainsView.handle(), mNodesView.handle(),
              mPatchesView.handle(), mIndicesView.handle(), mTileRecordsView.handle()};
    const uint32_t bindings[6] = {TS_BINDING_SUBDIV_POINTS,  TS_BINDING_SUBDIV_DOMAINS, TS_BINDING_SUBDIV_NODES,
                                  TS_BINDING_SUBDIV_PATCHES, TS_BINDING_SUBDIV_INDICES, TS_BINDING_SUBDIV_TILE_RECORDS};
    std::vector<VkWriteDescriptorSet> writes = {
        bufferWrite(TS_BINDING_SUBDIV_UNIFORMS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &mUniformInfo),
        imageWrite(TS_BINDING_SUBDIV_TILES, &mTileInfo)};
    for (int i = 0; i < 6; ++i) writes.push_back(texelWrite(bindings[i], &mViews[i]));
    return writes;
}

std::vector<gpu::BindingDesc> GpuSubdiv::levelBindings(VkShaderStageFlags stages) {
    std::vector<gpu::BindingDesc> bindings = evalBindings(stages);
    bindings.push_back({TS_BINDING_SUBDIV_SUPPORT, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, stages});
    return bindings;
}

std::vector<VkWriteDescriptorSet> GpuSubdiv::levelWrites(const gpu::UniformSlice& uniforms) {
    std::vector<VkWriteDescriptorSet> writes = evalWrites(uniforms);
    mSupportHandle = mSupportView.handle();
    writes.push_back(texelWrite(TS_BINDING_SUBDIV_SUPPORT, &mSupportHandle));
    return writes;
}

std::vector<gpu::BindingDesc> GpuSubdiv::refineBindings(VkShaderStageFlags stages) {
    std::vector<gpu::BindingDesc> bindings;
    for (uint32_t binding : {TS_BINDING_SUBDIV_STENCILS, TS_BINDING_SUBDIV_ENTRIES, TS_BINDING_SUBDIV_CAGE})
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, stages});
    return bindings;
}

std::vector<VkWriteDescriptorSet> GpuSubdiv::refineWrites(uint32_t slot) {
    mRefineViews = {mStencilsView.handle(), mEntriesView.handle(), mCageViews[slot].handle()};
    return {texelWrite(TS_BINDING_SUBDIV_STENCILS, &mRefineViews[0]),
            texelWrite(TS_BINDING_SUBDIV_ENTRIES, &mRefineViews[1]),
            texelWrite(TS_BINDING_SUBDIV_CAGE, &mRefineViews[2])};
}

Status GpuSubdiv::updateTiles(gpu::FrameContext& frame, const backend::SubdivTileData& tiles,
                              std::span<const glm::uvec4> rects) {
    if (rects.empty()) return {};
    if (tiles.width != mTiles.width() || tiles.height != mTiles.height() ||
        uint64_t(tiles.width) * tiles.height != tiles.texels.size())
        return fail("updateSubdivTiles: ", mName, "'s displacement texture changed size; create the surface again");
    // Each rectangle as one copy region, packed row after row into this
    // frame slot's staging buffer.
    std::vector<VkBufferImageCopy> regions;
    std::vector<float> staged;
    for (const glm::uvec4& rect : rects) {
        if (!backend::subdivTileRectValid(rect, tiles.width, tiles.height))
            return fail("updateSubdivTiles: ", mName, ": a rectangle leaves the displacement texture");
        VkBufferImageCopy region{};
        region.bufferOffset = staged.size() * sizeof(float);
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageOffset = {int32_t(rect.x), int32_t(rect.y), 0};
        region.imageExtent = {rect.z, rect.w, 1};
        for (uint32_t y = 0; y < rect.w; ++y) {
            const float* row = tiles.texels.data() + size_t(rect.y + y) * tiles.width + rect.x;
            staged.insert(staged.end(), row, row + rect.z);
        }
        regions.push_back(region);
    }
    gpu::Buffer& staging = mTileStaging[frame.slot()];
    const VkDeviceSize bytes = staged.size() * sizeof(float);
    if (staging.size() < bytes)
        staging = gpu::Buffer(*mDevice, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUsage::CpuToGpu,
                              mName + ".tileStaging" + slotTag(frame.slot()));
    std::memcpy(staging.mapped(), staged.data(), bytes);
    VkCommandBuffer cmd = frame.cmd();
    gpu::PassScope pass(frame, "subdiv.uploadTiles");
    gpu::transitionImage(cmd, mTiles.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdCopyBufferToImage(cmd, staging.handle(), mTiles.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
    gpu::transitionImage(cmd, mTiles.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                         VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    return {};
}

std::vector<glm::vec4> GpuSubdiv::readPoints() {
    const std::vector<std::byte> bytes =
        gpu::readBack(*mDevice, mPoints.size(), mName + ".pointsReadback", "subdiv.readPoints",
                      [&](VkCommandBuffer cmd, const gpu::Buffer& readback) {
                          const VkBufferCopy copy{0, 0, mPoints.size()};
                          vkCmdCopyBuffer(cmd, mPoints.handle(), readback.handle(), 1, &copy);
                      });
    std::vector<glm::vec4> points(mRefinedPointCount);
    std::memcpy(points.data(), bytes.data(), points.size() * sizeof(glm::vec4));
    return points;
}

uint64_t GpuSubdiv::bytes() const {
    uint64_t total = mStencils.size() + mEntries.size() + mPoints.size() + mDomains.size() + mNodes.size() +
                     mPatches.size() + mIndices.size() + mSupport.size() + mTileRecords.size() +
                     uint64_t(mTiles.width()) * mTiles.height() * sizeof(float);
    for (const gpu::Buffer& cage : mCages) total += cage.size();
    return total;
}

} // namespace tessera::backends
