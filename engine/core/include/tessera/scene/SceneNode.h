#pragma once
/// @file SceneNode.h
/// The plain data of one scene graph node.

#include "tessera/scene/Aabb.h"
#include "tessera/scene/NodeId.h"
#include "tessera/scene/Transform.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::scene {

/// One node of a SceneGraph. Read through SceneGraph::node(); change only
/// through SceneGraph's setters, which keep the derived fields and dirty flags
/// consistent. The derived fields (world, worldBounds, subtreeBounds) are valid
/// after SceneGraph::updateTransforms().
struct SceneNode {
    std::string name;
    /// Invalid for a root.
    NodeId parent;
    std::vector<NodeId> children;

    /// Transform relative to the parent (to the world for a root).
    Transform local;
    /// Local-to-world matrix: parent's world * local.toMatrix().
    glm::mat4 world{1.0f};

    /// Bounds of this node's own content in its local space. Empty means the
    /// node draws nothing (a pure grouping node) and culling never reports it.
    Aabb localBounds = Aabb::empty();
    /// localBounds transformed to world space.
    Aabb worldBounds = Aabb::empty();
    /// World bounds of this node and all its descendants, for hierarchical culling.
    Aabb subtreeBounds = Aabb::empty();

    /// User tag mapping the node to a system's own data, e.g. kind = terrain
    /// tile, payload = tile index. The scene graph never interprets it.
    uint32_t kind = 0;
    uint32_t payload = 0;

    /// This node's own local transform or bounds changed since the last
    /// updateTransforms(), so its world data is stale. Descendants of a dirty
    /// node are stale too but are not flagged; the update pass recomputes them.
    bool dirty = true;
};

} // namespace tessera::scene
