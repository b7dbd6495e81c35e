#pragma once
// GltfLayoutValidator: where the bytes are. Buffer views inside their
// buffers, accessors (and sparse parts) inside their views with the alignment
// and stride rules, and each buffer view used for one purpose only (vertex
// data, indices, or other data that must not be strided).

#include "JsonChecker.h"

#include <map>

namespace tessera::assets {

/// What a buffer view holds, as its users say.
enum class ViewUse { Vertex, Index, Other };

class GltfLayoutValidator {
public:
    explicit GltfLayoutValidator(const JsonChecker& json) : mJson(json) {}

    void validate();
    /// Records that accessor `accessor` (referenced at `ptr`) is used as `use`; throws on a conflicting use.
    void useAccessor(size_t accessor, const std::string& ptr, ViewUse use);
    /// Records a direct buffer view use (images).
    void useView(size_t view, const std::string& ptr, ViewUse use);

private:
    void checkBufferView(const Json& view, const std::string& ptr) const;
    void checkAccessor(const Json& accessor, const std::string& ptr) const;
    /// `element`: bytes per element when tightly packed; `end`: bytes its last component ends at.
    void checkRange(const Json& accessorPart, const std::string& ptr, uint64_t count, uint32_t element, uint32_t end,
                    uint32_t alignment) const;

    const JsonChecker& mJson;
    std::map<size_t, ViewUse> mUses;
};

} // namespace tessera::assets
