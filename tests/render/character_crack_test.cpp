// Crack test for characters (the first paper's "Displacement Map Tips and
// Reducing Surface Cracks"): one displaced creature alone on a magenta clear
// colour, close enough to fill much of the frame, on every backend, on both
// character paths and at several levels, fractional ones included so that
// fractional_odd spacing occurs. The background surrounds the silhouette, so
// a magenta pixel is no fault in itself; a hole is a magenta pixel that the
// background cannot reach from the image border (CharacterHoles.h). With back
// faces culled, a crack between patches, at a UV seam of the displacement map
// or between neighbouring triangles' displaced edges shows the clear colour
// through the body, and the border fill cannot reach it.
#include "CharacterDemo.h"
#include "CharacterHoles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

/// Where the camera stands at frame 0 (it circles 1.6 m above the site,
/// looking down on the creature) and what it must see.
struct CrackView {
    const char* name;
    const char* orbit; ///< --orbit-distance
    int width, height;
    size_t minCharacterPixels; ///< fewer means the character went missing
};

// From 1 m: head, ears, shoulders and arms seen from above cover about 9,200
// of the 76,800 pixels (lavapipe, every level up to 15).
const CrackView kClose{"close", "1.0", 320, 240, 6000};
// From 1.6 m: the whole body, legs and feet included, in about 9,100 of
// 120,000 pixels.
const CrackView kWhole{"whole", "1.6", 400, 300, 6000};

struct CrackRun {
    DemoShot shot;
    HoleReport holes;
    size_t characterPixels = 0; ///< pixels that are not background
    size_t minCharacterPixels = 0;
};

CrackRun runCrack(const std::string& backend, const std::string& path, const std::string& level,
                  const CrackView& view = kClose, const std::vector<std::string>& extra = {}) {
    std::string name = backend;
    name.append("_").append(view.name).append("_").append(path).append("_l").append(level);
    for (const std::string& flag : extra) {
        name += '_';
        name += flag.substr(flag.find_first_not_of('-'));
    }
    std::vector<std::string> args =
        soloCharacterArgs(backend, froblinFile(1), "1,0,1", view.orbit, view.width, view.height);
    args.insert(args.end(), {"--frames", "1", "--character-path", path, "--character-level", level});
    args.insert(args.end(), extra.begin(), extra.end());
    CrackRun run;
    run.minCharacterPixels = view.minCharacterPixels;
    run.shot = runDemoShot(args, testOutputDir("character_crack") / (name + ".png"));
    if (run.shot.image) {
        run.holes = findHoles(*run.shot.image);
        run.characterPixels = size_t(view.width) * size_t(view.height) - run.holes.magenta;
    }
    return run;
}

/// True when the default device is lavapipe (Mesa's CPU driver).
bool defaultDeviceIsLavapipe() {
    return runDemo({"--list-backends"}).output.find("device: llvmpipe") != std::string::npos;
}

/// Isolated one-pixel holes the whole-body views may show (see
/// CharacterCrackWholeBody); 0 everywhere else.
struct HoleAllowance {
    size_t isolatedPixels = 0;
};

/// Checks one run; returns whether it passed, so the sweep can count failures.
bool expectClosed(const CrackRun& run, HoleAllowance allowance = {}) {
    const DemoShot& shot = run.shot;
    EXPECT_EQ(shot.result.exitCode, 0) << shot.command << "\n" << shot.result.output;
    if (shot.result.exitCode != 0) return false;
    EXPECT_TRUE(validationClean(shot.result)) << shot.command << "\n" << shot.result.output;
    EXPECT_TRUE(shot.image) << shot.command << ": " << shot.readError;
    if (!shot.image) return false;
    std::cout << "[crack] " << shot.command << "\n        " << run.holes.describe() << ", character covers "
              << run.characterPixels << " px\n";
    // Not vacuous: the creature is in view and fills a good part of it.
    EXPECT_GT(run.characterPixels, run.minCharacterPixels) << "the character is barely in view\n  " << shot.command;
    // A crack is a line along an edge: any hole of two or more pixels fails,
    // and one-pixel holes only up to the allowance.
    const bool isolated = std::all_of(run.holes.holes.begin(), run.holes.holes.end(),
                                      [](const HoleComponent& h) { return h.pixels == 1; });
    const bool closed = run.holes.holePixels == 0 || (isolated && run.holes.holePixels <= allowance.isolatedPixels);
    EXPECT_TRUE(closed) << run.holes.describe() << ", a crack or hole in the surface\n  " << shot.command
                        << "\n  screenshot: " << shot.screenshot;
    return closed && validationClean(shot.result) && run.characterPixels > run.minCharacterPixels;
}

