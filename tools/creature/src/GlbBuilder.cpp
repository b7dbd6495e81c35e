#include "GlbBuilder.h"

#include <cstring>
#include <string>

namespace tessera::creature {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;     // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;    // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;     // "BIN\0"

void appendU32(std::vector<uint8_t>& out, uint32_t value) {
    // glb is little-endian whatever the host is.
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(value >> (8 * i)));
}

size_t paddedTo4(size_t n) { return (n + 3) & ~size_t(3); }

} // namespace

GlbBuilder::GlbBuilder() {
    mJson = nlohmann::json::object();
    mJson["bufferViews"] = nlohmann::json::array();
    mJson["accessors"] = nlohmann::json::array();
}

uint32_t GlbBuilder::addBufferView(std::span<const std::byte> bytes, GlbTarget target) {
    size_t offset = mBin.size();
    mBin.resize(offset + bytes.size());
    if (!bytes.empty()) std::memcpy(mBin.data() + offset, bytes.data(), bytes.size());
    mBin.resize(paddedTo4(mBin.size()), 0);

    nlohmann::json view = {{"buffer", 0}, {"byteLength", bytes.size()}};
    // byteOffset 0 is the default; leaving it out keeps the JSON minimal.
    if (offset != 0) view["byteOffset"] = offset;
    if (target != GlbTarget::None) view["target"] = static_cast<int>(target);
    mJson["bufferViews"].push_back(std::move(view));
    return static_cast<uint32_t>(mJson["bufferViews"].size() - 1);
}

uint32_t GlbBuilder::addAccessorOver(int64_t view, GlbComponent component, const char* type, size_t count,
                                     const std::optional<nlohmann::json>& min,
                                     const std::optional<nlohmann::json>& max) {
    nlohmann::json accessor = {{"componentType", static_cast<int>(component)}, {"type", type}, {"count", count}};
    if (view >= 0) accessor["bufferView"] = view;
    if (min) accessor["min"] = *min;
    if (max) accessor["max"] = *max;
    mJson["accessors"].push_back(std::move(accessor));
    return static_cast<uint32_t>(mJson["accessors"].size() - 1);
}

std::vector<uint8_t> GlbBuilder::finish() {
    // Empty arrays are schema errors in glTF (minItems 1).
    for (const char* key : {"bufferViews", "accessors"}) {
        if (mJson[key].empty()) mJson.erase(key);
    }
    if (!mBin.empty()) mJson["buffers"] = nlohmann::json::array({{{"byteLength", mBin.size()}}});

    std::string text = mJson.dump();
    text.resize(paddedTo4(text.size()), ' ');

    std::vector<uint8_t> out;
    size_t total = 12 + 8 + text.size() + (mBin.empty() ? 0 : 8 + mBin.size());
    out.reserve(total);
    appendU32(out, kGlbMagic);
    appendU32(out, 2);
    appendU32(out, static_cast<uint32_t>(total));
    appendU32(out, static_cast<uint32_t>(text.size()));
    appendU32(out, kChunkJson);
    out.insert(out.end(), text.begin(), text.end());
    if (!mBin.empty()) {
        appendU32(out, static_cast<uint32_t>(mBin.size()));
        appendU32(out, kChunkBin);
        out.insert(out.end(), mBin.begin(), mBin.end());
    }
    return out;
}

} // namespace tessera::creature
