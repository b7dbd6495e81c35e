#include "MeshshaderCrowdResources.h"

#include "tessera/character/BakedAnimation.h"
#include "tessera/character/BakedVertices.h"
#include "tessera/shaders/CompressedVertex.h"
#include "tessera/shaders/CrowdMeshlet.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace tessera::backends {
namespace {

// meshoptimizer's cone weight: some locality traded for tighter normal
// cones, which is what culls the back of a creature.
constexpr float kConeWeight = 0.25f;
// Beyond this half angle a cone culls too little to be worth testing.
constexpr float kMaxConeAngle = 1.45f;
// The mesh stage blends two baked frames; a blended triangle's normal can
// leave both frames' cones by a little, so the merged cone is widened.
constexpr float kConeMargin = 0.05f;

struct MeshletTables {
    std::vector<shader::CrowdMeshlet> meshlets;
    std::vector<uint32_t> vertices;
    std::vector<uint32_t> triangles; ///< three 8-bit local indices each
    uint32_t coned = 0;
};

/// Positions of every baked frame of a mesh: frame-major, `vertices` each.
std::vector<glm::vec3> framePositions(const std::vector<glm::uvec4>& texels, const character::PackingRange& range) {
    std::vector<glm::vec3> positions(texels.size());
    for (size_t i = 0; i < texels.size(); ++i)
        positions[i] = shader::tsUnpackPosition(texels[i], range.boxMin, range.boxMax);
    return positions;
}

/// The meshlet's sphere over every frame (the box's centre, the farthest
/// vertex) and its normal cone over every frame: meshoptimizer's cone per
/// frame, merged around their mean axis; no cone (cutoff 1) when a frame
/// has none or the merged cone is too wide.
void boundMeshlet(const meshopt_Meshlet& m, const unsigned int* vertices, const unsigned char* triangles,
                  const std::vector<glm::vec3>& positions, size_t vertexCount, shader::CrowdMeshlet& out) {
    const size_t frames = positions.size() / vertexCount;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (size_t f = 0; f < frames; ++f)
        for (uint32_t v = 0; v < m.vertex_count; ++v) {
            const glm::vec3& p = positions[f * vertexCount + vertices[m.vertex_offset + v]];
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (size_t f = 0; f < frames; ++f)
        for (uint32_t v = 0; v < m.vertex_count; ++v)
            radius = std::max(radius, glm::length(positions[f * vertexCount + vertices[m.vertex_offset + v]] - centre));
    out.sphere = glm::vec4(centre, radius);
    out.cone = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);

    std::vector<glm::vec3> axes;
    std::vector<float> angles;
    for (size_t f = 0; f < frames; ++f) {
        const meshopt_Bounds b =
            meshopt_computeMeshletBounds(vertices + m.vertex_offset, triangles + m.triangle_offset, m.triangle_count,
                                         &positions[f * vertexCount].x, vertexCount, sizeof(glm::vec3));
        if (b.cone_cutoff >= 1.0f) return;
        // meshoptimizer's cutoff is the sine of the normals' half angle.
        axes.push_back(glm::vec3(b.cone_axis[0], b.cone_axis[1], b.cone_axis[2]));
        angles.push_back(std::asin(std::clamp(b.cone_cutoff, 0.0f, 1.0f)));
    }
    glm::vec3 sum(0.0f);
    for (const glm::vec3& a : axes) sum += a;
    if (axes.empty() || glm::length(sum) < 1e-6f) return;
    const glm::vec3 axis = glm::normalize(sum);
    float angle = 0.0f;
    for (size_t f = 0; f < axes.size(); ++f)
        angle = std::max(angle, std::acos(std::clamp(glm::dot(axis, axes[f]), -1.0f, 1.0f)) + angles[f]);
    angle += kConeMargin;
    if (angle >= kMaxConeAngle) return;
    out.cone = glm::vec4(axis, std::sin(angle));
}

/// Cuts `mesh` into meshlets appended to `tables`; `positions` are its
/// baked frames.
Result<MeshshaderCrowdResources::MeshletRange> appendMeshlets(const character::CageMesh& mesh,
                                                              const std::vector<glm::vec3>& positions,
                                                              MeshletTables& tables) {
    const size_t vertexCount = mesh.vertices.size();
    if (vertexCount == 0 || positions.size() < vertexCount || positions.size() % vertexCount != 0)
        return Error{"createCrowd: a crowd mesh has no baked frames to build meshlets from"};
    const size_t bound =
        meshopt_buildMeshletsBound(mesh.indices.size(), TS_CROWD_MESHLET_VERTICES, TS_CROWD_MESHLET_TRIANGLES);
    std::vector<meshopt_Meshlet> meshlets(bound);
    std::vector<unsigned int> vertices(bound * TS_CROWD_MESHLET_VERTICES);
    std::vector<unsigned char> triangles(bound * TS_CROWD_MESHLET_TRIANGLES * 3);
    // Cut on the first frame's positions (the first clip's pose): the
    // grouping only needs locality, which the animation keeps.
    meshlets.resize(meshopt_buildMeshlets(meshlets.data(), vertices.data(), triangles.data(), mesh.indices.data(),
                                          mesh.indices.size(), &positions[0].x, vertexCount, sizeof(glm::vec3),
                                          TS_CROWD_MESHLET_VERTICES, TS_CROWD_MESHLET_TRIANGLES, kConeWeight));
    MeshshaderCrowdResources::MeshletRange range{uint32_t(tables.meshlets.size()), uint32_t(meshlets.size())};
    for (const meshopt_Meshlet& m : meshlets) {
        shader::CrowdMeshlet out{};
        out.range = glm::uvec4(uint32_t(tables.vertices.size()), uint32_t(tables.triangles.size()), m.vertex_count,
                               m.triangle_count);
        boundMeshlet(m, vertices.data(), triangles.data(), positions, vertexCount, out);
        if (out.cone.w < 1.0f) ++tables.coned;
        tables.meshlets.push_back(out);
        tables.vertices.insert(tables.vertices.end(), vertices.begin() + m.vertex_offset,
                               vertices.begin() + m.vertex_offset + m.vertex_count);
        for (uint32_t t = 0; t < m.triangle_count; ++t) {
            const unsigned char* k = &triangles[m.triangle_offset + 3 * t];
            tables.triangles.push_back(uint32_t(k[0]) | uint32_t(k[1]) << 8 | uint32_t(k[2]) << 16);
        }
    }
    return range;
}

uint32_t groupsOf(uint32_t items) {
    return (items + TS_CROWD_TASK_ITEMS - 1) / TS_CROWD_TASK_ITEMS;
}

} // namespace