/// `image` filled with magenta, `w` x `h`.
Rgba8Image magentaImage(uint32_t w, uint32_t h) {
    Rgba8Image image{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
    for (size_t i = 0; i < size_t(w) * h; ++i) {
        image.pixels[i * 4 + 0] = 255;
        image.pixels[i * 4 + 2] = 255;
        image.pixels[i * 4 + 3] = 255;
    }
    return image;
}

void paint(Rgba8Image& image, int x, int y, uint8_t r, uint8_t g, uint8_t b) {
    uint8_t* p = &image.pixels[(size_t(y) * image.width + size_t(x)) * 4];
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

class CharacterCrack : public ::testing::TestWithParam<std::string> {};
class CharacterCrackWholeBody : public ::testing::TestWithParam<std::string> {};

} // namespace

// The detector on images made here: a grey disc with a notch open to the
// background (no hole), then with a closed one-pixel diagonal crack and a
// small round hole (holes), and a disc touching the border (no hole).
TEST(CharacterHoleDetector, FindsSyntheticHolesAndIgnoresTheSilhouette) {
    Rgba8Image image = magentaImage(64, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            if ((x - 30) * (x - 30) + (y - 24) * (y - 24) <= 18 * 18) paint(image, x, y, 128, 120, 100);
    // A wedge cut in from the right edge of the disc: background, not a hole.
    for (int x = 36; x <= 48; ++x)
        for (int y = 24 - (x - 36) / 3; y <= 24 + (x - 36) / 3; ++y) paint(image, x, y, 255, 0, 255);
    HoleReport clean = findHoles(image);
    EXPECT_EQ(clean.holePixels, 0u) << clean.describe();
    EXPECT_GT(clean.magenta, 0u);

    // A diagonal crack, one pixel wide, 8-connected only: the fill must not
    // leak through it; and a 2x2 hole elsewhere.
    for (int i = 0; i < 10; ++i) paint(image, 18 + i, 14 + i, 255, 0, 255);
    for (int y = 32; y < 34; ++y)
        for (int x = 24; x < 26; ++x) paint(image, x, y, 253, 3, 250); // rounding still reads as magenta
    HoleReport holes = findHoles(image);
    EXPECT_EQ(holes.holePixels, 14u) << holes.describe();
    ASSERT_EQ(holes.holes.size(), 2u) << holes.describe();
    EXPECT_EQ(holes.holes[0].pixels, 10u);
    EXPECT_EQ(holes.holes[0].minX, 18u);
    EXPECT_EQ(holes.holes[0].maxY, 23u);
    EXPECT_EQ(holes.holes[1].pixels, 4u);

    // A crack that reaches the silhouette is open background, as it should
    // be: the detector looks for enclosed holes only.
    Rgba8Image edge = magentaImage(16, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) paint(edge, x, y, 90, 90, 90);
    for (int y = 4; y < 12; ++y) paint(edge, 8, y, 255, 0, 255);
    EXPECT_EQ(findHoles(edge).holePixels, 8u);
    for (int y = 0; y < 4; ++y) paint(edge, 8, y, 255, 0, 255);
    EXPECT_EQ(findHoles(edge).holePixels, 0u);
}

TEST_P(CharacterCrack, NoHolesOnEitherPathAtAnyLevel) {
    const std::string backend = GetParam();
    if (!deviceRunsBackend(backend)) GTEST_SKIP() << "the device cannot run " << backend;
    const std::vector<std::string> levels = {"1", "3.7", "7.5", "14.99"};
    int runs = 0, failures = 0;
    for (const char* path : {"two-pass", "single-pass"})
        for (const std::string& level : levels) {
            SCOPED_TRACE(std::string(path) + " level " + level);
            ++runs;
            failures += !expectClosed(runCrack(backend, path, level));
        }
    EXPECT_EQ(failures, 0) << failures << " of " << runs << " runs failed on " << backend;
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, CharacterCrack,
                         ::testing::Values("hulldomain", "r2vb", "streamout", "meshshader"),
                         [](const auto& test) { return test.param; });

// The whole body, legs and feet included, on both paths at the emulated
// tessellator's top level. Seen whole, the creature may show up to one
// isolated pixel of background, two or three pixels inside the silhouette
// where a leg's crease meets it (frame 0: at (150, 195) on single-pass, on
// every backend; frame 119 shows another on both paths). It is not a crack:
// the cage is closed (every welded edge has both sides), the seams of the
// shipped map agree within 0.09 mm (0.5% of a pixel here;
// content test LoadedCreatureSeams), and without displacement the pixel is
// covered. With culling off, the pixel shows a back face about 5 cm behind
// its neighbours: displacing along normals that converge in a concave crease
// folds a few tessellated triangles over (rays cast from a concave cage cross
// before they reach the sculpt), the known limit of displacing an
// interpolated cage along its normals. A crack would be a line of pixels
// along a patch edge or seam: any hole of two or more pixels still fails.
TEST_P(CharacterCrackWholeBody, NoCracksOnEitherPath) {
    if (!deviceRunsBackend(GetParam())) GTEST_SKIP() << "the device cannot run " << GetParam();
    for (const char* path : {"two-pass", "single-pass"}) {
        SCOPED_TRACE(path);
        expectClosed(runCrack(GetParam(), path, "14.99", kWhole), HoleAllowance{2});
    }
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, CharacterCrackWholeBody,
                         ::testing::Values("hulldomain", "r2vb", "streamout", "meshshader"),
                         [](const auto& test) { return test.param; });

// Above the emulated range, where only hulldomain goes (its hardware
// tessellator reaches 64). Not on lavapipe (Mesa 22.3.6, and still 25.0.7:
// 1,814 hole pixels at level 20 on both paths, re-checked 2026-11-27): there, triangle
// patches with more than 16 segments per edge come out broken, with stray
// triangles and about 1,500 hole pixels from level 15.5 on (level 15 is
// closed), with or without displacement and on both paths, while the same
// build on an H100 draws levels 20 and 33 closed. The shaders have nothing
// that depends on the level, and the terrain's quad patches are closed there
// at 33.3, so this is the driver. (Level 20 also takes 14 s there, 33 over
// two minutes, 64 over seven.)
TEST(CharacterCrackHighLevel, HulldomainUpToLevel64) {
    if (defaultDeviceIsLavapipe())
        GTEST_SKIP() << "lavapipe breaks triangle patches above 16 segments; see the comment above this test";
    int failures = 0;
    for (const char* path : {"two-pass", "single-pass"})
        for (const char* level : {"20", "33", "64"}) {
            SCOPED_TRACE(std::string(path) + " level " + level);
            failures += !expectClosed(runCrack("hulldomain", path, level));
        }
    EXPECT_EQ(failures, 0);
}

// meshshader generates the patterns itself, so lavapipe's limit above does
// not apply: its levels above the emulated range are checked on every device.
// Above 14.99 the close view, like the whole body (CharacterCrackWholeBody),
// may show one isolated background pixel just inside the silhouette where
// the finer displacement folds a crease over (level 20: (193, 136), level 27:
// (112, 191); both covered with --no-displacement); a crack would be a line.
TEST(CharacterCrackHighLevel, MeshshaderUpToLevel64) {
    if (!deviceRunsBackend("meshshader")) GTEST_SKIP() << "the device cannot run meshshader";
    int failures = 0;
    failures += !expectClosed(runCrack("meshshader", "two-pass", "20"), HoleAllowance{1});
    failures += !expectClosed(runCrack("meshshader", "two-pass", "64"), HoleAllowance{1});
    failures += !expectClosed(runCrack("meshshader", "single-pass", "33"), HoleAllowance{1});
    EXPECT_EQ(failures, 0);
}

// The cage's own surface (interpolating planar subdivision, no displacement)
// is closed as well.
TEST(CharacterCrackUndisplaced, NoHolesWithoutDisplacement) {
    expectClosed(runCrack("hulldomain", "two-pass", "7.5", kClose, {"--no-displacement"}));
}
