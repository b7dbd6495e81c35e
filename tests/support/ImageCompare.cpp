#include "ImageCompare.h"

#include "tessera/core/ImageDiff.h"

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
    auto diff = diffImages(actual, expected, tolerance.channelThreshold);
    if (!diff) {
        result.message = diff.error().message;
        return result;
    }
    result.differingFraction = diff->differingFraction;
    result.meanDifference = diff->meanDifference;
    result.match = result.differingFraction <= tolerance.maxDifferingFraction &&
                   result.meanDifference <= tolerance.maxMeanDifference;
    if (!result.match) {
        std::ostringstream out;
        out << result.differingFraction * 100.0 << "% of pixels differ by more than " << tolerance.channelThreshold
            << " (allowed " << tolerance.maxDifferingFraction * 100.0 << "%), mean difference " << result.meanDifference
            << " (allowed " << tolerance.maxMeanDifference << "); diff image: " << diffPath;
        result.message = out.str();
        (void)writePng(diffPath, diff->image);
    }
    return result;
}

} // namespace tessera::test