Result<std::unique_ptr<MeshshaderCrowdResources>> MeshshaderCrowdResources::create(gpu::Device& device,
                                                                                   GpuCrowd& crowd,
                                                                                   const backend::CrowdDesc& desc,
                                                                                   uint32_t id) {
    std::unique_ptr<MeshshaderCrowdResources> r(new MeshshaderCrowdResources());
    MeshletTables tables;
    const character::BakedAnimation& baked = *desc.animation;
    for (size_t i = 0; i < crowd.creatures().size(); ++i) {
        const GpuCharacter& k = *crowd.creatures()[i].character;
        // The box GpuCrowd packed the baked vertices in: the positions
        // bounded here are the ones the mesh stage unpacks.
        const character::PackingRange range{k.boxMin(), k.boxMax(), glm::vec2(k.uvRange()),
                                            glm::vec2(k.uvRange().z, k.uvRange().w)};
        const uint32_t first = baked.characterClipBase[i];
        const uint32_t end =
            i + 1 < desc.characters.size() ? baked.characterClipBase[i + 1] : uint32_t(baked.clips.size());
        std::array<MeshletRange, 3> ranges;
        // The middle tier's meshlets cover its triangles (the cage's, or the
        // simplified ones over the same vertices).
        const backend::CrowdCharacterDesc& c = desc.characters[i];
        character::CageMesh middle;
        if (!c.middleIndices.empty()) {
            middle.vertices = c.cage->vertices;
            middle.bindings = c.cage->bindings;
            middle.indices.assign(c.middleIndices.begin(), c.middleIndices.end());
        }
        // The far casters' meshlets: the far mesh's vertices with the
        // casters' triangles.
        character::CageMesh farCaster;
        if (!c.farCasterIndices.empty()) {
            farCaster.vertices = c.farMesh->vertices;
            farCaster.bindings = c.farMesh->bindings;
            farCaster.indices.assign(c.farCasterIndices.begin(), c.farCasterIndices.end());
        }
        const character::CageMesh* meshes[3] = {c.middleIndices.empty() ? c.cage : &middle, c.farMesh,
                                                c.farCasterIndices.empty() ? c.farMesh : &farCaster};
        for (int m = 0; m < 3; ++m) {
            std::vector<glm::uvec4> texels;
            character::appendBakedVertices(*meshes[m], baked, first, end, range, texels);
            auto appended = appendMeshlets(*meshes[m], framePositions(texels, range), tables);
            if (!appended) return appended.error();
            ranges[m] = appended.value();
        }
        r->mRanges.push_back(ranges);
    }
    r->mMeshletCount = uint32_t(tables.meshlets.size());
    r->mConed = tables.coned;

    // The commands' fourth word is fixed: near lists take a workgroup per
    // 32 cage triangles per instance, the middle and far lists' items are
    // their mesh's meshlets per instance (tsCrowdMeshletCommand); the
    // impostor lists' cards need none (tsCrowdImpostorCommand).
    std::vector<shader::CrowdMeshCommand> args(TS_CROWD_MESH_COMMANDS, shader::CrowdMeshCommand{glm::uvec4(0)});
    for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
        args[TS_LOD_NEAR * TS_CROWD_MAX_CHARACTERS + c].groups.w = groupsOf(crowd.creatures()[c].cageTriangles);
        for (uint32_t tier = TS_LOD_MIDDLE; tier <= TS_LOD_FAR; ++tier)
            args[tier * TS_CROWD_MAX_CHARACTERS + c].groups.w = r->meshlets(tier, c).count;
        for (uint32_t tier = TS_LOD_MIDDLE; tier <= TS_LOD_FAR; ++tier)
            args[shader::tsCrowdCasterCommand(tier, c)].groups.w = r->casterMeshlets(tier, c).count;
    }

    const std::string name = "meshshader.crowd[" + std::to_string(id) + "]";
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    r->mMeshlets = gpu::Buffer(device, tables.meshlets.size() * sizeof(shader::CrowdMeshlet), storage,
                               gpu::MemoryUsage::GpuOnly, name + ".meshlets");
    r->mMeshlets.upload(std::span<const shader::CrowdMeshlet>(tables.meshlets));
    r->mVertices = gpu::Buffer(device, tables.vertices.size() * sizeof(uint32_t), storage, gpu::MemoryUsage::GpuOnly,
                               name + ".meshletVertices");
    r->mVertices.upload(std::span<const uint32_t>(tables.vertices));
    r->mTriangles = gpu::Buffer(device, tables.triangles.size() * sizeof(uint32_t), storage,
                                gpu::MemoryUsage::GpuOnly, name + ".meshletTriangles");
    r->mTriangles.upload(std::span<const uint32_t>(tables.triangles));
    r->mArgs = gpu::Buffer(device, args.size() * sizeof(shader::CrowdMeshCommand),
                           storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                           name + ".meshTaskCommands");
    r->mArgs.upload(std::span<const shader::CrowdMeshCommand>(args));
    return r;
}

MeshshaderCrowdResources::MeshletRange MeshshaderCrowdResources::meshlets(uint32_t tier, uint32_t creature) const {
    return mRanges[creature][tier == TS_LOD_FAR ? 1 : 0];
}

MeshshaderCrowdResources::MeshletRange MeshshaderCrowdResources::casterMeshlets(uint32_t tier,
                                                                               uint32_t creature) const {
    return mRanges[creature][tier == TS_LOD_FAR ? 2 : 1];
}

uint64_t MeshshaderCrowdResources::bytes() const {
    return mMeshlets.size() + mVertices.size() + mTriangles.size() + mArgs.size();
}

} // namespace tessera::backends
