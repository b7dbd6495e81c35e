#include "DracoDecoder.h"

#include "GltfError.h"
#include "GltfFormats.h"

#include <draco/compression/decode.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessera::assets {

namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// The extension's rule: the decoded mesh has exactly the counts the glTF
// accessors declare. A damaged payload can decode "successfully" into other
// counts; rendering it would draw corrupted geometry.
void checkCount(const std::string& ptr, const std::string& what, int accessor, size_t declared, size_t decoded) {
    if (declared == decoded) return;
    raise(ptr, std::string(kExtension) + ": decoded " + std::to_string(decoded) + " " + what + ", but accessor " +
                   std::to_string(accessor) + " declares " + std::to_string(declared));
}

// Decoded values must lie within the accessor's declared min and max. The
// encoder quantised them (at most 2^-8 of the range off for the coarsest
// quantisation Draco's glTF tools use, 8 bits), so that much slack is
// allowed; a damaged payload decodes far outside.
void checkBounds(const std::string& ptr, const std::string& name, int accessorIndex, const tinygltf::Accessor& accessor,
                 const std::vector<float>& values, int components) {
    const auto& lo = accessor.minValues;
    const auto& hi = accessor.maxValues;
    if (lo.size() != size_t(components) || hi.size() != size_t(components)) return;
    for (int c = 0; c < components; ++c) {
        const double range = std::max(hi[size_t(c)] - lo[size_t(c)], 0.0);
        const double slack = range / 256.0 + 1e-6 * std::max({1.0, std::abs(lo[size_t(c)]), std::abs(hi[size_t(c)])});
        for (size_t i = size_t(c); i < values.size(); i += size_t(components)) {
            const double v = values[i];
            if (std::isfinite(v) && v >= lo[size_t(c)] - slack && v <= hi[size_t(c)] + slack) continue;
            raise(ptr, std::string(kExtension) + ": attribute " + name + " decoded value " + std::to_string(v) +
                           " (point " + std::to_string(i / size_t(components)) + ", component " + std::to_string(c) +
                           ") lies outside accessor " + std::to_string(accessorIndex) + "'s min " +
                           std::to_string(lo[size_t(c)]) + " and max " + std::to_string(hi[size_t(c)]));
        }
    }
}

// Appends a tightly packed buffer + view and points `accessor` at it.
void attachData(tinygltf::Model& model, int accessor, std::vector<unsigned char> bytes, int componentType,
                size_t count) {
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteLength = buffer.data.size();
    model.buffers.push_back(std::move(buffer));
    model.bufferViews.push_back(view);
    tinygltf::Accessor& a = model.accessors[static_cast<size_t>(accessor)];
    a.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    a.byteOffset = 0;
    a.componentType = componentType;
    a.normalized = false;
    a.count = count;
    a.sparse.isSparse = false;
}

void decodePrimitive(tinygltf::Model& model, tinygltf::Primitive& primitive, const tinygltf::Value& ext,
                     const std::string& ptr) {
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(ext.Get("bufferView").Get<int>())];
    const auto& data = model.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        raise(ptr, "Draco buffer view exceeds its buffer's data");
    draco::DecoderBuffer input;
    input.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&input);
    if (!decoded.ok()) raise(ptr, "Draco: " + decoded.status().error_msg_string());
    const draco::Mesh& mesh = *decoded.value();
    const size_t points = mesh.num_points();
    // Draco holds triangle meshes; other modes cannot come out of it.
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
        raise(ptr, std::string(kExtension) + ": mode " + std::to_string(primitive.mode) +
                       " is not TRIANGLES (4) or TRIANGLE_STRIP (5)");
    if (points == 0 || mesh.num_faces() == 0) raise(ptr, std::string(kExtension) + ": decoded an empty mesh");
    const size_t indexCount = static_cast<size_t>(mesh.num_faces()) * 3;
    if (primitive.indices >= 0)
        checkCount(ptr, "indices", primitive.indices, model.accessors[static_cast<size_t>(primitive.indices)].count,
                   indexCount);

    std::vector<unsigned char> indexBytes(static_cast<size_t>(mesh.num_faces()) * 3 * 4);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            uint32_t index = mesh.face(f)[k].value();
            if (index >= points) raise(ptr, "Draco: face index out of range");
            std::memcpy(&indexBytes[(f.value() * 3 + static_cast<uint32_t>(k)) * 4], &index, 4);
        }

    // Every attribute first, so nothing is attached for a primitive that fails.
    struct Decoded {
        int accessor;
        std::vector<float> values;
    };
    std::vector<Decoded> decodedAttributes;

    const tinygltf::Value& attributes = ext.Get("attributes");
    for (const std::string& name : attributes.Keys()) {
        auto target = primitive.attributes.find(name);
        if (target == primitive.attributes.end()) raise(ptr, "Draco attribute " + name + " is not a primitive attribute");
        const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(
            static_cast<uint32_t>(attributes.Get(name).Get<int>()));
        if (!attribute) raise(ptr, "Draco attribute " + name + " is not in the compressed mesh");
        const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(target->second)];
        checkCount(ptr, "points for attribute " + name, target->second, accessor.count, points);
        int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
        if (components <= 0 || attribute->num_components() != components)
            raise(ptr, "Draco attribute " + name + " has " + std::to_string(attribute->num_components()) +
                           " components, but accessor " + std::to_string(target->second) + " has " +
                           std::to_string(components));
        std::vector<float> values(points * static_cast<size_t>(components));
        for (draco::PointIndex p(0); p < static_cast<uint32_t>(points); ++p)
            if (!attribute->ConvertValue<float>(attribute->mapped_index(p), static_cast<int8_t>(components),
                                                &values[p.value() * static_cast<size_t>(components)]))
                raise(ptr, "Draco attribute " + name + " cannot be converted");
        checkBounds(ptr, name, target->second, accessor, values, components);
        decodedAttributes.push_back({target->second, std::move(values)});
    }

    if (primitive.indices < 0) {
        model.accessors.emplace_back();
        model.accessors.back().type = TINYGLTF_TYPE_SCALAR;
        primitive.indices = static_cast<int>(model.accessors.size() - 1);
    }
    attachData(model, primitive.indices, std::move(indexBytes), kUnsignedInt, indexCount);
    // The indices are a triangle list whatever the mode was.
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    for (Decoded& d : decodedAttributes) {
        std::vector<unsigned char> bytes(d.values.size() * 4);
        std::memcpy(bytes.data(), d.values.data(), bytes.size());
        attachData(model, d.accessor, std::move(bytes), kFloat, points);
    }
}

} // namespace

void decodeDracoPrimitives(tinygltf::Model& model) {
    for (size_t m = 0; m < model.meshes.size(); ++m)
        for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            auto ext = primitive.extensions.find("KHR_draco_mesh_compression");
            if (ext == primitive.extensions.end()) continue;
            decodePrimitive(model, primitive, ext->second,
                            "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p));
        }
}

} // namespace tessera::assets
