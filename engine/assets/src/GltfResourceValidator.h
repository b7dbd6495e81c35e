#pragma once
// GltfResourceValidator: the URIs of buffers and images. Data URIs must be
// well formed with an allowed media type and enough bytes; other URIs must be
// relative paths that stay inside the file's folder (no scheme, no "..", no
// absolute path) and name existing files large enough for their buffer.

#include "JsonChecker.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace tessera::assets {

class GltfResourceValidator {
public:
    GltfResourceValidator(const JsonChecker& json, std::filesystem::path folder, bool isGlb,
                          std::optional<std::string_view> glbBin)
        : mJson(json), mFolder(std::move(folder)), mIsGlb(isGlb), mGlbBin(glbBin) {}

    /// Throws GltfError at the first faulty buffer or image.
    void validate() const;

private:
    /// Bytes a data URI decodes to; throws when malformed or of a media type not in `allowed`.
    size_t checkDataUri(const std::string& uri, const std::string& ptr, const std::vector<std::string>& allowed) const;
    /// The file a relative URI names; throws when unsafe or missing.
    std::filesystem::path resolveFile(const std::string& uri, const std::string& ptr) const;

    const JsonChecker& mJson;
    std::filesystem::path mFolder;
    bool mIsGlb;
    std::optional<std::string_view> mGlbBin;
};

/// Percent-decodes a URI; nullopt on a malformed escape.
std::optional<std::string> percentDecode(const std::string& uri);

} // namespace tessera::assets
