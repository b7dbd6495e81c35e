#include "common/GpuCrowd.h"

#include "tessera/backend/CrowdChecks.h"
#include "tessera/character/BakedAnimation.h"
#include "tessera/character/BakedVertices.h"
#include "tessera/core/ParallelFor.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/tessellator/TrianglePatternLibrary.h"

#include <algorithm>
#include <cstring>
#include <span>
#include <tuple>
#include <utility>

namespace tessera::backends {

Result<std::unique_ptr<GpuCrowd>> GpuCrowd::create(gpu::Device& device, const backend::CrowdDesc& desc,
                                                   const std::function<GpuCharacter*(backend::CharacterHandle)>& find,
                                                   VkBufferUsageFlags writeUsage) {
    if (Status ok = backend::checkCrowdDesc(desc); !ok) return ok.error();
    const character::BakedAnimation& baked = *desc.animation;
    const uint32_t texelLimit = device.properties().limits.maxTexelBufferElements;
    if (baked.texelCount() > texelLimit)
        return Error{"createCrowd: the baked clips need " + std::to_string(baked.texelCount()) +
                     " texels, more than this device's maxTexelBufferElements (" + std::to_string(texelLimit) + ")"};

    std::unique_ptr<GpuCrowd> crowd(new GpuCrowd());
    crowd->mMaxInstances = desc.maxInstances;
    crowd->mMaxIds = desc.maxIds;
    crowd->mNearSlots = std::max(desc.nearSlots, 1u);
    crowd->mClipCount = uint32_t(baked.clips.size());

    // Every creature's cage, then its far mesh, in one vertex and one index
    // buffer: one binding serves every list's draw.
    std::vector<shader::CharacterVertex> vertices;
    std::vector<uint32_t> indices;
    for (size_t i = 0; i < desc.characters.size(); ++i) {
        const backend::CrowdCharacterDesc& c = desc.characters[i];
        GpuCharacter* character = find(c.character);
        if (!character)
            return Error{"createCrowd: character " + std::to_string(i) + " (handle " + std::to_string(c.character.id) +
                         ") does not exist"};
        const uint32_t palette = character->paletteSize();
        const uint32_t clipBase = baked.characterClipBase[i];
        if (clipBase >= baked.clips.size() || baked.clips[clipBase].frames.z != palette)
            return Error{"createCrowd: " + character->name() + " has " + std::to_string(palette) +
                         " skinning matrices; its baked clips do not"};
        auto far = GpuCharacter::convertVertices(*c.farMesh, palette, character->name() + " far mesh");
        if (!far) return far.error();
        for (uint32_t index : c.farMesh->indices)
            if (index >= c.farMesh->vertices.size())
                return Error{"createCrowd: " + character->name() + " far mesh: index " + std::to_string(index) +
                             " out of range"};
        Creature creature;
        creature.character = character;
        creature.cageFirstVertex = uint32_t(vertices.size());
        creature.cageFirstIndex = uint32_t(indices.size());
        creature.cageTriangles = character->triangleCount();
        vertices.insert(vertices.end(), character->gpuVertices().begin(), character->gpuVertices().end());
        indices.insert(indices.end(), character->cageIndices().begin(), character->cageIndices().end());
        // A tier's own triangles over a mesh's vertices, where given: first
        // index and triangles, else the mesh's own.
        auto appendTriangles = [&](std::span<const uint32_t> own, uint32_t first, uint32_t triangles) {
            if (own.empty()) return std::pair{first, triangles};
            const std::pair range{uint32_t(indices.size()), uint32_t(own.size() / 3)};
            indices.insert(indices.end(), own.begin(), own.end());
            return range;
        };
        std::tie(creature.middleFirstIndex, creature.middleTriangles) =
            appendTriangles(c.middleIndices, creature.cageFirstIndex, creature.cageTriangles);
        creature.farFirstVertex = uint32_t(vertices.size());
        creature.farFirstIndex = uint32_t(indices.size());
        creature.farTriangles = c.farMesh->triangleCount();
        vertices.insert(vertices.end(), far.value().begin(), far.value().end());
        indices.insert(indices.end(), c.farMesh->indices.begin(), c.farMesh->indices.end());
        std::tie(creature.farCasterFirstIndex, creature.farCasterTriangles) =
            appendTriangles(c.farCasterIndices, creature.farFirstIndex, creature.farTriangles);
        crowd->mCreatures.push_back(creature);
        crowd->mLevelPerPixel.push_back(c.levelPerPixel);
        crowd->mNearStride = std::max(crowd->mNearStride, character->vertexCount());
        crowd->mTriangleStride = std::max(crowd->mTriangleStride, creature.cageTriangles);
    }

    // The impostor tier's card, one for every creature (its corners are
    // placed by crowd_impostor.glsl).
    const uint32_t impostorFirstIndex = uint32_t(indices.size());
    for (uint32_t i = 0; i < TS_CROWD_IMPOSTOR_INDICES; ++i) indices.push_back(shader::tsCrowdImpostorIndex(i));
    for (Creature& creature : crowd->mCreatures) creature.impostorFirstIndex = impostorFirstIndex;

    // The middle and far tiers' baked vertex animation: each creature's
    // cage and far mesh skinned at every baked frame of its clips, packed
    // with its character's box and uv range (the GPU unpacks with them).
    std::vector<glm::uvec4> bakedVertices;
    std::vector<glm::uvec4> clipMeshes(baked.clips.size(), glm::uvec4(0));
    for (size_t i = 0; i < desc.characters.size(); ++i) {
        const GpuCharacter& k = *crowd->mCreatures[i].character;
        const character::PackingRange range{k.boxMin(), k.boxMax(), glm::vec2(k.uvRange()),
                                            glm::vec2(k.uvRange().z, k.uvRange().w)};
        const uint32_t first = baked.characterClipBase[i];
        const uint32_t end =
            i + 1 < desc.characters.size() ? baked.characterClipBase[i + 1] : uint32_t(baked.clips.size());
        const auto cage =
            character::appendBakedVertices(*desc.characters[i].cage, baked, first, end, range, bakedVertices);
        const auto far =
            character::appendBakedVertices(*desc.characters[i].farMesh, baked, first, end, range, bakedVertices);
        for (uint32_t c = first; c < end; ++c) clipMeshes[c] = glm::uvec4(cage[c - first], far[c - first], 0u, 0u);
        crowd->mFarVertices.push_back(uint32_t(desc.characters[i].farMesh->vertices.size()));
    }
    if (bakedVertices.size() > texelLimit)
        return Error{"createCrowd: the baked vertex animation needs " + std::to_string(bakedVertices.size()) +
                     " texels, more than this device's maxTexelBufferElements (" + std::to_string(texelLimit) + ")"};

    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    const VkBufferUsageFlags texels = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    const VkBufferUsageFlags dst = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    const VkBufferUsageFlags src = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    const VkBufferUsageFlags vertex = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    const VkBufferUsageFlags written = writeUsage | dst | src;
    auto whole = [](const gpu::Buffer& b) { return b.size(); };
    crowd->mVertices = gpu::Buffer(device, vertices.size() * sizeof(shader::CharacterVertex), storage | vertex,
                                   gpu::MemoryUsage::GpuOnly, "crowd.vertices");
    crowd->mVertices.upload(std::span<const shader::CharacterVertex>(vertices));
    crowd->mIndices = gpu::Buffer(device, indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT | texels,
                                  gpu::MemoryUsage::GpuOnly, "crowd.indices");
    crowd->mIndices.upload(std::span<const uint32_t>(indices));
    crowd->mIndicesView =
        gpu::BufferView(device, crowd->mIndices, VK_FORMAT_R32_UINT, 0, whole(crowd->mIndices), "crowd.indices.texels");
    crowd->mBaked = gpu::Buffer(device, baked.rows.size() * sizeof(glm::vec4), texels, gpu::MemoryUsage::GpuOnly,
                                "crowd.bakedMatrices");
    crowd->mBaked.upload(std::span<const glm::vec4>(baked.rows));
    crowd->mBakedView = gpu::BufferView(device, crowd->mBaked, VK_FORMAT_R32G32B32A32_SFLOAT, 0,
                                        baked.rows.size() * sizeof(glm::vec4), "crowd.bakedMatrices.texels");
    crowd->mClips = gpu::Buffer(device, baked.clips.size() * sizeof(shader::BakedClip), storage | texels,
                                gpu::MemoryUsage::GpuOnly, "crowd.clips");
    // The GPU's clips carry their first impostor layer (BakedAnimation.h).
    crowd->mImpostors = GpuImpostorAtlas::create(device, desc);
    std::vector<shader::BakedClip> clips = baked.clips;
    for (size_t k = 0; k < clips.size(); ++k) clips[k].timing.w = float(crowd->mImpostors.firstLayers()[k]);
    crowd->mClips.upload(std::span<const shader::BakedClip>(clips));
    crowd->mClipsView = gpu::BufferView(device, crowd->mClips, VK_FORMAT_R32G32B32A32_UINT, 0, whole(crowd->mClips),
                                        "crowd.clips.texels");
    crowd->mState = gpu::Buffer(device, VkDeviceSize(desc.maxIds) * sizeof(uint32_t), storage | dst,
                                gpu::MemoryUsage::GpuOnly, "crowd.lodState");
    // A tier's entry per instance (tsCrowdListBase), and one to spare: a
    // binding of an empty list at the very end still has an entry's room.
    crowd->mLists = gpu::Buffer(device,
                                (VkDeviceSize(TS_LOD_TIERS) * desc.maxInstances + 1) * sizeof(shader::CrowdListEntry),
                                written | vertex, gpu::MemoryUsage::GpuOnly, "crowd.tierLists");
    crowd->mArgs =
        gpu::Buffer(device, TS_CROWD_ARG_WORDS * sizeof(uint32_t), written | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                    gpu::MemoryUsage::GpuOnly, "crowd.indirect");
    crowd->mNear = gpu::Buffer(device, VkDeviceSize(crowd->mNearSlots) * crowd->mNearStride * 16, written | texels,
                               gpu::MemoryUsage::GpuOnly, "crowd.nearCages");
    crowd->mNearView = gpu::BufferView(device, crowd->mNear, VK_FORMAT_R32G32B32A32_UINT, 0, whole(crowd->mNear),
                                       "crowd.nearCages.texels");
    crowd->mNearOwners = gpu::Buffer(device, VkDeviceSize(crowd->mNearSlots) * sizeof(glm::uvec2), storage,
                                     gpu::MemoryUsage::GpuOnly, "crowd.nearSlots");
    crowd->mNearSlotRecords = gpu::Buffer(device, VkDeviceSize(crowd->mNearSlots) * sizeof(shader::CrowdNearSlot),
                                          written | texels, gpu::MemoryUsage::GpuOnly, "crowd.nearSlotRecords");
    crowd->mNearSlotsView = gpu::BufferView(device, crowd->mNearSlotRecords, VK_FORMAT_R32G32B32A32_UINT, 0,
                                            whole(crowd->mNearSlotRecords), "crowd.nearSlotRecords.texels");
    crowd->mNearCommands = gpu::Buffer(
        device,
        VkDeviceSize(crowd->mCreatures.size()) * crowd->mNearSlots * TS_CROWD_NEAR_COMMAND_WORDS * sizeof(uint32_t),
        written | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, gpu::MemoryUsage::GpuOnly, "crowd.nearCommands");
    crowd->mBakedVertices = gpu::Buffer(device, bakedVertices.size() * sizeof(glm::uvec4), texels,
                                        gpu::MemoryUsage::GpuOnly, "crowd.bakedVertices");
    crowd->mBakedVertices.upload(std::span<const glm::uvec4>(bakedVertices));
    crowd->mBakedVerticesView = gpu::BufferView(device, crowd->mBakedVertices, VK_FORMAT_R32G32B32A32_UINT, 0,
                                                whole(crowd->mBakedVertices), "crowd.bakedVertices.texels");
    crowd->mClipMeshes = gpu::Buffer(device, clipMeshes.size() * sizeof(glm::uvec4), texels, gpu::MemoryUsage::GpuOnly,
                                     "crowd.clipMeshes");
    crowd->mClipMeshes.upload(std::span<const glm::uvec4>(clipMeshes));
    crowd->mClipMeshesView = gpu::BufferView(device, crowd->mClipMeshes, VK_FORMAT_R32G32B32A32_UINT, 0,
                                             whole(crowd->mClipMeshes), "crowd.clipMeshes.texels");
    const tessellator::TrianglePatternLibrary& patterns = tessellator::TrianglePatternLibrary::fractionalOdd();
    crowd->mPatternCodes =
        gpu::Buffer(device, patterns.codes().size_bytes(), vertex, gpu::MemoryUsage::GpuOnly, "crowd.nearPatternCodes");
    crowd->mPatternCodes.upload(patterns.codes());
    crowd->mPatternIndices = gpu::Buffer(device, patterns.indices().size_bytes(), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                                         gpu::MemoryUsage::GpuOnly, "crowd.nearPatternIndices");
    crowd->mPatternIndices.upload(patterns.indices());
    for (uint32_t slot = 0; slot < gpu::kFramesInFlight; ++slot) {
        // (Built in steps: GCC 12 warns falsely on "[" + to_string + "]".)
        std::string tag = "[";
        tag += std::to_string(slot);
        tag += ']';
        crowd->mInstances[slot] = gpu::Buffer(device, VkDeviceSize(desc.maxInstances) * sizeof(shader::CrowdInstance),
                                              storage | texels, gpu::MemoryUsage::CpuToGpu, "crowd.instances" + tag);
        crowd->mInstancesView[slot] = gpu::BufferView(device, crowd->mInstances[slot], VK_FORMAT_R32G32B32A32_UINT, 0,
                                                      whole(crowd->mInstances[slot]), "crowd.instances.texels" + tag);
        const VkDeviceSize occluderBytes =
            VkDeviceSize(TS_CROWD_MAX_OCCLUDER_CELLS) * TS_CROWD_MAX_OCCLUDER_CELLS * sizeof(float);
        crowd->mOccluders[slot] = gpu::Buffer(device, occluderBytes, texels, gpu::MemoryUsage::CpuToGpu,
                                              "crowd.occluders" + tag);
        crowd->mOccludersView[slot] = gpu::BufferView(device, crowd->mOccluders[slot], VK_FORMAT_R32_SFLOAT, 0,
                                                      occluderBytes, "crowd.occluders.texels" + tag);
        crowd->mArgsReadback[slot] = gpu::Buffer(device, TS_CROWD_ARG_WORDS * sizeof(uint32_t), dst,
                                                 gpu::MemoryUsage::GpuToCpu, "crowd.indirectReadback" + tag);
    }

    // Each list draws its creature's mesh: the cage (near), its middle
    // triangles (the cage's or fewer, over the same vertices), the far mesh
    // or the card (impostor); firstInstance is the list's region (set per
    // frame by uploadInstances), so the instance stream (or
    // gl_InstanceIndex) is the entry. Indices stay local to the mesh
    // (vertexOffset 0): every tier fetches its vertices by local index, the
    // near tier from its compressed cage, the others from the baked vertex
    // animation.
    std::vector<uint32_t> args(TS_CROWD_ARG_WORDS, 0u);
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
        for (uint32_t c = 0; c < crowd->mCreatures.size(); ++c) {
            const Creature& k = crowd->mCreatures[c];
            uint32_t* cmd = &args[(tier * TS_CROWD_MAX_CHARACTERS + c) * TS_CROWD_ARG_DRAW_WORDS];
            cmd[0] = 3 * k.tierTriangles(tier);
            cmd[1] = 0;
            cmd[2] = k.tierFirstIndex(tier);
            cmd[3] = 0;
            cmd[4] = 0;
        }
    args[TS_CROWD_ARG_DISPATCH + 1] = 1;
    args[TS_CROWD_ARG_DISPATCH + 2] = 1;
    // The casters' commands: the middle and far lists' (their instances)
    // over the casters' triangles; only the instance counts change per frame.
    std::vector<uint32_t> casterArgs(2 * TS_CROWD_MAX_CHARACTERS * TS_CROWD_ARG_DRAW_WORDS);
    for (uint32_t tier = TS_LOD_MIDDLE; tier <= TS_LOD_FAR; ++tier)
        for (uint32_t c = 0; c < crowd->mCreatures.size(); ++c) {
            const Creature& k = crowd->mCreatures[c];
            const uint32_t* list = &args[(tier * TS_CROWD_MAX_CHARACTERS + c) * TS_CROWD_ARG_DRAW_WORDS];
            uint32_t* cmd = &casterArgs[casterArgsOffset(tier, c) / sizeof(uint32_t)];
            std::copy(list, list + TS_CROWD_ARG_DRAW_WORDS, cmd);
            // The middle tier's creatures (64 pixels and more) keep their
            // limbs' shadows with the whole far mesh; the far tier's are a
            // few texels and cast the simplified casters.
            cmd[0] = 3 * (tier == TS_LOD_FAR ? k.farCasterTriangles : k.farTriangles);
            cmd[2] = tier == TS_LOD_FAR ? k.farCasterFirstIndex : k.farFirstIndex;
        }
    crowd->mCasterArgs = gpu::Buffer(device, casterArgs.size() * sizeof(uint32_t),
                                     dst | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                                     "crowd.casterIndirect");
    crowd->mCasterArgs.upload(std::span<const uint32_t>(casterArgs));
    for (auto& slotArgs : crowd->mInitialArgs) slotArgs = args;
    return crowd;
}

void GpuCrowd::recordCasterArgs(VkCommandBuffer cmd) {
    // Whichever pass wrote the counts (compute, a copy, transform feedback)
    // and the previous frame's caster draws that read these commands.
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // Each list's instance count and first instance (its region moves with
    // the frame's instances).
    std::vector<VkBufferCopy> counts;
    const VkDeviceSize word = sizeof(uint32_t);
    for (uint32_t tier = TS_LOD_MIDDLE; tier <= TS_LOD_FAR; ++tier)
        for (uint32_t c = 0; c < mCreatures.size(); ++c)
            for (VkDeviceSize w : {VkDeviceSize(1), VkDeviceSize(4)})
                counts.push_back({((tier * TS_CROWD_MAX_CHARACTERS + c) * TS_CROWD_ARG_DRAW_WORDS + w) * word,
                                  casterArgsOffset(tier, c) + w * word, word});
    vkCmdCopyBuffer(cmd, mArgs.handle(), mCasterArgs.handle(), uint32_t(counts.size()), counts.data());
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

bool GpuCrowd::uploadOccluders(uint32_t slot, std::span<const float> occluders) {
    if (occluders.size_bytes() > mOccluders[slot].size()) return false;
    if (!occluders.empty()) mOccluders[slot].upload(occluders);
    return true;
}

uint32_t GpuCrowd::uploadInstances(uint32_t slot, std::span<const shader::CrowdInstance> instances) {
    // A counting sort by creature: the emulated techniques cull and rank
    // each creature's instances as one contiguous range. By chunks over the
    // cores (a million instances are 64 MB a frame): each chunk counts its
    // valid instances per creature, a prefix over the chunks in order gives
    // each its place, so the order is the serial one (stable).
    mLastSlot = slot;
    const uint32_t creatures = uint32_t(mCreatures.size());
    constexpr uint32_t kChunk = 16384;
    uint32_t count = uint32_t(instances.size());
    uint32_t chunks = (count + kChunk - 1) / kChunk;
    std::vector<uint32_t>& counts = mChunkCounts;
    counts.assign(size_t(chunks) * creatures, 0u);
    auto countChunk = [&](uint32_t begin, uint32_t end) {
        uint32_t* mine = &counts[size_t(begin / kChunk) * creatures];
        std::fill(mine, mine + creatures, 0u);
        for (uint32_t i = begin; i < end; ++i)
            if (backend::crowdInstanceValid(instances[i], mMaxIds, creatures, mClipCount)) ++mine[instances[i].ids.y];
    };
    core::parallelForRanges(count, kChunk, 0, [&](core::IndexRange range) { countChunk(range.begin, range.end); });
    // Past the buffer's capacity the last valid instances are left out: the
    // chunk that crosses it is cut where its valid ones fill it.
    uint32_t kept = 0;
    for (uint32_t k = 0; k < chunks; ++k) {
        uint32_t inChunk = 0;
        for (uint32_t c = 0; c < creatures; ++c) inChunk += counts[size_t(k) * creatures + c];
        if (kept + inChunk > mMaxInstances) {
            uint32_t end = k * kChunk;
            for (uint32_t room = mMaxInstances - kept; room > 0; ++end)
                room -= backend::crowdInstanceValid(instances[end], mMaxIds, creatures, mClipCount) ? 1u : 0u;
            count = end;
            chunks = k + 1;
            countChunk(k * kChunk, end);
            kept = mMaxInstances;
            break;
        }
        kept += inChunk;
    }
    std::vector<glm::uvec2>& ranges = mRanges[slot];
    ranges.assign(creatures, glm::uvec2(0));
    for (uint32_t k = 0; k < chunks; ++k)
        for (uint32_t c = 0; c < creatures; ++c) ranges[c].y += counts[size_t(k) * creatures + c];
    for (uint32_t c = 1; c < creatures; ++c) ranges[c].x = ranges[c - 1].x + ranges[c - 1].y;
    // Each chunk's counts become its first place per creature.
    std::vector<uint32_t> next(creatures);
    for (uint32_t c = 0; c < creatures; ++c) next[c] = ranges[c].x;
    for (uint32_t k = 0; k < chunks; ++k)
        for (uint32_t c = 0; c < creatures; ++c) {
            uint32_t& n = counts[size_t(k) * creatures + c];
            const uint32_t first = next[c];
            next[c] += n;
            n = first;
        }
    auto* out = static_cast<shader::CrowdInstance*>(mInstances[slot].mapped());
    std::vector<uint32_t>& host = mHostIndex[slot];
    host.resize(kept);
    core::parallelForRanges(count, kChunk, 0, [&](core::IndexRange range) {
        uint32_t* at = &counts[size_t(range.begin / kChunk) * creatures];
        for (uint32_t i = range.begin; i < range.end; ++i) {
            if (!backend::crowdInstanceValid(instances[i], mMaxIds, creatures, mClipCount)) continue;
            const uint32_t place = at[instances[i].ids.y]++;
            out[place] = instances[i];
            host[place] = i;
        }
    });
    std::vector<uint32_t>& args = mInitialArgs[slot];
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
        for (uint32_t c = 0; c < creatures; ++c)
            args[(tier * TS_CROWD_MAX_CHARACTERS + c) * TS_CROWD_ARG_DRAW_WORDS + 4] = listBase(slot, tier, c);
    return kept;
}

backend::CrowdTiers GpuCrowd::toHostIndices(backend::CrowdTiers tiers) const {
    const std::vector<uint32_t>& host = mHostIndex[mLastSlot];
    for (auto& list : tiers.instances)
        for (uint32_t& i : list) i = i < host.size() ? host[i] : UINT32_MAX;
    return tiers;
}

shader::CrowdUniforms GpuCrowd::uniforms(const backend::CrowdDrawInfo& draw, uint32_t instanceCount) const {
    shader::CrowdUniforms u{};
    u.lod = draw.lod;
    for (size_t c = 0; c < mCreatures.size(); ++c) {
        const GpuCharacter& k = *mCreatures[c].character;
        shader::CrowdCharacter& out = u.characters[c];
        out.boxMin = glm::vec4(k.boxMin(), mLevelPerPixel[c]);
        out.boxMax = glm::vec4(k.boxMax(), k.negativeHandedness() ? 1.0f : 0.0f);
        out.uvRange = k.uvRange();
        out.displacement = glm::vec4(k.displacementScale(), k.displacementBias(), 1.0f, 0.0f);
        const Creature& m = mCreatures[c];
        out.mesh = glm::uvec4(m.cageFirstVertex, k.vertexCount(), m.farFirstVertex, mFarVertices[c]);
        out.indices = glm::uvec4(m.cageFirstIndex, m.cageTriangles, m.farFirstIndex, m.farTriangles);
    }
    const auto classes = tessellator::TrianglePatternLibrary::fractionalOdd().classes();
    for (size_t k = 0; k < classes.size() && k < TS_EMU_TRIANGLE_CLASSES; ++k)
        u.nearPatterns[k] = glm::uvec4(classes[k].firstIndex, classes[k].indexCount, classes[k].firstCode, 0u);
    u.emulated = glm::uvec4(mTriangleStride, 0u, 0u, 0u);
    for (size_t c = 0; c < mCreatures.size(); ++c) u.creatureFirst[c / 4][c % 4] = mRanges[mLastSlot][c].x;
    const auto& bounds = mImpostors.bounds();
    for (size_t w = 0; w < bounds.size(); ++w) u.impostorBounds[w / 4][w % 4] = bounds[w];
    u.counts = glm::uvec4(instanceCount, uint32_t(mCreatures.size()), mNearSlots, mMaxInstances);
    u.flags = glm::uvec4(draw.displacement ? 1u : 0u, draw.lodColors ? 1u : 0u, mNearStride, mMaxIds);
    return u;
}

uint64_t GpuCrowd::bytes() const {
    uint64_t total = mVertices.size() + mIndices.size() + mBaked.size() + mClips.size() + mState.size() +
                     mBakedVertices.size() + mClipMeshes.size() + mLists.size() + mArgs.size() + mCasterArgs.size() + mNear.size() +
                     mNearOwners.size() + mNearSlotRecords.size() + mNearCommands.size() + mPatternCodes.size() +
                     mPatternIndices.size() + mImpostors.bytes();
    for (const gpu::Buffer& b : mInstances) total += b.size();
    for (const gpu::Buffer& b : mOccluders) total += b.size();
    return total;
}

} // namespace tessera::backends
