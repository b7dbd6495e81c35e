#include "tessera/character/CompressionError.h"

#include "tessera/character/Pose.h"

#include "tessera/shaders/CompressedVertex.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tessera::character {

namespace {

// Angles in double through atan2(|a x b|, a . b): acos of a float dot
// product cannot resolve the hundredths of a degree being measured.
double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

// A tangent parallel to its normal has no orthogonal part; it is kept as is
// so the measurement stays finite.
glm::dvec3 orthogonalised(const glm::dvec3& t, const glm::dvec3& n) {
    const glm::dvec3 r = t - n * glm::dot(n, t);
    const double len = glm::length(r);
    return len > 1e-12 ? r / len : glm::normalize(t);
}

// The worst case over one vertex, merged into `stats`.
void measureOne(const glm::vec3& p, const glm::vec3& nIn, const glm::vec3& tIn, const glm::vec2& uvIn,
                const scene::Aabb& box, const UvRange& uv, double extent, CompressionErrorStats& stats) {
    const glm::uvec4 word = shader::tsPackVertex(p, nIn, tIn, uvIn, box.min, box.max, uv.min, uv.max);
    glm::vec3 position, normal, tangent;
    glm::vec2 texcoord;
    shader::tsUnpackVertex(word, box.min, box.max, uv.min, uv.max, position, normal, tangent, texcoord);

    ++stats.vertexCount;
    const double positionError = glm::length(glm::dvec3(position) - glm::dvec3(p));
    if (extent > 0.0) stats.maxPositionError = std::max(stats.maxPositionError, positionError / extent);
    const glm::dvec3 n = glm::normalize(glm::dvec3(nIn));
    const glm::dvec3 decodedN(normal);
    stats.maxNormalAngleDeg = std::max(stats.maxNormalAngleDeg, angleDeg(n, decodedN));
    const glm::dvec3 t = orthogonalised(glm::dvec3(tIn), n);
    const glm::dvec3 decodedT = orthogonalised(glm::dvec3(tangent), decodedN);
    stats.maxTangentAngleDeg = std::max(stats.maxTangentAngleDeg, angleDeg(t, decodedT));
    const glm::dvec2 uvError = glm::abs(glm::dvec2(texcoord) - glm::dvec2(uvIn));
    stats.maxUvError = std::max({stats.maxUvError, uvError.x, uvError.y});
}

double largestExtent(const scene::Aabb& box) {
    const glm::vec3 size = box.max - box.min;
    return std::max({size.x, size.y, size.z});
}

void measureSkinned(const CageMesh& cage, const Pose& pose, std::vector<glm::mat4>& palette, const scene::Aabb& box,
                    const UvRange& uv, CompressionErrorStats& stats) {
    pose.palette(cage, palette);
    const double extent = largestExtent(box);
    for (const CageVertex& vertex : cage.vertices) {
        const SkinnedVertex s = skinVertex(vertex, palette);
        measureOne(s.position, s.normal, glm::vec3(s.tangent), s.uv, box, uv, extent, stats);
    }
}

} // namespace

CompressionErrorStats measureCompressionError(std::span<const CageVertex> vertices, const scene::Aabb& box,
                                              const UvRange& uv) {
    CompressionErrorStats stats;
    const double extent = largestExtent(box);
    for (const CageVertex& v : vertices)
        measureOne(v.position, v.normal, glm::vec3(v.tangent), v.uv, box, uv, extent, stats);
    return stats;
}

CompressionErrorStats measureCompressionError(std::span<const SkinnedVertex> vertices, const scene::Aabb& box,
                                              const UvRange& uv) {
    CompressionErrorStats stats;
    const double extent = largestExtent(box);
    for (const SkinnedVertex& v : vertices)
        measureOne(v.position, v.normal, glm::vec3(v.tangent), v.uv, box, uv, extent, stats);
    return stats;
}

CompressionErrorStats measureAnimatedCompressionError(const CharacterAsset& character, const scene::Aabb& box,
                                                      const UvRange& uv, uint32_t samplesPerClip) {
    CompressionErrorStats stats;
    Pose pose(character.skeleton);
    std::vector<glm::mat4> palette;
    measureSkinned(character.cage, pose, palette, box, uv, stats);
    const uint32_t samples = std::max(samplesPerClip, 2u);
    for (const AnimationClip& clip : character.clips) {
        for (uint32_t s = 0; s < samples; ++s) {
            pose.reset();
            pose.apply(clip, clip.duration() * static_cast<float>(s) / static_cast<float>(samples - 1), false);
            pose.computeGlobals();
            measureSkinned(character.cage, pose, palette, box, uv, stats);
        }
    }
    return stats;
}

scene::Aabb positionBounds(std::span<const CageVertex> vertices) {
    scene::Aabb box = scene::Aabb::empty();
    for (const CageVertex& v : vertices) box.expand(v.position);
    return box;
}

UvRange uvBounds(std::span<const CageVertex> vertices) {
    if (vertices.empty()) return UvRange{};
    UvRange range{vertices.front().uv, vertices.front().uv};
    for (const CageVertex& v : vertices) {
        range.min = glm::min(range.min, v.uv);
        range.max = glm::max(range.max, v.uv);
    }
    return range;
}

} // namespace tessera::character
