#include "tessera/scene/SceneGraph.h"

#include <algorithm>
#include <utility>

namespace tessera::scene {

NodeId SceneGraph::createNode(std::string name, NodeId parent) {
    assert((!parent.valid() || isAlive(parent)) && "SceneGraph::createNode: stale parent");
    uint32_t index;
    if (!mFreeSlots.empty()) {
        index = mFreeSlots.back();
        mFreeSlots.pop_back();
        mNodes[index] = SceneNode{};
    } else {
        index = static_cast<uint32_t>(mNodes.size());
        assert(index != UINT32_MAX && "SceneGraph: out of node slots");
        mNodes.emplace_back();
        mSlots.emplace_back();
    }
    mSlots[index].alive = true;
    mSlots[index].descendantDirty = false;
    const NodeId id{index, mSlots[index].generation};

    SceneNode& n = mNodes[index];
    n.name = std::move(name);
    n.parent = parent;
    if (parent.valid()) {
        mNodes[parent.index].children.push_back(id);
    } else {
        mRoots.push_back(id);
    }
    // A fresh node starts dirty (SceneNode's default), so flag its ancestors
    // directly; markDirty() would see the flag and skip them.
    markAncestorsDescendantDirty(parent);
    mNeedsUpdate = true;
    return id;
}

void SceneGraph::destroyNode(NodeId id) {
    assert(isAlive(id) && "SceneGraph::destroyNode: stale or invalid id");
    detachFromParent(id);
    // The parent's subtreeBounds shrink; the node itself needs no flag.
    markAncestorsDescendantDirty(mNodes[id.index].parent);
    mNeedsUpdate = true;

    // Iterative so that a deep chain cannot overflow the stack.
    std::vector<NodeId> pending{id};
    while (!pending.empty()) {
        NodeId current = pending.back();
        pending.pop_back();
        SceneNode& n = mNodes[current.index];
        pending.insert(pending.end(), n.children.begin(), n.children.end());
        n = SceneNode{}; // Frees the name and children now rather than on reuse.
        Slot& slot = mSlots[current.index];
        slot.alive = false;
        slot.descendantDirty = false;
        // A slot whose generation would wrap could make an ancient id look
        // alive again, so it is retired instead of recycled.
        if (slot.generation == UINT32_MAX) {
            ++mRetiredSlots;
        } else {
            ++slot.generation;
            mFreeSlots.push_back(current.index);
        }
    }
}

bool SceneGraph::isAlive(NodeId id) const {
    return id.index < mSlots.size() && mSlots[id.index].alive &&
           mSlots[id.index].generation == id.generation;
}

void SceneGraph::setLocalTransform(NodeId id, const Transform& transform) {
    mutableNode(id).local = transform;
    markDirty(id);
}

void SceneGraph::setLocalBounds(NodeId id, const Aabb& bounds) {
    mutableNode(id).localBounds = bounds;
    markDirty(id);
}

void SceneGraph::setTag(NodeId id, uint32_t kind, uint32_t payload) {
    SceneNode& n = mutableNode(id);
    n.kind = kind;
    n.payload = payload;
}

void SceneGraph::reparent(NodeId child, NodeId newParent) {
    assert(isAlive(child) && "SceneGraph::reparent: stale child");
    assert((!newParent.valid() || isAlive(newParent)) && "SceneGraph::reparent: stale parent");
    for (NodeId p = newParent; p.valid(); p = mNodes[p.index].parent) {
        assert(p != child && "SceneGraph::reparent: would create a cycle");
        if (p == child) return; // Release builds: refuse rather than corrupt the graph.
    }
    SceneNode& n = mNodes[child.index];
    if (n.parent == newParent) return;

    detachFromParent(child);
    markAncestorsDescendantDirty(n.parent);
    n.parent = newParent;
    if (newParent.valid()) {
        mNodes[newParent.index].children.push_back(child);
    } else {
        mRoots.push_back(child);
    }
    // Force the flag chain up the new ancestry even if the node was already
    // dirty: the invariant held for the old ancestors, not the new ones.
    n.dirty = true;
    markAncestorsDescendantDirty(newParent);
    mNeedsUpdate = true;
}

void SceneGraph::updateTransforms() {
    if (!mNeedsUpdate) return;
    for (NodeId root : mRoots) updateSubtree(root.index, glm::mat4(1.0f), false);
    mNeedsUpdate = false;
}

void SceneGraph::cull(const Frustum& frustum, std::vector<NodeId>& visible) const {
    assert(!mNeedsUpdate && "SceneGraph::cull: call updateTransforms() first");
    for (NodeId root : mRoots) cullSubtree(root.index, frustum, visible);
}

SceneNode& SceneGraph::mutableNode(NodeId id) {
    assert(isAlive(id) && "SceneGraph: stale or invalid id");
    return mNodes[id.index];
}

void SceneGraph::markDirty(NodeId id) {
    SceneNode& n = mNodes[id.index];
    mNeedsUpdate = true;
    // An already dirty node has already flagged its ancestors (see Slot).
    if (n.dirty) return;
    n.dirty = true;
    markAncestorsDescendantDirty(n.parent);
}

void SceneGraph::markAncestorsDescendantDirty(NodeId parent) {
    // Stops at the first flagged ancestor: by the invariant the rest are flagged
    // too, so a burst of changes in one subtree costs O(depth) once, not each time.
    for (NodeId p = parent; p.valid(); p = mNodes[p.index].parent) {
        if (mSlots[p.index].descendantDirty) return;
        mSlots[p.index].descendantDirty = true;
    }
}

void SceneGraph::detachFromParent(NodeId id) {
    const NodeId parent = mNodes[id.index].parent;
    std::vector<NodeId>& siblings = parent.valid() ? mNodes[parent.index].children : mRoots;
    auto it = std::find(siblings.begin(), siblings.end(), id);
    assert(it != siblings.end());
    siblings.erase(it);
}

void SceneGraph::updateSubtree(uint32_t index, const glm::mat4& parentWorld, bool parentChanged) {
    SceneNode& n = mNodes[index];
    Slot& slot = mSlots[index];
    const bool changed = n.dirty || parentChanged;
    if (!changed && !slot.descendantDirty) return;

    if (changed) {
        n.world = parentWorld * n.local.toMatrix();
        n.worldBounds = n.localBounds.transformed(n.world);
    }
    Aabb subtree = n.worldBounds;
    for (NodeId child : n.children) {
        updateSubtree(child.index, n.world, changed);
        subtree.expand(mNodes[child.index].subtreeBounds);
    }
    n.subtreeBounds = subtree;
    n.dirty = false;
    slot.descendantDirty = false;
}

void SceneGraph::cullSubtree(uint32_t index, const Frustum& frustum,
                             std::vector<NodeId>& visible) const {
    const SceneNode& n = mNodes[index];
    switch (frustum.classify(n.subtreeBounds)) {
    case Frustum::Containment::Outside:
        return;
    case Frustum::Containment::Inside:
        // Everything below is inside too: no more plane tests.
        appendSubtree(index, visible);
        return;
    case Frustum::Containment::Intersects:
        break;
    }
    if (!n.localBounds.isEmpty() && frustum.intersects(n.worldBounds)) {
        visible.push_back(NodeId{index, mSlots[index].generation});
    }
    for (NodeId child : n.children) cullSubtree(child.index, frustum, visible);
}

void SceneGraph::appendSubtree(uint32_t index, std::vector<NodeId>& visible) const {
    const SceneNode& n = mNodes[index];
    if (!n.localBounds.isEmpty()) visible.push_back(NodeId{index, mSlots[index].generation});
    for (NodeId child : n.children) appendSubtree(child.index, visible);
}

} // namespace tessera::scene
