#pragma once
/// @file Skeleton.h
/// The node hierarchy a character animates: every glTF node of the model's
/// scene (joints and plain transform nodes alike), parents before children.

#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

namespace tessera::character {

/// A local transform as translation, rotation and scale (glTF's TRS order:
/// M = T * R * S).
struct NodeTransform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; ///< w, x, y, z
    glm::vec3 scale{1.0f};

    /// The matrix T * R * S.
    glm::mat4 matrix() const;
};

/// One node of the hierarchy.
struct SkeletonNode {
    std::string name;
    /// Index of the parent node, or -1 for a root. Always less than this
    /// node's own index (Skeleton keeps nodes in parent-first order).
    int32_t parent = -1;
    /// The node's rest (unanimated) local transform.
    NodeTransform rest;
};

/// The nodes of one character, parents before children, so global matrices
/// are computed in one forward pass. Animation channels and skin bindings
/// refer to nodes by index into `nodes`.
struct Skeleton {
    std::vector<SkeletonNode> nodes;

    /// True when every parent index is -1 or less than its child's index.
    bool isParentFirst() const;
};

} // namespace tessera::character
