#pragma once
/// @file SkinnedVertex.h
/// Linear blend skinning of one cage vertex: the CPU reference of the GPU
/// skinning pass that feeds the compressed vertex format.

#include "tessera/character/CageMesh.h"

#include <glm/glm.hpp>
#include <span>

namespace tessera::character {

/// A cage vertex after skinning, in the character's model space.
struct SkinnedVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};        ///< unit length
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f}; ///< unit xyz; w = bitangent sign, as the input's
    glm::vec2 uv{0.0f};                        ///< copied from the input
};

/// Skins `vertex` with the palette (Pose::palette): the blended matrix is
/// M = sum(w_i * palette[joint_i]) over the non-zero weights, renormalised by
/// their sum (an all-zero vertex keeps its bind position, M = identity).
///
/// position = M * p; tangent = normalize(M3 * t), as tangents follow the
/// surface; normal = normalize(cofactor(M3) * n), the inverse-transpose up to
/// the factor det(M3), with the determinant's sign kept so a mirroring bone
/// does not flip normals inward. For rigid bones (rotation and uniform scale)
/// the cofactor is a positive multiple of M3, so a GPU pass that transforms
/// normals by M3 and renormalises agrees with this reference; with
/// non-uniform scale only the cofactor is right.
///
/// Asserts that every joint with a non-zero weight indexes the palette.
SkinnedVertex skinVertex(const CageVertex& vertex, std::span<const glm::mat4> palette);

/// The cofactor matrix of m: det(m) * transpose(inverse(m)), defined for
/// singular m too.
glm::mat3 cofactorMatrix(const glm::mat3& m);

} // namespace tessera::character
