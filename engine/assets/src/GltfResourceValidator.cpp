#include "GltfResourceValidator.h"

#include <algorithm>
#include <cctype>

namespace tessera::assets {

namespace fs = std::filesystem;

std::optional<std::string> percentDecode(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out += uri[i];
            continue;
        }
        if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
            !std::isxdigit(static_cast<unsigned char>(uri[i + 2])))
            return std::nullopt;
        out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
        i += 2;
    }
    return out;
}

static bool isDataUri(const std::string& uri) {
    return uri.size() >= 5 && std::equal(uri.begin(), uri.begin() + 5, "data:", [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) == b;
           });
}

size_t GltfResourceValidator::checkDataUri(const std::string& uri, const std::string& ptr,
                                           const std::vector<std::string>& allowed) const {
    size_t comma = uri.find(',');
    if (comma == std::string::npos) raise(ptr, "invalid data URI (no ',')");
    std::string header = uri.substr(5, comma - 5);
    std::vector<std::string> parts;
    for (size_t start = 0;;) {
        size_t semi = header.find(';', start);
        parts.push_back(header.substr(start, semi == std::string::npos ? std::string::npos : semi - start));
        if (semi == std::string::npos) break;
        start = semi + 1;
    }
    bool base64 = parts.size() > 1 && parts.back() == "base64";
    for (size_t i = 1; i < parts.size(); ++i) {
        bool isBase64Flag = base64 && i + 1 == parts.size();
        if (!isBase64Flag && parts[i].find('=') == std::string::npos)
            raise(ptr, "invalid data URI parameter '" + parts[i] + "'");
    }
    if (std::find(allowed.begin(), allowed.end(), parts[0]) == allowed.end())
        raise(ptr, "data URI media type '" + parts[0] + "' is not allowed here");
    std::string payload = uri.substr(comma + 1);
    if (!base64) {
        auto decoded = percentDecode(payload);
        if (!decoded) raise(ptr, "invalid data URI (bad percent escape)");
        return decoded->size();
    }
    if (payload.size() % 4 != 0) raise(ptr, "invalid base64 data in data URI");
    size_t padding = 0;
    for (size_t i = 0; i < payload.size(); ++i) {
        char c = payload[i];
        bool valid = std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/';
        if (c == '=' && i + 2 >= payload.size() && (i + 1 == payload.size() || payload[i + 1] == '=')) {
            ++padding;
            continue;
        }
        if (!valid || padding) raise(ptr, "invalid base64 data in data URI");
    }
    return payload.size() / 4 * 3 - padding;
}

fs::path GltfResourceValidator::resolveFile(const std::string& uri, const std::string& ptr) const {
    size_t colon = uri.find(':');
    if (colon != std::string::npos && uri.find_first_of("/?#") > colon) {
        if (colon == 0) raise(ptr, "invalid URI '" + uri + "' (empty scheme)");
        raise(ptr, "URI '" + uri + "' has a scheme; only relative file paths and data URIs are supported");
    }
    auto decoded = percentDecode(uri);
    if (!decoded || decoded->empty()) raise(ptr, "invalid URI '" + uri + "'");
    fs::path relative(*decoded);
    if (relative.is_absolute() || decoded->find('\\') != std::string::npos || decoded->find('\0') != std::string::npos)
        raise(ptr, "URI '" + uri + "' must be a relative path");
    for (const fs::path& part : relative)
        if (part == "..") raise(ptr, "URI '" + uri + "' leaves the file's folder");
    fs::path file = mFolder / relative;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) raise(ptr, "resource not found (" + *decoded + ")");
    return file;
}

void GltfResourceValidator::validate() const {
    const Json& root = mJson.root();
    for (size_t i = 0; i < mJson.count("buffers"); ++i) {
        std::string ptr = childPointer("/buffers", i);
        const Json& buffer = root["buffers"][i];
        uint64_t byteLength = buffer["byteLength"].get<uint64_t>();
        uint64_t actual = 0;
        if (!buffer.contains("uri")) {
            // A .gltf buffer without a URI has no data; its views and accessors are still checked, and
            // the load fails later only if something reads from it.
            if (!mIsGlb) continue;
            if (i != 0 || !mGlbBin) raise(ptr, "buffer refers to a missing GLB binary chunk");
            actual = mGlbBin->size();
        } else {
            std::string uri = buffer["uri"].get<std::string>();
            if (isDataUri(uri)) {
                actual = checkDataUri(uri, ptr + "/uri", {"application/octet-stream", "application/gltf-buffer"});
            } else {
                std::error_code ec;
                actual = fs::file_size(resolveFile(uri, ptr + "/uri"), ec);
            }
        }
        if (actual < byteLength)
            raise(ptr, "actual data length " + std::to_string(actual) + " is less than byteLength " +
                           std::to_string(byteLength));
    }
    for (size_t i = 0; i < mJson.count("images"); ++i) {
        std::string ptr = childPointer("/images", i);
        const Json& image = root["images"][i];
        if (!image.contains("uri")) continue;
        std::string uri = image["uri"].get<std::string>();
        if (isDataUri(uri)) checkDataUri(uri, ptr + "/uri", {"image/png", "image/jpeg", "image/webp", "image/ktx2"});
        else resolveFile(uri, ptr + "/uri");
    }
}

} // namespace tessera::assets
