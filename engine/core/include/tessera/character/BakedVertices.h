#pragma once
/// @file BakedVertices.h
/// Baked vertex animation for a crowd's middle and far tiers: every frame of
/// every baked clip of a creature, its mesh (the cage, or the far mesh)
/// skinned once on the CPU and packed in the paper's 128-bit animated vertex
/// (CompressedVertex.h), so an instance's vertex is two texel fetches (the
/// frames around its phase) and a blend instead of skinning: 4 joints x 2
/// frames x 3 texels of baked matrices per vertex. Blending two skinned
/// positions is blending the two frames' matrices and then skinning
/// (skinning is linear in the matrices), so the positions are what
/// baked_animation.glsl gives up to the format's quantisation; normals and
/// tangents are blended and renormalised.

#include "tessera/character/BakedAnimation.h"
#include "tessera/character/CageMesh.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::character {

/// The compression box and uv range the vertices are packed in (the ones
/// the GPU unpacks with: a character's animatedBounds, padded, and its
/// cage's uv range).
struct PackingRange {
    glm::vec3 boxMin{0.0f}, boxMax{1.0f};
    glm::vec2 uvMin{0.0f}, uvMax{1.0f};
};

/// Appends to `texels`, for each global clip in [firstClip, endClip) of
/// `baked`, every frame of `mesh` skinned with that frame's matrices and
/// packed (frame-major: texel first + frame * vertices + vertex). Returns
/// each clip's first texel, in clip order. `mesh` must use the clips'
/// joints (its bindings are the palette they were baked for). Asserts the
/// clips are in range.
std::vector<uint32_t> appendBakedVertices(const CageMesh& mesh, const BakedAnimation& baked, uint32_t firstClip,
                                          uint32_t endClip, const PackingRange& range, std::vector<glm::uvec4>& texels);

} // namespace tessera::character
