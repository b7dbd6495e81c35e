#include "ImageCompare.h"

#include <cstdlib>
#include <sstream>

namespace tessera::test {

ImageComparison compareImages(const Rgba8Image& actual, const Rgba8Image& expected, const ImageTolerance& tolerance,
                              const std::string& diffPath) {
    ImageComparison result;
    if (actual.width != expected.width || actual.height != expected.height) {
        std::ostringstream out;
        out << "size " << actual.width << "x" << actual.height << " differs from golden " << expected.width << "x"
            << expected.height;
        result.message = out.str();
        return result;
    }
    const size_t pixels = size_t(actual.width) * actual.height;
    Rgba8Image diff{actual.width, actual.height, std::vector<uint8_t>(pixels * 4)};
    size_t differing = 0;
    double total = 0.0;
    for (size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(actual.pixels[p * 4 + c]) - int(expected.pixels[p * 4 + c]));
            worst = std::max(worst, d);
            total += d;
        }
        const bool differs = worst > tolerance.channelThreshold;
        differing += differs;
        for (int c = 0; c < 3; ++c) diff.pixels[p * 4 + c] = uint8_t(expected.pixels[p * 4 + c] / 4);
        if (differs) diff.pixels[p * 4 + 0] = 255;
        diff.pixels[p * 4 + 3] = 255;
    }
    result.differingFraction = double(differing) / double(pixels);
    result.meanDifference = total / double(pixels * 3);
    result.match = result.differingFraction <= tolerance.maxDifferingFraction &&
                   result.meanDifference <= tolerance.maxMeanDifference;
    if (!result.match) {
        std::ostringstream out;
        out << result.differingFraction * 100.0 << "% of pixels differ by more than " << tolerance.channelThreshold
            << " (allowed " << tolerance.maxDifferingFraction * 100.0 << "%), mean difference " << result.meanDifference
            << " (allowed " << tolerance.maxMeanDifference << "); diff image: " << diffPath;
        result.message = out.str();
        (void)writePng(diffPath, diff);
    }
    return result;
}

} // namespace tessera::test
