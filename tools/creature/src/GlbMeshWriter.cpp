#include "GlbMeshWriter.h"

#include "GlbDracoEncoder.h"

#include <limits>

namespace tessera::creature {

namespace {

using nlohmann::json;

// The largest vertex count whose indices all fit in uint16 without using
// 65535, which glTF reserves for primitive restart.
constexpr size_t kMaxU16Vertices = 65535;

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

template <int N, class Get>
std::vector<float> packFloats(const std::vector<character::CageVertex>& vertices, Get get) {
    std::vector<float> out;
    out.reserve(vertices.size() * N);
    for (const character::CageVertex& v : vertices) {
        const auto& value = get(v);
        for (int c = 0; c < N; ++c) out.push_back(value[c]);
    }
    return out;
}

template <class T>
std::vector<T> packJoints(const std::vector<character::CageVertex>& vertices) {
    std::vector<T> out;
    out.reserve(vertices.size() * 4);
    for (const character::CageVertex& v : vertices) {
        for (int c = 0; c < 4; ++c) out.push_back(static_cast<T>(v.joints[c]));
    }
    return out;
}

template <class T>
uint32_t addIndices(GlbBuilder& glb, const std::vector<uint32_t>& indices, GlbComponent component) {
    std::vector<T> packed(indices.begin(), indices.end());
    return glb.addAccessor(packed, component, "SCALAR", packed.size(), GlbTarget::ElementArrayBuffer);
}

json writePlain(GlbBuilder& glb, const character::CageMesh& cage, bool skinned) {
    const auto& v = cage.vertices;
    const size_t n = v.size();
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const character::CageVertex& vertex : v) {
        lo = glm::min(lo, vertex.position);
        hi = glm::max(hi, vertex.position);
    }
    constexpr GlbTarget kArray = GlbTarget::ArrayBuffer;
    json attributes;
    attributes["POSITION"] = glb.addAccessor(packFloats<3>(v, [](const auto& x) { return x.position; }),
                                             GlbComponent::F32, "VEC3", n, kArray, vec3Json(lo), vec3Json(hi));
    attributes["NORMAL"] = glb.addAccessor(packFloats<3>(v, [](const auto& x) { return x.normal; }),
                                           GlbComponent::F32, "VEC3", n, kArray);
    attributes["TANGENT"] = glb.addAccessor(packFloats<4>(v, [](const auto& x) { return x.tangent; }),
                                            GlbComponent::F32, "VEC4", n, kArray);
    attributes["TEXCOORD_0"] = glb.addAccessor(packFloats<2>(v, [](const auto& x) { return x.uv; }),
                                               GlbComponent::F32, "VEC2", n, kArray);
    if (skinned) {
        attributes["JOINTS_0"] = cage.bindings.size() < 256
                                     ? glb.addAccessor(packJoints<uint8_t>(v), GlbComponent::U8, "VEC4", n, kArray)
                                     : glb.addAccessor(packJoints<uint16_t>(v), GlbComponent::U16, "VEC4", n, kArray);
        attributes["WEIGHTS_0"] = glb.addAccessor(packFloats<4>(v, [](const auto& x) { return x.weights; }),
                                                  GlbComponent::F32, "VEC4", n, kArray);
    }
    uint32_t indices = n <= kMaxU16Vertices ? addIndices<uint16_t>(glb, cage.indices, GlbComponent::U16)
                                            : addIndices<uint32_t>(glb, cage.indices, GlbComponent::U32);
    return json{{"attributes", attributes}, {"indices", indices}, {"material", 0}, {"mode", 4}};
}

json writeDraco(GlbBuilder& glb, const DracoPrimitive& draco, bool skinned) {
    const size_t n = draco.vertexCount;
    // No bufferView: the data is the decoded Draco geometry.
    json attributes;
    attributes["POSITION"] = glb.addAccessorOver(-1, GlbComponent::F32, "VEC3", n, vec3Json(draco.positionMin),
                                                 vec3Json(draco.positionMax));
    attributes["NORMAL"] = glb.addAccessorOver(-1, GlbComponent::F32, "VEC3", n);
    attributes["TANGENT"] = glb.addAccessorOver(-1, GlbComponent::F32, "VEC4", n);
    attributes["TEXCOORD_0"] = glb.addAccessorOver(-1, GlbComponent::F32, "VEC2", n);
    if (skinned) {
        attributes["JOINTS_0"] =
            glb.addAccessorOver(-1, draco.joints16 ? GlbComponent::U16 : GlbComponent::U8, "VEC4", n);
        attributes["WEIGHTS_0"] = glb.addAccessorOver(-1, GlbComponent::F32, "VEC4", n);
    }
    uint32_t indices = glb.addAccessorOver(-1, n <= kMaxU16Vertices ? GlbComponent::U16 : GlbComponent::U32,
                                           "SCALAR", draco.indexCount);
    uint32_t view = glb.addBufferView(std::as_bytes(std::span(draco.bytes)));
    json extension = {{"bufferView", view}, {"attributes", draco.attributeIds}};
    return json{{"attributes", attributes},
                {"indices", indices},
                {"material", 0},
                {"mode", 4},
                {"extensions", {{"KHR_draco_mesh_compression", extension}}}};
}

} // namespace

Result<json> writePrimitive(GlbBuilder& glb, const character::CageMesh& source, bool skinned,
                            const ExportOptions& options, const std::string& file) {
    // A joint slot with zero weight has no effect; glTF asks for it to be 0
    // (the validator warns otherwise), so both encodings write it that way.
    character::CageMesh cage = source;
    for (character::CageVertex& v : cage.vertices) {
        for (int c = 0; c < 4; ++c) {
            if (v.weights[c] == 0.0f) v.joints[c] = 0;
        }
    }
    if (!options.draco) return writePlain(glb, cage, skinned);
    Result<DracoPrimitive> draco = encodeDraco(cage, skinned, options, file);
    if (!draco) return draco.error();
    return writeDraco(glb, draco.value(), skinned);
}

} // namespace tessera::creature
