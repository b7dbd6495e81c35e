#pragma once
/// @file NodeId.h
/// Stable handle to a node of a SceneGraph.

#include <cstddef>
#include <cstdint>
#include <functional>

namespace tessera::scene {

/// Names a node by slot index and generation. A slot's generation is bumped
/// when its node is destroyed, so an id kept past destroyNode() no longer
/// matches and SceneGraph::isAlive() reports it stale, even after the slot is
/// reused. The default id is invalid and means "no node" (e.g. no parent).
struct NodeId {
    uint32_t index = UINT32_MAX;
    uint32_t generation = 0;

    /// True unless this is the "no node" id. Says nothing about liveness; ask
    /// SceneGraph::isAlive() for that.
    bool valid() const { return index != UINT32_MAX; }

    friend bool operator==(const NodeId&, const NodeId&) = default;
};

} // namespace tessera::scene

/// Lets NodeId key unordered containers.
template <>
struct std::hash<tessera::scene::NodeId> {
    size_t operator()(const tessera::scene::NodeId& id) const noexcept {
        return std::hash<uint64_t>{}((uint64_t{id.generation} << 32) | id.index);
    }
};
