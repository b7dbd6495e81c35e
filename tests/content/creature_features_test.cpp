// The close-up features (issue 16): eyes, a mouth with teeth, and leather
// gear show in the base colour, and vary across the crowd.

#include "creature/CreatureGenerator.h"
#include "creature/CreatureParams.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>

using namespace tessera;
using namespace tessera::creature;

namespace {

// The default 5K cage (the features need its resolution), a small sculpt
// and a 512 texture: the eyes are a few texels across there.
const Creature& closeUpCreature() {
    static const Creature creature = [] {
        CreatureOptions o;
        o.seed = 1;
        o.sculptTriangles = 80'000;
        o.baseColorSize = 512;
        return generateCreature(o);
    }();
    return creature;
}

struct Counts {
    size_t bright = 0;   // sclera, teeth, stitching: paler than any skin
    size_t black = 0;    // pupils and the mouth's inside
    size_t leather = 0;  // red-brown, where the skin is green
};

Counts countColours(const character::TextureImage& image) {
    Counts n;
    for (size_t i = 0; i + 3 < image.bytes.size(); i += 4) {
        int r = image.bytes[i], g = image.bytes[i + 1], b = image.bytes[i + 2];
        if (r > 185 && g > 170 && b > 105) ++n.bright;
        if (r < 50 && g < 50 && b < 50) ++n.black;
        if (r * 10 > g * 14 && r * 10 > b * 18 && r > 50) ++n.leather;
    }
    return n;
}

} // namespace

TEST(CreatureFeatures, BaseColourHasEyesMouthAndLeather) {
    const Creature& c = closeUpCreature();
    ASSERT_TRUE(c.asset.baseColor.has_value());
    Counts n = countColours(*c.asset.baseColor);
    const size_t texels = size_t(c.asset.baseColor->width) * c.asset.baseColor->height;
    std::printf("bright %zu, black %zu, leather %zu of %zu texels\n", n.bright, n.black, n.leather, texels);
    // The old skin-only palette had none of the first two and no red-brown.
    EXPECT_GT(n.bright, 20u) << "no sclera, teeth or stitching";
    EXPECT_GT(n.black, 5u) << "no pupils or mouth";
    EXPECT_GT(n.leather, texels / 200) << "no leather gear";
}

TEST(CreatureFeatures, GearAndFaceVaryAcrossTheCrowd) {
    std::set<bool> straps, bracers;
    std::set<uint32_t> teeth;
    for (uint32_t seed = 1; seed <= 12; ++seed) {
        CreatureParams p = makeCreatureParams(seed);
        straps.insert(p.chestStrap);
        bracers.insert(p.bracers);
        teeth.insert(p.toothCount);
        EXPECT_GE(p.toothCount, 4u);
        EXPECT_LE(p.toothCount, 6u);
        EXPECT_GT(p.eyeRadius, 0.02f);
        EXPECT_LT(p.eyeRadius, 0.027f);
    }
    EXPECT_EQ(straps.size(), 2u);
    EXPECT_EQ(bracers.size(), 2u);
    EXPECT_GT(teeth.size(), 1u);
    // The docs' close-up creature wears everything; the crowd's other two
    // seeds wear one piece each.
    EXPECT_TRUE(makeCreatureParams(1).chestStrap && makeCreatureParams(1).bracers);
    EXPECT_TRUE(makeCreatureParams(2).chestStrap && !makeCreatureParams(2).bracers);
    EXPECT_TRUE(!makeCreatureParams(3).chestStrap && makeCreatureParams(3).bracers);
}
