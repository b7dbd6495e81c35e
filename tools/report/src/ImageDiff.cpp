#include "report/ImageDiff.h"

#include <cstdlib>

namespace tessera::report {

Result<ImageDiff> diffImages(const Rgba8Image& image, const Rgba8Image& reference) {
    if (image.width != reference.width || image.height != reference.height)
        return fail("image is ", std::to_string(image.width), "x", std::to_string(image.height), ", the reference ",
                    std::to_string(reference.width), "x", std::to_string(reference.height));
    const size_t pixels = size_t(image.width) * image.height;
    if (image.pixels.size() < pixels * 4 || reference.pixels.size() < pixels * 4) return fail("image data is short");
    ImageDiff diff;
    diff.image = {image.width, image.height, std::vector<uint8_t>(pixels * 4)};
    size_t differing = 0;
    double total = 0.0;
    for (size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(image.pixels[p * 4 + c]) - int(reference.pixels[p * 4 + c]));
            worst = std::max(worst, d);
            total += d;
            diff.image.pixels[p * 4 + c] = uint8_t(reference.pixels[p * 4 + c] / 4);
        }
        if (worst > kDiffChannelThreshold) {
            ++differing;
            diff.image.pixels[p * 4 + 0] = 255;
        }
        diff.image.pixels[p * 4 + 3] = 255;
    }
    diff.differingFraction = pixels ? double(differing) / double(pixels) : 0.0;
    diff.meanDifference = pixels ? total / double(pixels * 3) : 0.0;
    return diff;
}

std::string base64(const std::vector<uint8_t>& bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const uint32_t v = uint32_t(bytes[i]) << 16 | uint32_t(bytes[i + 1]) << 8 | bytes[i + 2];
        out += kAlphabet[v >> 18 & 63];
        out += kAlphabet[v >> 12 & 63];
        out += kAlphabet[v >> 6 & 63];
        out += kAlphabet[v & 63];
    }
    if (i < bytes.size()) {
        uint32_t v = uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(bytes[i + 1]) << 8;
        out += kAlphabet[v >> 18 & 63];
        out += kAlphabet[v >> 12 & 63];
        out += i + 1 < bytes.size() ? kAlphabet[v >> 6 & 63] : '=';
        out += '=';
    }
    return out;
}

Result<std::string> pngDataUri(const Rgba8Image& image) {
    auto png = encodePng({image.width, image.height, PngLayout::Rgba8, image.pixels.data()});
    if (!png) return png.error();
    return "data:image/png;base64," + base64(png.value());
}

} // namespace tessera::report
