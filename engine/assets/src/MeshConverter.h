#pragma once
// MeshConverter: every triangle primitive of every mesh node of the skeleton
// into the one CageMesh, with the skinning palette. Strips and fans become
// lists; missing normals are generated smooth over welded positions, missing
// tangents from UV derivatives; weights are renormalised.

#include "AccessorReader.h"
#include "SkeletonBuilder.h"
#include "tessera/character/CageMesh.h"

#include <map>

namespace tessera::assets {

class MeshConverter {
public:
    MeshConverter(const tinygltf::Model& model, const SkeletonBuild& skeleton)
        : mModel(model), mSkeleton(skeleton), mReader(model) {}

    /// Throws GltfError when there is no triangle primitive at all.
    character::CageMesh convert();
    /// The triangle primitives of one node's mesh alone, with the palette its
    /// skin gives (or, unskinned, bound rigidly to `skeletonNode`): an MSFT_lod
    /// level of the mesh node at `skeletonNode`, which need not be in the
    /// scene itself. Use a fresh converter. Throws GltfError when it has none.
    character::CageMesh convertNode(int node, uint32_t skeletonNode);
    /// The material of the first triangle primitive (-1 if none).
    int firstMaterial() const { return mFirstMaterial; }

private:
    void addPrimitive(const tinygltf::Primitive& primitive, uint32_t skeletonNode, int skin, const std::string& ptr);
    /// Adds the triangle primitives of a node's mesh.
    void addMesh(const tinygltf::Node& node, uint32_t skeletonNode);
    /// The palette offset of a skin (its bindings are appended once).
    uint32_t skinPalette(int skin, const std::string& ptr);
    uint32_t rigidPalette(uint32_t skeletonNode);

    const tinygltf::Model& mModel;
    const SkeletonBuild& mSkeleton;
    AccessorReader mReader;
    character::CageMesh mMesh;
    std::map<int, uint32_t> mSkinOffsets;
    std::map<uint32_t, uint32_t> mRigidOffsets;
    int mFirstMaterial = -1;
    bool mHaveTriangles = false;
};

/// Per-vertex tangents from UV derivatives (w = handedness) for a triangle list.
void generateTangents(std::vector<character::CageVertex>& vertices, const std::vector<uint32_t>& indices);
/// Smooth normals, accumulated over vertices that share a position (so seams stay closed).
void generateNormals(std::vector<character::CageVertex>& vertices, const std::vector<uint32_t>& indices);

} // namespace tessera::assets
