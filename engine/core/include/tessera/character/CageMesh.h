#pragma once
/// @file CageMesh.h
/// The control cage of a character: the coarse, skinned triangle mesh the
/// tessellator amplifies (the paper's "superprimitive mesh").

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::character {

/// One cage vertex in the bind pose, in the character's model space.
struct CageVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  ///< unit length
    /// Unit tangent along +u in xyz; w = +1 or -1 is the bitangent's sign
    /// (bitangent = w * cross(normal, tangent)), as glTF's TANGENT.
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f};        ///< texture coordinates in [0, 1]
    glm::u16vec4 joints{0};    ///< indices into CageMesh::bindings
    glm::vec4 weights{1.0f, 0.0f, 0.0f, 0.0f};  ///< sum to 1
};

/// What a skinning-palette entry binds: a skeleton node and the inverse of
/// its bind-pose global matrix. The palette matrix each frame is
/// global(node) * inverseBind. A rigid (unskinned) mesh's vertices bind to
/// their own node with an identity inverse bind.
struct SkinBinding {
    uint32_t node = 0;
    glm::mat4 inverseBind{1.0f};
};

/// A skinned triangle list. Vertices on a UV seam are split (one per chart)
/// but keep identical positions, normals and skinning, so the tessellated
/// surface stays watertight.
struct CageMesh {
    std::vector<CageVertex> vertices;
    std::vector<uint32_t> indices;       ///< three per triangle
    std::vector<SkinBinding> bindings;   ///< the skinning palette

    uint32_t triangleCount() const { return static_cast<uint32_t>(indices.size() / 3); }
};

} // namespace tessera::character
