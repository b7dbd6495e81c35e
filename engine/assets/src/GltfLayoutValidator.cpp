#include "GltfLayoutValidator.h"

#include "GltfFormats.h"

namespace tessera::assets {

namespace {
const char* useName(ViewUse use) {
    return use == ViewUse::Vertex ? "vertex data" : use == ViewUse::Index ? "indices" : "non-vertex data";
}
} // namespace

void GltfLayoutValidator::validate() {
    const Json& root = mJson.root();
    for (size_t i = 0; i < mJson.count("bufferViews"); ++i)
        checkBufferView(root["bufferViews"][i], childPointer("/bufferViews", i));
    for (size_t i = 0; i < mJson.count("accessors"); ++i)
        checkAccessor(root["accessors"][i], childPointer("/accessors", i));
}

void GltfLayoutValidator::checkBufferView(const Json& view, const std::string& ptr) const {
    uint64_t offset = view.value("byteOffset", uint64_t{0}), length = view["byteLength"].get<uint64_t>();
    uint64_t bufferLength = mJson.root()["buffers"][view["buffer"].get<size_t>()]["byteLength"].get<uint64_t>();
    if (offset > bufferLength || length > bufferLength - offset)
        raise(ptr, "byte range " + std::to_string(offset) + ".." + std::to_string(offset + length) +
                       " exceeds buffer " + view["buffer"].dump() + " (" + std::to_string(bufferLength) + " bytes)");
    if (view.contains("byteStride")) {
        if (view["byteStride"].get<uint64_t>() > length)
            raise(ptr + "/byteStride", "byteStride is greater than byteLength");
        if (view.value("target", 0) == 34963) raise(ptr + "/byteStride", "only vertex buffer views can have byteStride");
    }
}

void GltfLayoutValidator::checkRange(const Json& part, const std::string& ptr, uint64_t count, uint32_t element,
                                     uint32_t end, uint32_t alignment) const {
    const Json& view = mJson.root()["bufferViews"][part["bufferView"].get<size_t>()];
    uint64_t offset = part.value("byteOffset", uint64_t{0});
    uint64_t viewOffset = view.value("byteOffset", uint64_t{0}), viewLength = view["byteLength"].get<uint64_t>();
    uint64_t stride = view.value("byteStride", uint64_t{0});
    if (offset % alignment != 0)
        raise(ptr + "/byteOffset", "offset " + std::to_string(offset) + " is not a multiple of " + std::to_string(alignment));
    if ((viewOffset + offset) % alignment != 0)
        raise(ptr, "total byte offset " + std::to_string(viewOffset + offset) + " is not a multiple of " +
                       std::to_string(alignment));
    if (stride != 0 && stride < element)
        raise(ptr, "buffer view byteStride " + std::to_string(stride) + " is less than the element size " +
                       std::to_string(element));
    uint64_t step = stride != 0 ? stride : element;
    // count <= 2^53 from the JSON, so this cannot overflow 64 bits meaningfully before the comparison.
    long double last = static_cast<long double>(offset) + static_cast<long double>(step) * (count - 1) + end;
    if (last > static_cast<long double>(viewLength))
        raise(ptr, "byte range " + std::to_string(offset) + ".." + std::to_string(static_cast<uint64_t>(last)) +
                       " exceeds buffer view " + part["bufferView"].dump() + " (" + std::to_string(viewLength) +
                       " bytes)");
}

void GltfLayoutValidator::checkAccessor(const Json& accessor, const std::string& ptr) const {
    int64_t componentType = accessor["componentType"].get<int64_t>();
    std::string type = accessor["type"].get<std::string>();
    uint64_t count = accessor["count"].get<uint64_t>();
    if (accessor.value("normalized", false) && (componentType == kFloat || componentType == kUnsignedInt))
        raise(ptr + "/normalized", "only (unsigned) byte and short accessors can be normalized");
    uint32_t components = componentCount(type);
    for (const char* key : {"min", "max"})
        if (accessor.contains(key) && accessor[key].size() != components)
            raise(ptr + "/" + key, "must have " + std::to_string(components) + " elements");
    bool matrix = type.rfind("MAT", 0) == 0;
    uint32_t alignment = componentSize(componentType);
    if (matrix && alignment < 4 && type != "MAT4" && accessor.contains("byteOffset") &&
        accessor["byteOffset"].get<uint64_t>() % 4 != 0)
        raise(ptr + "/byteOffset", "matrix accessors must be aligned to 4-byte boundaries");
    if (accessor.contains("bufferView"))
        checkRange(accessor, ptr, count, elementSize(componentType, type), elementEnd(componentType, type), alignment);
    if (accessor.contains("sparse")) {
        const Json& sparse = accessor["sparse"];
        uint64_t sparseCount = sparse["count"].get<uint64_t>();
        if (sparseCount > count)
            raise(ptr + "/sparse/count", "sparse accessor overrides more elements than the accessor has");
        const Json& indices = sparse["indices"];
        for (const Json* part : {&indices, &sparse["values"]}) {
            const Json& view = mJson.root()["bufferViews"][(*part)["bufferView"].get<size_t>()];
            if (view.contains("byteStride") || view.value("target", 0) != 0)
                raise(ptr + "/sparse", "sparse buffer views cannot have byteStride or target");
        }
        int64_t indexType = indices["componentType"].get<int64_t>();
        uint32_t indexSize = componentSize(indexType);
        checkRange(indices, ptr + "/sparse/indices", sparseCount, indexSize, indexSize, indexSize);
        checkRange(sparse["values"], ptr + "/sparse/values", sparseCount, elementSize(componentType, type),
                   elementEnd(componentType, type), alignment);
    }
}

void GltfLayoutValidator::useView(size_t view, const std::string& ptr, ViewUse use) {
    const Json& v = mJson.root()["bufferViews"][view];
    int64_t target = v.value("target", int64_t{0});
    if ((target == 34962 && use != ViewUse::Vertex) || (target == 34963 && use != ViewUse::Index))
        raise(ptr, std::string("buffer view target does not match its use as ") + useName(use));
    auto [it, inserted] = mUses.emplace(view, use);
    if (!inserted && it->second != use)
        raise(ptr, std::string("buffer view ") + std::to_string(view) + " is used both as " + useName(it->second) +
                       " and as " + useName(use));
    if (use != ViewUse::Vertex && v.contains("byteStride"))
        raise(ptr, std::string("byteStride must not be defined for buffer views holding ") + useName(use));
}

void GltfLayoutValidator::useAccessor(size_t accessor, const std::string& ptr, ViewUse use) {
    const Json& a = mJson.root()["accessors"][accessor];
    if (a.contains("bufferView")) useView(a["bufferView"].get<size_t>(), ptr, use);
}

} // namespace tessera::assets
