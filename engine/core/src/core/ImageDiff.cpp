#include "tessera/core/ImageDiff.h"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace tessera {

Result<ImageDiff> diffImages(const Rgba8Image& image, const Rgba8Image& reference, int channelThreshold) {
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
        if (worst > channelThreshold) {
            ++differing;
            diff.image.pixels[p * 4 + 0] = 255;
        }
        diff.image.pixels[p * 4 + 3] = 255;
    }
    diff.differingFraction = pixels ? double(differing) / double(pixels) : 0.0;
    diff.meanDifference = pixels ? total / double(pixels * 3) : 0.0;
    return diff;
}

} // namespace tessera
