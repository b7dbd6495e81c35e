#include "AccessorReader.h"

#include "GltfError.h"
#include "GltfFormats.h"

#include <algorithm>
#include <cstring>

namespace tessera::assets {

namespace {

// Accessors with no buffer view are all zeros; refuse absurd counts rather than allocate them.
constexpr size_t kMaxImplicitValues = size_t{1} << 26;

double decode(const uint8_t* p, int componentType, bool normalize) {
    switch (componentType) {
    case kByte: { int8_t v; std::memcpy(&v, p, 1); return normalize ? std::max(v / 127.0, -1.0) : v; }
    case kUnsignedByte: return normalize ? p[0] / 255.0 : p[0];
    case kShort: { int16_t v; std::memcpy(&v, p, 2); return normalize ? std::max(v / 32767.0, -1.0) : v; }
    case kUnsignedShort: { uint16_t v; std::memcpy(&v, p, 2); return normalize ? v / 65535.0 : v; }
    case kUnsignedInt: { uint32_t v; std::memcpy(&v, p, 4); return v; }
    default: { float v; std::memcpy(&v, p, 4); return v; }
    }
}

const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    default: return "MAT4";
    }
}

// Reads `count` elements starting at byteOffset of a buffer view into out[firstValue...].
struct Span { const uint8_t* data; size_t size; };

Span viewSpan(const tinygltf::Model& model, int viewIndex, const std::string& what) {
    if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size()) raise(what, "missing buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) raise(what, "missing buffer");
    const auto& data = model.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        raise(what, "buffer view exceeds its buffer's data");
    return {data.data() + view.byteOffset, view.byteLength};
}

} // namespace

uint32_t AccessorReader::components(int accessor) const {
    return componentCount(typeName(mModel.accessors[static_cast<size_t>(accessor)].type));
}

std::vector<double> AccessorReader::read(int index, bool normalize) const {
    const std::string what = "/accessors/" + std::to_string(index);
    if (index < 0 || static_cast<size_t>(index) >= mModel.accessors.size()) raise(what, "unresolved accessor");
    const tinygltf::Accessor& a = mModel.accessors[static_cast<size_t>(index)];
    const std::string type = typeName(a.type);
    const uint32_t comps = componentCount(type), size = componentSize(a.componentType);
    const uint32_t rows = type == "MAT2" ? 2 : type == "MAT3" ? 3 : type == "MAT4" ? 4 : comps;
    const uint32_t columnBytes = (type.rfind("MAT", 0) == 0) ? (rows * size + 3) / 4 * 4 : rows * size;
    const uint32_t element = elementSize(a.componentType, type);
    bool norm = normalize && a.normalized;
    if (a.bufferView < 0 && a.count * comps > kMaxImplicitValues) raise(what, "accessor without data is too large");

    auto readElements = [&](Span span, size_t offset, size_t stride, size_t count, int componentType, uint32_t n,
                            uint32_t perColumn, uint32_t colBytes, double* out) {
        uint32_t cs = componentSize(componentType);
        if (count == 0) return;
        size_t last = n - 1, elementEnd = (last / perColumn) * colBytes + (last % perColumn) * cs + cs;
        if (stride == 0 || offset > span.size || (count - 1) > (span.size - offset) / stride ||
            elementEnd > span.size - offset - (count - 1) * stride)
            raise(what, "byte range exceeds its buffer view");
        for (size_t e = 0; e < count; ++e)
            for (uint32_t c = 0; c < n; ++c) {
                size_t at = offset + e * stride + (c / perColumn) * colBytes + (c % perColumn) * cs;
                out[e * n + c] = decode(span.data + at, componentType, norm);
            }
    };

    std::vector<double> values(a.count * comps, 0.0);
    if (a.bufferView >= 0) {
        Span span = viewSpan(mModel, a.bufferView, what);
        size_t stride = static_cast<size_t>(a.ByteStride(mModel.bufferViews[static_cast<size_t>(a.bufferView)]));
        if (stride == 0 || stride == static_cast<size_t>(-1)) stride = element;
        readElements(span, a.byteOffset, stride, a.count, a.componentType, comps, rows, columnBytes, values.data());
    }
    if (a.sparse.isSparse) {
        size_t n = static_cast<size_t>(a.sparse.count);
        if (n > a.count) raise(what, "sparse count exceeds the accessor count");
        std::vector<double> indices(n), replacement(n * comps);
        bool saved = norm;
        norm = false;
        readElements(viewSpan(mModel, a.sparse.indices.bufferView, what), static_cast<size_t>(a.sparse.indices.byteOffset),
                     componentSize(a.sparse.indices.componentType), n, a.sparse.indices.componentType, 1, 1, 0,
                     indices.data());
        norm = saved;
        readElements(viewSpan(mModel, a.sparse.values.bufferView, what), static_cast<size_t>(a.sparse.values.byteOffset),
                     element, n, a.componentType, comps, rows, columnBytes, replacement.data());
        for (size_t i = 0; i < n; ++i) {
            if (indices[i] >= static_cast<double>(a.count) || (i > 0 && indices[i] <= indices[i - 1]))
                raise(what + "/sparse/indices", "sparse indices must be increasing and less than the accessor count");
            std::copy_n(&replacement[i * comps], comps, &values[static_cast<size_t>(indices[i]) * comps]);
        }
    }
    return values;
}

std::vector<float> AccessorReader::readFloats(int accessor) const {
    std::vector<double> values = read(accessor, true);
    return std::vector<float>(values.begin(), values.end());
}

} // namespace tessera::assets
