#include "tessera/character/BakedVertices.h"

#include "tessera/character/SkinnedVertex.h"
#include "tessera/core/ParallelFor.h"

#include "tessera/shaders/CompressedVertex.h"

#include <cassert>

namespace tessera::character {
namespace {

/// The baked frame `frame` of global clip `clip` as a palette: the rows are
/// exactly Pose::palette's matrices (no blend at a frame).
void framePalette(const BakedAnimation& baked, uint32_t clip, uint32_t frame, std::vector<glm::mat4>& out) {
    const shader::BakedClip& c = baked.clips[clip];
    out.resize(c.frames.z);
    for (uint32_t j = 0; j < c.frames.z; ++j) {
        const size_t t = shader::tsBakedJointTexel(c, frame, j);
        const glm::vec4 r0 = baked.rows[t], r1 = baked.rows[t + 1], r2 = baked.rows[t + 2];
        out[j] = glm::mat4(glm::vec4(r0.x, r1.x, r2.x, 0.0f), glm::vec4(r0.y, r1.y, r2.y, 0.0f),
                           glm::vec4(r0.z, r1.z, r2.z, 0.0f), glm::vec4(r0.w, r1.w, r2.w, 1.0f));
    }
}

} // namespace

std::vector<uint32_t> appendBakedVertices(const CageMesh& mesh, const BakedAnimation& baked, uint32_t firstClip,
                                          uint32_t endClip, const PackingRange& range,
                                          std::vector<glm::uvec4>& texels) {
    assert(firstClip <= endClip && endClip <= baked.clips.size());
    std::vector<uint32_t> first;
    const size_t vertices = mesh.vertices.size();
    for (uint32_t clip = firstClip; clip < endClip; ++clip) {
        first.push_back(uint32_t(texels.size()));
        const uint32_t frames = baked.clips[clip].frames.y;
        const size_t base = texels.size();
        texels.resize(base + size_t(frames) * vertices);
        // Frames are independent: each writes its own slice.
        core::parallelFor(frames, 0, [&](uint32_t f) {
            std::vector<glm::mat4> palette;
            framePalette(baked, clip, f, palette);
            glm::uvec4* out = texels.data() + base + size_t(f) * vertices;
            for (size_t v = 0; v < vertices; ++v) {
                const SkinnedVertex s = skinVertex(mesh.vertices[v], palette);
                out[v] = shader::tsPackVertex(s.position, s.normal, glm::vec3(s.tangent), s.uv, range.boxMin,
                                              range.boxMax, range.uvMin, range.uvMax);
            }
        });
    }
    return first;
}

} // namespace tessera::character
