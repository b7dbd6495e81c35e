#include "DracoDecoder.h"

#include "GltfError.h"
#include "GltfFormats.h"

#include <draco/compression/decode.h>

#include <cstring>

namespace tessera::assets {

namespace {

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

    std::vector<unsigned char> indexBytes(static_cast<size_t>(mesh.num_faces()) * 3 * 4);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            uint32_t index = mesh.face(f)[k].value();
            if (index >= points) raise(ptr, "Draco: face index out of range");
            std::memcpy(&indexBytes[(f.value() * 3 + static_cast<uint32_t>(k)) * 4], &index, 4);
        }
    if (primitive.indices < 0) {
        model.accessors.emplace_back();
        model.accessors.back().type = TINYGLTF_TYPE_SCALAR;
        primitive.indices = static_cast<int>(model.accessors.size() - 1);
    }
    attachData(model, primitive.indices, std::move(indexBytes), kUnsignedInt, static_cast<size_t>(mesh.num_faces()) * 3);

    const tinygltf::Value& attributes = ext.Get("attributes");
    for (const std::string& name : attributes.Keys()) {
        auto target = primitive.attributes.find(name);
        if (target == primitive.attributes.end()) raise(ptr, "Draco attribute " + name + " is not a primitive attribute");
        const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(
            static_cast<uint32_t>(attributes.Get(name).Get<int>()));
        if (!attribute) raise(ptr, "Draco attribute " + name + " is not in the compressed mesh");
        const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(target->second)];
        int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
        if (components <= 0 || attribute->num_components() != components)
            raise(ptr, "Draco attribute " + name + " has " + std::to_string(attribute->num_components()) +
                           " components, its accessor " + std::to_string(components));
        std::vector<float> values(points * static_cast<size_t>(components));
        for (draco::PointIndex p(0); p < static_cast<uint32_t>(points); ++p)
            if (!attribute->ConvertValue<float>(attribute->mapped_index(p), static_cast<int8_t>(components),
                                                &values[p.value() * static_cast<size_t>(components)]))
                raise(ptr, "Draco attribute " + name + " cannot be converted");
        std::vector<unsigned char> bytes(values.size() * 4);
        std::memcpy(bytes.data(), values.data(), bytes.size());
        attachData(model, target->second, std::move(bytes), kFloat, points);
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
