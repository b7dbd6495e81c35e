#pragma once
/// @file CompressionError.h
/// How much the 128-bit compressed vertex format (CompressedVertex.h) loses
/// on a set of vertices: the figures the benchmark reports and tests bound.

#include "tessera/character/CageMesh.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/character/SkinnedVertex.h"
#include "tessera/scene/Aabb.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

namespace tessera::character {

/// The uv rectangle a character's texture coordinates are quantised in.
struct UvRange {
    glm::vec2 min{0.0f};
    glm::vec2 max{1.0f};
};

/// The worst case over the vertices of one pack/unpack round trip.
struct CompressionErrorStats {
    uint32_t vertexCount = 0; ///< vertices measured (each posed sample counts)
    /// Largest position error (Euclidean) divided by the box's largest extent.
    double maxPositionError = 0.0;
    /// Largest angle between a normal and its decoded normal, in degrees.
    double maxNormalAngleDeg = 0.0;
    /// Largest angle between a tangent and its decoded tangent after
    /// Gram-Schmidt against the decoded normal (as the shader uses it), in
    /// degrees. The input tangent is orthogonalised against its own normal.
    double maxTangentAngleDeg = 0.0;
    /// Largest uv error on either axis, in uv units.
    double maxUvError = 0.0;
};

/// Packs and unpacks every vertex (its position, normal, tangent and uv as
/// given) with `box` and `uv`, and measures the error against the input.
/// Positions outside the box count with their clamping error, so pass
/// vertices in the space the box was made for.
CompressionErrorStats measureCompressionError(std::span<const CageVertex> vertices, const scene::Aabb& box,
                                              const UvRange& uv);
/// The same for skinned vertices (what the first pass packs).
CompressionErrorStats measureCompressionError(std::span<const SkinnedVertex> vertices, const scene::Aabb& box,
                                              const UvRange& uv);

/// The error of the format as the renderer uses it: the cage skinned at the
/// rest pose and at `samplesPerClip` uniform times of every clip (as
/// animatedBounds samples), packed in `box` (normally animatedBounds of the
/// character) and `uv` (normally uvBounds of its cage). The figure the
/// benchmark reports. Bind-pose positions are not measured: glTF cages are
/// often authored in another space than the skinned result.
CompressionErrorStats measureAnimatedCompressionError(const CharacterAsset& character, const scene::Aabb& box,
                                                      const UvRange& uv, uint32_t samplesPerClip = 32);

/// The box of the vertices' positions; empty for no vertices.
scene::Aabb positionBounds(std::span<const CageVertex> vertices);

/// The rectangle of the vertices' uvs; [0, 1]^2 for no vertices. A flat
/// axis (all uvs equal) is fine: it encodes as 0 and decodes exactly.
UvRange uvBounds(std::span<const CageVertex> vertices);

} // namespace tessera::character
