#pragma once
// SkeletonBuilder: the nodes of the default scene as a parent-first
// character::Skeleton, with the glTF node -> skeleton index map the other
// converters use.

#include "GltfTinyGltf.h"
#include "tessera/character/Skeleton.h"

#include <map>

namespace tessera::assets {

struct SkeletonBuild {
    character::Skeleton skeleton;
    std::map<int, uint32_t> nodeToIndex;  ///< glTF node -> index in skeleton.nodes
    std::vector<int> indexToNode;         ///< the inverse
};

/// The default scene (`scene`, else scene 0, else every root node).
SkeletonBuild buildSkeleton(const tinygltf::Model& model);

/// A node's local transform (TRS, or its matrix decomposed).
character::NodeTransform nodeTransform(const tinygltf::Node& node);

} // namespace tessera::assets
