#include "MeshConverter.h"

#include "GltfError.h"

#include <glm/gtc/type_ptr.hpp>

namespace tessera::assets {

namespace {

std::vector<uint32_t> triangleList(int mode, const std::vector<uint32_t>& in) {
    std::vector<uint32_t> out;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(in.size() / 3 * 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 2; i < in.size(); ++i) {
            // Every other triangle of a strip flips to keep the winding.
            if (i % 2 == 0) out.insert(out.end(), {in[i - 2], in[i - 1], in[i]});
            else out.insert(out.end(), {in[i - 1], in[i - 2], in[i]});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (size_t i = 2; i < in.size(); ++i) out.insert(out.end(), {in[0], in[i - 1], in[i]});
    }
    return out;
}

} // namespace

uint32_t MeshConverter::rigidPalette(uint32_t skeletonNode) {
    auto it = mRigidOffsets.find(skeletonNode);
    if (it != mRigidOffsets.end()) return it->second;
    uint32_t offset = static_cast<uint32_t>(mMesh.bindings.size());
    mMesh.bindings.push_back({skeletonNode, glm::mat4(1.0f)});
    mRigidOffsets[skeletonNode] = offset;
    return offset;
}

uint32_t MeshConverter::skinPalette(int skin, const std::string& ptr) {
    auto it = mSkinOffsets.find(skin);
    if (it != mSkinOffsets.end()) return it->second;
    const tinygltf::Skin& s = mModel.skins[static_cast<size_t>(skin)];
    std::vector<float> ibm;
    if (s.inverseBindMatrices >= 0) ibm = mReader.readFloats(s.inverseBindMatrices);
    uint32_t offset = static_cast<uint32_t>(mMesh.bindings.size());
    for (size_t j = 0; j < s.joints.size(); ++j) {
        auto node = mSkeleton.nodeToIndex.find(s.joints[j]);
        if (node == mSkeleton.nodeToIndex.end()) raise(ptr, "skin joint node " + std::to_string(s.joints[j]) + " is not in the scene");
        glm::mat4 inverseBind(1.0f);
        if (ibm.size() >= (j + 1) * 16) inverseBind = glm::make_mat4(&ibm[j * 16]);
        mMesh.bindings.push_back({node->second, inverseBind});
    }
    mSkinOffsets[skin] = offset;
    return offset;
}

void MeshConverter::addPrimitive(const tinygltf::Primitive& primitive, uint32_t skeletonNode, int skin,
                                 const std::string& ptr) {
    auto attribute = [&](const char* name) {
        auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    if (attribute("POSITION") < 0) raise(ptr, "POSITION attribute is missing");
    std::vector<float> positions = mReader.readFloats(attribute("POSITION"));
    size_t count = positions.size() / 3;
    auto readN = [&](const char* name, size_t n) {
        int a = attribute(name);
        if (a < 0) return std::vector<float>();
        std::vector<float> v = mReader.readFloats(a);
        if (v.size() != count * n) raise(ptr + "/attributes/" + name, "count differs from POSITION");
        return v;
    };
    std::vector<float> normals = readN("NORMAL", 3), uvs = readN("TEXCOORD_0", 2), tangents = readN("TANGENT", 4);
    std::vector<float> weights = skin >= 0 ? readN("WEIGHTS_0", 4) : std::vector<float>();
    std::vector<double> joints;
    if (skin >= 0 && attribute("JOINTS_0") >= 0) joints = mReader.read(attribute("JOINTS_0"), false);
    if (skin >= 0 && (joints.size() != count * 4 || weights.size() != count * 4))
        raise(ptr, "skinned primitive needs JOINTS_0 and WEIGHTS_0");

    uint32_t palette = skin >= 0 ? skinPalette(skin, ptr) : rigidPalette(skeletonNode);
    size_t jointCount = skin >= 0 ? mModel.skins[static_cast<size_t>(skin)].joints.size() : 1;
    std::vector<character::CageVertex> vertices(count);
    for (size_t v = 0; v < count; ++v) {
        character::CageVertex& cv = vertices[v];
        cv.position = glm::make_vec3(&positions[v * 3]);
        if (!normals.empty()) cv.normal = glm::normalize(glm::make_vec3(&normals[v * 3]));
        if (!uvs.empty()) cv.uv = glm::make_vec2(&uvs[v * 2]);
        if (!tangents.empty()) cv.tangent = glm::make_vec4(&tangents[v * 4]);
        if (skin >= 0) {
            glm::vec4 w = glm::make_vec4(&weights[v * 4]);
            float sum = w.x + w.y + w.z + w.w;
            cv.weights = sum > 0.0f ? w / sum : glm::vec4(1, 0, 0, 0);
            for (int c = 0; c < 4; ++c) {
                double j = joints[v * 4 + static_cast<size_t>(c)];
                if (j >= static_cast<double>(jointCount)) raise(ptr + "/attributes/JOINTS_0", "joint index outside the skin");
                cv.joints[c] = static_cast<uint16_t>(palette + static_cast<uint32_t>(j));
            }
        } else {
            cv.joints = glm::u16vec4(static_cast<uint16_t>(palette), 0, 0, 0);
            cv.weights = glm::vec4(1, 0, 0, 0);
        }
    }
    std::vector<uint32_t> raw;
    if (primitive.indices >= 0) {
        for (double i : mReader.read(primitive.indices, false)) {
            if (i >= static_cast<double>(count)) raise(ptr + "/indices", "index out of range");
            raw.push_back(static_cast<uint32_t>(i));
        }
    } else {
        for (size_t i = 0; i < count; ++i) raw.push_back(static_cast<uint32_t>(i));
    }
    std::vector<uint32_t> indices = triangleList(primitive.mode, raw);
    if (normals.empty()) generateNormals(vertices, indices);
    if (tangents.empty()) generateTangents(vertices, indices);
    uint32_t base = static_cast<uint32_t>(mMesh.vertices.size());
    mMesh.vertices.insert(mMesh.vertices.end(), vertices.begin(), vertices.end());
    for (uint32_t i : indices) mMesh.indices.push_back(base + i);
}

void MeshConverter::addMesh(const tinygltf::Node& node, uint32_t skeletonNode) {
    const tinygltf::Mesh& mesh = mModel.meshes[static_cast<size_t>(node.mesh)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& primitive = mesh.primitives[p];
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            primitive.mode != TINYGLTF_MODE_TRIANGLE_FAN)
            continue;
        if (mFirstMaterial < 0 && !mHaveTriangles) mFirstMaterial = primitive.material;
        mHaveTriangles = true;
        addPrimitive(primitive, skeletonNode, node.skin,
                     "/meshes/" + std::to_string(node.mesh) + "/primitives/" + std::to_string(p));
    }
}

character::CageMesh MeshConverter::convert() {
    for (size_t s = 0; s < mSkeleton.indexToNode.size(); ++s) {
        const tinygltf::Node& node = mModel.nodes[static_cast<size_t>(mSkeleton.indexToNode[s])];
        if (node.mesh >= 0) addMesh(node, static_cast<uint32_t>(s));
    }
    if (!mHaveTriangles || mMesh.indices.empty()) raise("", "no triangle primitives");
    if (mMesh.bindings.size() > 65535) raise("", "too many skin joints");
    return std::move(mMesh);
}

character::CageMesh MeshConverter::convertNode(int node, uint32_t skeletonNode) {
    const tinygltf::Node& n = mModel.nodes[static_cast<size_t>(node)];
    if (n.mesh >= 0) addMesh(n, skeletonNode);
    if (!mHaveTriangles || mMesh.indices.empty()) raise("/nodes/" + std::to_string(node), "no triangle primitives");
    return std::move(mMesh);
}

} // namespace tessera::assets
