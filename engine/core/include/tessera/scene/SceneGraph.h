#pragma once
/// @file SceneGraph.h
/// A transform hierarchy with bounds, dirty propagation and hierarchical culling.

#include "tessera/scene/Aabb.h"
#include "tessera/scene/Frustum.h"
#include "tessera/scene/NodeId.h"
#include "tessera/scene/SceneNode.h"
#include "tessera/scene/Transform.h"

#include <cassert>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tessera::scene {

/// Owns scene nodes in a slot array with a free list. Ids are stable handles
/// (index + generation); destroying a node bumps its slot's generation so old
/// ids become detectably stale. Any number of roots is allowed.
///
/// Passing a stale or invalid id where a live node is required is a programming
/// error and asserts. Not thread-safe; const member functions may be called
/// concurrently with each other.
///
/// Typical frame: setters as things move, then updateTransforms(), then cull().
class SceneGraph {
public:
    /// Creates a node under `parent` (a root when `parent` is invalid) with an
    /// identity transform, empty bounds and tag (0, 0).
    NodeId createNode(std::string name, NodeId parent = {});

    /// Destroys `id` and all its descendants; their ids become stale.
    void destroyNode(NodeId id);

    /// True when `id` names a node that exists now.
    bool isAlive(NodeId id) const;

    /// Sets the transform relative to the parent; the subtree's world data is
    /// recomputed at the next updateTransforms().
    void setLocalTransform(NodeId id, const Transform& transform);

    /// Sets the bounds of the node's own content in its local space. Empty means
    /// the node draws nothing and is never reported by cull().
    void setLocalBounds(NodeId id, const Aabb& bounds);

    /// Sets the user tag (see SceneNode::kind and SceneNode::payload).
    void setTag(NodeId id, uint32_t kind, uint32_t payload);

    /// The node's data. The reference is invalidated by createNode().
    const SceneNode& node(NodeId id) const {
        assert(isAlive(id) && "SceneGraph::node: stale or invalid id");
        return mNodes[id.index];
    }

    /// Moves `child` (with its subtree) under `newParent`, or makes it a root
    /// when `newParent` is invalid. The local transform is kept, so the world
    /// transform changes. Asserts if `newParent` is `child` or a descendant.
    void reparent(NodeId child, NodeId newParent);

    /// Recomputes world, worldBounds and subtreeBounds where anything changed.
    /// Visits only dirty subtrees and the ancestors whose subtreeBounds they
    /// affect; a frame with no changes costs one check per root.
    void updateTransforms();

    /// Appends to `visible` every node whose worldBounds intersect `frustum`,
    /// skipping whole subtrees whose subtreeBounds are outside. Nodes with empty
    /// localBounds are never reported. Order is depth-first, parents before
    /// children. Requires updateTransforms() since the last change (asserts).
    void cull(const Frustum& frustum, std::vector<NodeId>& visible) const;

    /// Number of live nodes.
    size_t nodeCount() const { return mNodes.size() - mFreeSlots.size() - mRetiredSlots; }

    /// The ids of all root nodes, in creation order.
    std::span<const NodeId> roots() const { return mRoots; }

    /// Calls `f(NodeId, const SceneNode&)` for every live node, in slot order.
    /// `f` must not create or destroy nodes.
    template <class F>
    void forEach(F&& f) const {
        for (uint32_t i = 0; i < mNodes.size(); ++i) {
            if (mSlots[i].alive) f(NodeId{i, mSlots[i].generation}, mNodes[i]);
        }
    }

private:
    /// Bookkeeping kept out of SceneNode so that the public data stays plain.
    struct Slot {
        uint32_t generation = 0;
        bool alive = false;
        /// Some descendant is dirty, so this node's subtreeBounds are stale.
        /// Invariant: if set, it is also set on every ancestor.
        bool descendantDirty = false;
    };

    SceneNode& mutableNode(NodeId id);
    void markDirty(NodeId id);
    void markAncestorsDescendantDirty(NodeId parent);
    void detachFromParent(NodeId id);
    void updateSubtree(uint32_t index, const glm::mat4& parentWorld, bool parentChanged);
    void cullSubtree(uint32_t index, const Frustum& frustum, std::vector<NodeId>& visible) const;
    void appendSubtree(uint32_t index, std::vector<NodeId>& visible) const;

    std::vector<SceneNode> mNodes;
    std::vector<Slot> mSlots;
    std::vector<uint32_t> mFreeSlots;
    std::vector<NodeId> mRoots;
    /// Slots whose generation ran out; never reused, so never counted as live.
    size_t mRetiredSlots = 0;
    /// Something changed since the last updateTransforms(); cull() asserts on it.
    bool mNeedsUpdate = false;
};

} // namespace tessera::scene
