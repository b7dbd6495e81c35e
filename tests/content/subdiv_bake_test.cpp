// The generated creature as a Catmull-Clark surface (creature/SubdivBaker.h):
// the bake is deterministic for any thread count, its file is what the demo
// reads back for the same cage, and the displaced limit surface lands on the
// sculpt about as closely as the planar bake does (a small creature: 1K cage,
// 50K-triangle sculpt, 256^2 planar map).

#include "creature/CreatureGenerator.h"
#include "creature/DisplacementBaker.h"
#include "creature/SubdivBaker.h"
#include "tessera/subdiv/CageTiles.h"
#include "tessera/subdiv/PtexTopology.h"
#include "tessera/subdiv/TriangleCage.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace tessera;
using namespace tessera::creature;

namespace {

struct SmallCreature {
    Creature creature;
    uint64_t planarTexels = 0;
};

const SmallCreature& smallCreature() {
    static const SmallCreature c = [] {
        CreatureOptions o;
        o.seed = 2;
        o.sculptTriangles = 50'000;
        o.cageTriangles = 1'000;
        o.baseColorSize = 64;
        SmallCreature s{generateCreature(o)};
        BakeOptions bake;
        bake.resolution = 256;
        bake.threads = 2;
        Result<BakeResult> planar = bakeDisplacement(s.creature.asset.cage, s.creature.sculpt, bake);
        EXPECT_TRUE(planar.ok());
        s.creature.asset.displacement = planar->displacement;
        s.planarTexels = planar->stats.texelsCovered;
        return s;
    }();
    return c;
}

SubdivBakeResult bakeOk(uint32_t threads) {
    const SmallCreature& c = smallCreature();
    SubdivBakeOptions options;
    options.threads = threads;
    options.log2Size = 2;
    Result<SubdivBakeResult> r = bakeSubdivDisplacement(c.creature.asset, c.creature.sculpt, options, "small.glb");
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    return r.ok() ? std::move(r).value() : SubdivBakeResult{};
}

} // namespace

TEST(SubdivBake, SameBytesForAnyThreadCount) {
    const SubdivBakeResult one = bakeOk(1), two = bakeOk(2);
    EXPECT_EQ(subdiv::encodeCageTiles(one.file), subdiv::encodeCageTiles(two.file));
    EXPECT_EQ(one.stats.subdiv.rms, two.stats.subdiv.rms);
    EXPECT_EQ(one.stats.planar.max, two.stats.planar.max);
}

TEST(SubdivBake, FileMatchesTheWeldedCage) {
    const SubdivBakeResult r = bakeOk(2);
    const auto& cage = smallCreature().creature.asset.cage;
    std::vector<glm::vec3> positions;
    for (const auto& v : cage.vertices) positions.push_back(v.position);
    Result<subdiv::WeldedCage> welded = subdiv::weldTriangleCage(positions, cage.indices, "small.glb");
    ASSERT_TRUE(welded.ok()) << welded.error().message;
    Result<subdiv::PtexTopology> topology = subdiv::PtexTopology::create(welded->shape);
    ASSERT_TRUE(topology.ok()) << topology.error().message;
    EXPECT_EQ(topology->tileCount(), 3 * cage.triangleCount());
    const std::vector<uint8_t> bytes = subdiv::encodeCageTiles(r.file);
    Result<subdiv::CageTiles> back = subdiv::decodeCageTiles(bytes, "small.cctiles");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(subdiv::checkCageTiles(*back, *welded, uint32_t(positions.size()), topology->tileCount(), "small.cctiles").ok());
    EXPECT_EQ(r.stats.fileBytes, bytes.size());
    EXPECT_EQ(r.stats.coefficients, uint64_t(16) * topology->tileCount());
}

TEST(SubdivBake, DisplacedSurfaceLandsOnTheSculptLikeThePlanarBake) {
    const SubdivBakeStats s = bakeOk(2).stats;
    std::printf("[ subdiv bake ] %u ptex faces, %llu coefficients, %llu misses (%llu filled, %llu zero), %u rounds\n"
                "[ subdiv bake ] error rms / max (m): displaced %.6f / %.6f, undisplaced %.6f / %.6f, "
                "planar %.6f / %.6f\n",
                s.ptexFaces, static_cast<unsigned long long>(s.coefficients), static_cast<unsigned long long>(s.misses),
                static_cast<unsigned long long>(s.missesFromNeighbours), static_cast<unsigned long long>(s.missesZero),
                s.conversionRounds, s.subdiv.rms, s.subdiv.max, s.subdivBase.rms, s.subdivBase.max, s.planar.rms,
                s.planar.max);
    EXPECT_TRUE(s.converged);
    EXPECT_EQ(s.misses, s.missesFromNeighbours + s.missesZero);
    EXPECT_LT(s.misses, s.coefficients / 100);
    EXPECT_GT(s.subdiv.samples, 0u);
    EXPECT_LT(s.subdiv.unmeasured, s.subdiv.samples / 100);
    // The displacement does its job: far closer than the bare limit surface,
    EXPECT_LT(s.subdiv.rms, 0.5 * s.subdivBase.rms);
    // and within a small factor of the planar bake at a similar density.
    EXPECT_GT(s.planar.samples, 0u);
    EXPECT_LT(s.subdiv.rms, 2.0 * s.planar.rms);
}

TEST(SubdivBake, RefusesBadInputNamingIt) {
    const SmallCreature& c = smallCreature();
    SubdivBakeOptions options;
    Result<SubdivBakeResult> empty = bakeSubdivDisplacement(c.creature.asset, SculptMesh{}, options, "small.glb");
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().message, "small.glb: the sculpt is empty");
    options.log2Size = 9;
    Result<SubdivBakeResult> big = bakeSubdivDisplacement(c.creature.asset, c.creature.sculpt, options, "small.glb");
    ASSERT_FALSE(big.ok());
    EXPECT_NE(big.error().message.find("tile log2 size 9"), std::string::npos) << big.error().message;
    character::CharacterAsset broken = c.creature.asset;
    broken.cage.indices[4] = 1u << 30;
    options.log2Size = 2;
    Result<SubdivBakeResult> bad = bakeSubdivDisplacement(broken, c.creature.sculpt, options, "small.glb");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("small.glb: cage triangle 1 names vertex"), std::string::npos)
        << bad.error().message;
}
