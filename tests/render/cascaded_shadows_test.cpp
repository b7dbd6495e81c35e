// Cascaded shadow maps in the demo (docs/LOOKS.md, "Cascaded shadow maps"):
// a character's shadow falls where the sun and the terrain put it, on every
// backend that draws them, under the validation layer. The reference is the
// blob shadow, placed on the CPU from the character's feet, its height and
// the sun (CharacterShadowPass): the cascaded shadow's darkened pixels must
// lie where the blob's do. Which cascade covers which distance, and that the
// cascades cover the view without gaps, are the data model's tests
// (tests/unit/scene_shadow_cascade_test.cpp).
#include "CharacterDemo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;
// Sun elevation 35 degrees; azimuths across the view, so the shadow falls
// beside the character, not behind it (the orbit's first frame looks along
// azimuth 20 or so).
const std::string kSunA = "110,35";
const std::string kSunB = "290,35";
// A terrain pixel is in shadow where it keeps less than this of its light
// under the other sun (same elevation, so the same light on level ground).
constexpr double kShadowRatio = 0.75;

struct PixelSet {
    size_t count = 0;
    double x = 0.0, y = 0.0; ///< centroid, pixels
};

double luminance(const Rgba8Image& image, size_t i) {
    const uint8_t* p = &image.pixels[i * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

/// The one character's demo run with the full look on the terrain (or, with
/// `mask`, alone on a black clear colour in the plain look: its pixels).
std::optional<Rgba8Image> shot(const std::string& backend, const std::string& shadows, const std::string& sun,
                               bool mask, const std::string& name) {
    std::vector<std::string> args = {"--backend", backend, "--scene", "characters", "--crowd", "0", "--model",
                                     froblinFile(), "--tess-max", "14.99", "--frames", "1", "--width",
                                     std::to_string(kWidth), "--height", std::to_string(kHeight), "--sun", sun,
                                     "--shadows", shadows};
    if (mask) args.insert(args.end(), {"--no-terrain", "--look", "plain", "--clear-color", "0,0,0"});
    const DemoShot s = runDemoShot(args, testOutputDir("cascaded_shadows") / (name + ".png"));
    EXPECT_EQ(s.result.exitCode, 0) << s.command << "\n" << s.result.output;
    EXPECT_TRUE(validationClean(s.result)) << s.command << "\n" << s.result.output;
    EXPECT_TRUE(s.image) << s.command << ": " << s.readError;
    return s.image;
}

/// The terrain pixels (not the character's, from `mask`, grown by a pixel
/// for its antialiased edge) `lit` darkens against `reference`.
PixelSet shadowPixels(const Rgba8Image& lit, const Rgba8Image& reference, const Rgba8Image& mask) {
    auto character = [&](int x, int y) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int px = std::clamp(x + dx, 0, kWidth - 1), py = std::clamp(y + dy, 0, kHeight - 1);
                if (luminance(mask, size_t(py) * kWidth + px) > 0.0) return true;
            }
        return false;
    };
    PixelSet set;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = size_t(y) * kWidth + x;
            if (character(x, y) || luminance(lit, i) >= kShadowRatio * luminance(reference, i)) continue;
            ++set.count;
            set.x += x;
            set.y += y;
        }
    if (set.count) set.x /= double(set.count), set.y /= double(set.count);
    return set;
}

} // namespace

// One test over the four backends: they render the same frame (parity), so
// the first backend the device runs makes the reference runs (the
// character's mask, the opposite sun, the blob) and every backend, it
// included, only its own cascaded run: seven demo runs instead of sixteen.
TEST(CascadedShadows, FallWhereTheSunAndTerrainPutThemOnEveryBackend) {
    std::vector<std::string> backends;
    for (const char* backend : {"hulldomain", "r2vb", "streamout", "meshshader"})
        if (deviceRunsBackend(backend)) backends.push_back(backend);
    if (backends.empty()) GTEST_SKIP() << "the device runs no backend that draws cascaded shadows";
    const std::string& first = backends.front();
    const auto mask = shot(first, "cascaded", kSunA, true, first + "_mask");
    const auto opposite = shot(first, "cascaded", kSunB, false, first + "_cascaded_opposite");
    const auto blob = shot(first, "blob", kSunA, false, first + "_blob");
    if (!mask || !opposite || !blob) return;
    // Under the opposite sun the same ground is lit: what the shadow darkens.
    const PixelSet reference = shadowPixels(*blob, *opposite, *mask);
    std::cout << "[cascaded shadows] the blob's " << reference.count << " shadowed pixels at (" << reference.x
              << ", " << reference.y << ") on " << first << "\n";
    ASSERT_GT(reference.count, 100u) << "the blob reference casts no shadow in view";
    for (const std::string& backend : backends) {
        const auto cascaded = shot(backend, "cascaded", kSunA, false, backend + "_cascaded");
        if (!cascaded) continue;
        const PixelSet csm = shadowPixels(*cascaded, *opposite, *mask);
        std::cout << "[cascaded shadows] " << backend << ": " << csm.count << " shadowed pixels centred at ("
                  << csm.x << ", " << csm.y << ")\n";
        EXPECT_GT(csm.count, 100u) << backend << ": the character casts no cascaded shadow";
        EXPECT_LT(std::hypot(csm.x - reference.x, csm.y - reference.y), 10.0)
            << backend << ": the cascaded shadow is not where the sun puts the character's";
    }
}
