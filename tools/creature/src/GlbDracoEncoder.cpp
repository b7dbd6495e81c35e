#include "GlbDracoEncoder.h"

#include <draco/compression/decode.h>
#include <draco/compression/expert_encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <limits>
#include <memory>

namespace tessera::creature {

namespace {

using draco::DataType;
using draco::GeometryAttribute;

// Adds one attribute with a value per cage vertex; `element(i, out)` writes
// vertex i's `Components` values of type T.
template <class T, int Components, class Element>
int addAttribute(draco::Mesh& mesh, GeometryAttribute::Type type, DataType dataType, size_t count,
                 Element element) {
    GeometryAttribute attribute;
    attribute.Init(type, nullptr, Components, dataType, false, sizeof(T) * Components, 0);
    int id = mesh.AddAttribute(attribute, true, static_cast<uint32_t>(count));
    draco::PointAttribute* stored = mesh.attribute(id);
    T value[Components];
    for (size_t i = 0; i < count; ++i) {
        element(i, value);
        stored->SetAttributeValue(draco::AttributeValueIndex(static_cast<uint32_t>(i)), value);
    }
    return id;
}

// draco::Mesh cannot be moved (its metadata member blocks it): built on the heap.
std::unique_ptr<draco::Mesh> buildMesh(const character::CageMesh& cage, bool skinned, bool joints16,
                                       std::map<std::string, uint32_t>& ids) {
    const auto& v = cage.vertices;
    auto meshPtr = std::make_unique<draco::Mesh>();
    draco::Mesh& mesh = *meshPtr;
    mesh.set_num_points(static_cast<uint32_t>(v.size()));
    for (size_t t = 0; t + 2 < cage.indices.size(); t += 3) {
        mesh.AddFace({draco::PointIndex(cage.indices[t]), draco::PointIndex(cage.indices[t + 1]),
                      draco::PointIndex(cage.indices[t + 2])});
    }
    ids["POSITION"] = addAttribute<float, 3>(mesh, GeometryAttribute::POSITION, draco::DT_FLOAT32, v.size(),
                                             [&](size_t i, float* o) { std::copy_n(&v[i].position.x, 3, o); });
    ids["NORMAL"] = addAttribute<float, 3>(mesh, GeometryAttribute::NORMAL, draco::DT_FLOAT32, v.size(),
                                           [&](size_t i, float* o) { std::copy_n(&v[i].normal.x, 3, o); });
    // Tangents, joints and weights go as GENERIC: the newer named Draco
    // types (TANGENT, JOINTS, WEIGHTS) are rejected by older decoders, and
    // glTF maps attributes by unique id anyway.
    ids["TANGENT"] = addAttribute<float, 4>(mesh, GeometryAttribute::GENERIC, draco::DT_FLOAT32, v.size(),
                                            [&](size_t i, float* o) { std::copy_n(&v[i].tangent.x, 4, o); });
    ids["TEXCOORD_0"] = addAttribute<float, 2>(mesh, GeometryAttribute::TEX_COORD, draco::DT_FLOAT32, v.size(),
                                               [&](size_t i, float* o) { std::copy_n(&v[i].uv.x, 2, o); });
    if (skinned) {
        if (joints16) {
            ids["JOINTS_0"] = addAttribute<uint16_t, 4>(
                mesh, GeometryAttribute::GENERIC, draco::DT_UINT16, v.size(),
                [&](size_t i, uint16_t* o) { std::copy_n(&v[i].joints.x, 4, o); });
        } else {
            ids["JOINTS_0"] = addAttribute<uint8_t, 4>(mesh, GeometryAttribute::GENERIC, draco::DT_UINT8, v.size(),
                                                       [&](size_t i, uint8_t* o) {
                                                           for (int c = 0; c < 4; ++c)
                                                               o[c] = static_cast<uint8_t>(v[i].joints[c]);
                                                       });
        }
        ids["WEIGHTS_0"] = addAttribute<float, 4>(mesh, GeometryAttribute::GENERIC, draco::DT_FLOAT32, v.size(),
                                                  [&](size_t i, float* o) { std::copy_n(&v[i].weights.x, 4, o); });
    }
    // Sharing equal values (a seam vertex's position on both charts) lets
    // Edgebreaker see one connected surface and encode the UV seams as
    // attribute seams; equal inputs also decode to equal outputs, so the
    // cage stays watertight.
    mesh.DeduplicateAttributeValues();
    return meshPtr;
}

} // namespace

Result<DracoPrimitive> encodeDraco(const character::CageMesh& cage, bool skinned, const ExportOptions& options,
                                   const std::string& file) {
    for (int bits : {options.dracoPositionBits, options.dracoNormalBits, options.dracoTexCoordBits,
                     options.dracoGenericBits}) {
        if (bits < 1 || bits > 30) return fail(file, ": Draco quantisation bits must be in 1..30, got ", std::to_string(bits));
    }
    DracoPrimitive out;
    out.joints16 = cage.bindings.size() >= 256;
    std::unique_ptr<draco::Mesh> mesh = buildMesh(cage, skinned, out.joints16, out.attributeIds);

    draco::ExpertEncoder encoder(*mesh);
    encoder.SetEncodingMethod(draco::MESH_EDGEBREAKER_ENCODING);
    encoder.SetSpeedOptions(3, 3);
    encoder.SetAttributeQuantization(out.attributeIds["POSITION"], options.dracoPositionBits);
    encoder.SetAttributeQuantization(out.attributeIds["NORMAL"], options.dracoNormalBits);
    encoder.SetAttributeQuantization(out.attributeIds["TANGENT"], options.dracoGenericBits);
    encoder.SetAttributeQuantization(out.attributeIds["TEXCOORD_0"], options.dracoTexCoordBits);
    // Joints are integers: Draco stores them losslessly, unquantised.
    if (skinned) encoder.SetAttributeQuantization(out.attributeIds["WEIGHTS_0"], options.dracoGenericBits);

    draco::EncoderBuffer buffer;
    draco::Status status = encoder.EncodeToBuffer(&buffer);
    if (!status.ok()) return fail(file, ": Draco encoding failed: ", status.error_msg_string());
    out.bytes.assign(buffer.data(), buffer.data() + buffer.size());

    draco::DecoderBuffer input;
    input.Init(buffer.data(), buffer.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&input);
    if (!decoded.ok()) return fail(file, ": Draco round trip failed: ", decoded.status().error_msg_string());
    const draco::Mesh& result = *decoded.value();
    out.vertexCount = result.num_points();
    out.indexCount = result.num_faces() * 3;

    const draco::PointAttribute* position = result.GetAttributeByUniqueId(out.attributeIds["POSITION"]);
    if (!position) return fail(file, ": Draco round trip lost the positions");
    out.positionMin = glm::vec3(std::numeric_limits<float>::max());
    out.positionMax = glm::vec3(std::numeric_limits<float>::lowest());
    for (uint32_t p = 0; p < result.num_points(); ++p) {
        glm::vec3 value;
        position->GetMappedValue(draco::PointIndex(p), &value.x);
        out.positionMin = glm::min(out.positionMin, value);
        out.positionMax = glm::max(out.positionMax, value);
    }
    return out;
}

} // namespace tessera::creature
