// The Catmull-Clark character's tile file (.cctiles, CageTiles.h) and the
// seam welding that turns a character's triangle cage into a control mesh
// (TriangleCage.h): round trips, every truncation, corruptions and cages
// that do not match, each a one-line error naming the file.

#include "tessera/subdiv/CageTiles.h"
#include "tessera/subdiv/PtexTopology.h"
#include "tessera/subdiv/SubdivSurface.h"
#include "tessera/subdiv/TriangleCage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::subdiv;

namespace {

// An octahedron whose every vertex is split once more per triangle corner
// (a cage with a UV seam everywhere): 24 cage vertices, 6 control vertices.
struct SplitOctahedron {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    SplitOctahedron() {
        const glm::vec3 p[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        const uint32_t f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                  {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
        for (const auto& tri : f)
            for (uint32_t k : tri) {
                indices.push_back(uint32_t(positions.size()));
                // -0.0 on one copy: welding must not tell it from +0.0.
                positions.push_back(positions.size() % 2 ? p[k] * glm::vec3(1.0f) : p[k] + glm::vec3(-0.0f));
            }
    }
};

CageTiles sampleTiles(const WeldedCage& cage, uint32_t tileCount) {
    std::vector<uint8_t> sizes(tileCount, 2);
    std::vector<float> coefficients(tileCount * 16);
    for (size_t i = 0; i < coefficients.size(); ++i) coefficients[i] = 0.01f * float(int(i % 37) - 18);
    CageTiles tiles = quantizeCageTiles(sizes, coefficients);
    tiles.cageVertices = 24;
    tiles.cageTriangles = cage.shape.faceCount();
    tiles.controlVertices = uint32_t(cage.shape.positions.size());
    tiles.topologyHash = cage.topologyHash;
    return tiles;
}

WeldedCage weldOk() {
    const SplitOctahedron o;
    Result<WeldedCage> cage = weldTriangleCage(o.positions, o.indices, "octahedron");
    EXPECT_TRUE(cage.ok()) << (cage.ok() ? "" : cage.error().message);
    return std::move(cage).value();
}

} // namespace

TEST(TriangleCage, WeldsSeamCopiesIntoACatmullClarkControlMesh) {
    const WeldedCage cage = weldOk();
    EXPECT_EQ(cage.shape.positions.size(), 6u);
    EXPECT_EQ(cage.shape.faceCount(), 8u);
    EXPECT_EQ(cage.controlOf.size(), 24u);
    for (uint32_t c = 0; c < 6; ++c) EXPECT_EQ(cage.controlOf[cage.firstCageVertex[c]], c);
    Result<SubdivSurface> surface = SubdivSurface::create(cage.shape);
    ASSERT_TRUE(surface.ok()) << surface.error().message;
    EXPECT_EQ(surface->ptexFaceCount(), 24u); // three quad sub-faces a triangle
    Result<PtexTopology> topology = PtexTopology::create(cage.shape);
    ASSERT_TRUE(topology.ok()) << topology.error().message;
    EXPECT_EQ(topology->tileCount(), 24u);
    // The same cage welds the same way: the hash is the tile file's key.
    EXPECT_EQ(weldOk().topologyHash, cage.topologyHash);
}

TEST(TriangleCage, RefusesBadCagesNamingThem) {
    SplitOctahedron o;
    auto expectError = [](const Result<WeldedCage>& r, const std::string& part) {
        ASSERT_FALSE(r.ok());
        EXPECT_NE(r.error().message.find("octahedron"), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find(part), std::string::npos) << r.error().message;
    };
    expectError(weldTriangleCage(o.positions, {}, "octahedron"), "no triangles");
    std::vector<uint32_t> partial(o.indices.begin(), o.indices.end() - 1);
    expectError(weldTriangleCage(o.positions, partial, "octahedron"), "not a multiple of 3");
    std::vector<uint32_t> outOfRange = o.indices;
    outOfRange[5] = 99;
    expectError(weldTriangleCage(o.positions, outOfRange, "octahedron"), "names vertex 99");
    std::vector<glm::vec3> collapsed = o.positions;
    collapsed[1] = collapsed[0]; // triangle 0's first two corners weld
    expectError(weldTriangleCage(collapsed, o.indices, "octahedron"), "degenerate");
    std::vector<glm::vec3> nan = o.positions;
    nan[3].y = std::nanf("");
    expectError(weldTriangleCage(nan, o.indices, "octahedron"), "non-finite");
}

TEST(CageTiles, RoundTripsAndQuantizesTo16Bits) {
    const WeldedCage cage = weldOk();
    const CageTiles tiles = sampleTiles(cage, 24);
    const std::vector<uint8_t> bytes = encodeCageTiles(tiles);
    EXPECT_EQ(bytes.size(), 44u + 24u + 2u * 24u * 16u + 8u);
    Result<CageTiles> back = decodeCageTiles(bytes, "x.cctiles");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->quantized, tiles.quantized);
    EXPECT_EQ(back->log2Sizes, tiles.log2Sizes);
    EXPECT_EQ(back->topologyHash, cage.topologyHash);
    const std::vector<float> c = back->coefficients();
    EXPECT_NEAR(c.front(), 0.01f * (0 - 18), 0.36f / 65535.0f);
    EXPECT_TRUE(checkCageTiles(*back, cage, 24, 24, "x.cctiles").ok());
    EXPECT_EQ(encodeCageTiles(*back), bytes);
}

TEST(CageTiles, EveryTruncationIsAnErrorNamingTheFile) {
    const std::vector<uint8_t> bytes = encodeCageTiles(sampleTiles(weldOk(), 24));
    for (size_t n = 0; n < bytes.size(); ++n) {
        Result<CageTiles> r = decodeCageTiles(std::span(bytes).first(n), "cut.cctiles");
        ASSERT_FALSE(r.ok()) << n;
        EXPECT_EQ(r.error().message.rfind("cut.cctiles: ", 0), 0u) << r.error().message;
        if (n > 0) {
            EXPECT_NE(r.error().message.find("truncated"), std::string::npos) << n << ": " << r.error().message;
        }
    }
}

TEST(CageTiles, CorruptionsAreErrorsNamingTheProblem) {
    const std::vector<uint8_t> good = encodeCageTiles(sampleTiles(weldOk(), 24));
    auto expectError = [](std::vector<uint8_t> bytes, const std::string& part) {
        Result<CageTiles> r = decodeCageTiles(bytes, "bad.cctiles");
        ASSERT_FALSE(r.ok()) << part;
        EXPECT_EQ(r.error().message.rfind("bad.cctiles: ", 0), 0u) << r.error().message;
        EXPECT_NE(r.error().message.find(part), std::string::npos) << r.error().message;
    };
    std::vector<uint8_t> b = good;
    b[0] = 'X';
    expectError(b, "no TSCCTILE magic");
    b = good;
    b[8] = 2;
    expectError(b, "version 2, this build reads version 1");
    b = good;
    b[32] = b[33] = b[34] = b[35] = 0;
    expectError(b, "no tiles");
    b = good;
    b[44 + 5] = 13;
    expectError(b, "tile 5 has log2 size 13");
    b = good;
    b[44 + 5] = 3; // a larger tile: the coefficients no longer fit
    expectError(b, "truncated");
    b = good;
    b.push_back(0);
    expectError(b, "1 bytes after the end");
    const float inf = INFINITY;
    b = good;
    std::memcpy(&b[36], &inf, 4);
    expectError(b, "bad coefficient range");
    // Any flipped bit past the header's checked fields: the checksum.
    for (size_t at : {size_t(12), size_t(24), size_t(44 + 24), good.size() / 2, good.size() - 9, good.size() - 1}) {
        b = good;
        b[at] ^= 0x10;
        expectError(b, "checksum mismatch");
    }
}

TEST(CageTiles, FilesThatDoNotMatchTheCageAreRefused) {
    const WeldedCage cage = weldOk();
    const CageTiles good = sampleTiles(cage, 24);
    auto expectMismatch = [&](CageTiles tiles, uint32_t cageVertices, uint32_t tileCount, const std::string& part) {
        Status s = checkCageTiles(tiles, cage, cageVertices, tileCount, "f.cctiles");
        ASSERT_FALSE(s.ok()) << part;
        EXPECT_NE(s.error().message.find("f.cctiles: baked for another cage: " + part), std::string::npos)
            << s.error().message;
    };
    expectMismatch(good, 25, 24, "cage vertices 24 in the file, 25 in the model");
    CageTiles t = good;
    t.cageTriangles = 9;
    expectMismatch(t, 24, 24, "cage triangles 9");
    t = good;
    t.controlVertices = 7;
    expectMismatch(t, 24, 24, "control vertices 7");
    t = good;
    t.topologyHash ^= 1;
    expectMismatch(t, 24, 24, "topology hash");
    expectMismatch(good, 24, 30, "tiles 24 in the file, 30");
}

TEST(CageTiles, FilesOnDisk) {
    const std::filesystem::path dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "cage_tiles";
    std::filesystem::create_directories(dir);
    const CageTiles tiles = sampleTiles(weldOk(), 24);
    ASSERT_TRUE(writeCageTiles(dir / "ok.cctiles", tiles).ok());
    Result<CageTiles> back = readCageTiles(dir / "ok.cctiles");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->quantized, tiles.quantized);
    Result<CageTiles> missing = readCageTiles(dir / "missing.cctiles");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("missing.cctiles: cannot open"), std::string::npos)
        << missing.error().message;
    std::vector<uint8_t> bytes = encodeCageTiles(tiles);
    bytes.resize(bytes.size() / 2);
    std::ofstream(dir / "half.cctiles", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    Result<CageTiles> half = readCageTiles(dir / "half.cctiles");
    ASSERT_FALSE(half.ok());
    EXPECT_NE(half.error().message.find("half.cctiles: truncated"), std::string::npos) << half.error().message;
}
