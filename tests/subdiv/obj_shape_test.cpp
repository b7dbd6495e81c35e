// The .obj reader on OpenSubdiv's regression shapes (every file, its counts
// checked against an independent count of its lines, its tags as written)
// and on inline text for the index forms and the tag forms.
#include "ObjShapeTestFiles.h"

#include "tessera/subdiv/ObjShape.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <numeric>

using namespace tessera;
using namespace tessera::subdiv;
using tessera::test::countObjLines;
using tessera::test::ObjLineCounts;

namespace {

ObjShape loadShape(const std::string& file) {
    Result<ObjShape> shape = readObjShape(test::osdShapesDir() / file);
    EXPECT_TRUE(shape.ok()) << (shape.ok() ? "" : shape.error().message);
    return shape.ok() ? std::move(shape).value() : ObjShape{};
}

Result<ObjShape> parse(const std::string& text) {
    return parseObjShape(text, "inline.obj");
}

const char* kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                      "vn 0 0 1\n";

} // namespace

TEST(ObjShape, EveryRegressionShapeLoadsWithTheCountsOfItsLines) {
    const std::vector<std::filesystem::path> files = test::osdShapeFiles();
    ASSERT_EQ(files.size(), 12u) << "osd_shapes holds 12 .obj files (and the license)";
    for (const std::filesystem::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        const ObjLineCounts counts = countObjLines(test::readObjText(file));
        Result<ObjShape> loaded = readObjShape(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        const ObjShape& shape = loaded.value();
        EXPECT_EQ(shape.name, file.string());
        EXPECT_EQ(shape.positions.size(), counts.vertices);
        EXPECT_EQ(shape.uvs.size(), counts.uvs);
        EXPECT_EQ(shape.faceCount(), counts.faces);
        EXPECT_EQ(shape.faceVertices.size(), counts.faceCorners);
        EXPECT_EQ(std::accumulate(shape.faceSizes.begin(), shape.faceSizes.end(), size_t(0)), counts.faceCorners);
        std::map<size_t, size_t> sizes;
        for (uint32_t size : shape.faceSizes) ++sizes[size];
        EXPECT_EQ(sizes, counts.faceSizes);
        // Every face of every shape carries uvs.
        EXPECT_EQ(counts.facesWithUvs, counts.faces);
        EXPECT_EQ(shape.faceUvs.size(), shape.faceVertices.size());
        for (uint32_t v : shape.faceVertices) EXPECT_LT(v, shape.positions.size());
        for (uint32_t t : shape.faceUvs) EXPECT_LT(t, shape.uvs.size());
        EXPECT_EQ(shape.creases.size(), counts.creaseEdges);
        EXPECT_EQ(shape.corners.size(), counts.corners);
        EXPECT_EQ(shape.holes, counts.holes);
        EXPECT_EQ(int(shape.boundary), counts.interpolateBoundary.value_or(int(BoundaryInterpolation::EdgeAndCorner)));
        std::printf("%-28s %4zu v %4zu vt %3u f (sizes", file.filename().string().c_str(), shape.positions.size(),
                    shape.uvs.size(), shape.faceCount());
        for (const auto& [size, faces] : sizes) std::printf(" %zux%zu", faces, size);
        std::printf(") %zu creases %zu corners %zu holes boundary %d smoothtriangles %d\n", shape.creases.size(),
                    shape.corners.size(), shape.holes.size(), int(shape.boundary), int(shape.smoothTriangles));
    }
}

TEST(ObjShape, ReadsTheFirstCubeExactly) {
    const ObjShape cube = loadShape("catmark_cube.obj");
    ASSERT_EQ(cube.positions.size(), 8u);
    EXPECT_EQ(cube.positions[0], glm::vec3(0.0f, -1.414214f, 1.0f)); // v 0.000000 -1.414214 1.000000
    EXPECT_EQ(cube.uvs[0], glm::vec2(0.375f, 0.0f));
    // f 1/1/1 2/2/2 4/4/3 3/3/4: 0-based.
    EXPECT_EQ(std::vector<uint32_t>(cube.faceVertices.begin(), cube.faceVertices.begin() + 4),
              (std::vector<uint32_t>{0, 1, 3, 2}));
    EXPECT_TRUE(cube.creases.empty() && cube.corners.empty() && cube.holes.empty());
    EXPECT_EQ(cube.boundary, BoundaryInterpolation::EdgeAndCorner);
    EXPECT_FALSE(cube.smoothTriangles);
}

TEST(ObjShape, HoleCornerCreaseAndBoundaryTagsOfTheShapes) {
    EXPECT_EQ(loadShape("catmark_hole_test1.obj").holes, (std::vector<uint32_t>{1}));

    const ObjShape corner = loadShape("catmark_cube_corner4.obj");
    ASSERT_EQ(corner.corners.size(), 1u); // t corner 1/1/0 0 10.0
    EXPECT_EQ(corner.corners[0].vertex, 0u);
    EXPECT_EQ(corner.corners[0].sharpness, 10.0f);

    const ObjShape crease = loadShape("catmark_single_crease.obj");
    ASSERT_EQ(crease.creases.size(), 36u);
    // The first tag line: t crease 2/1/0 1 22 10.000000; the last: 80 101 0.200000.
    EXPECT_EQ(crease.creases.front().v0, 1u);
    EXPECT_EQ(crease.creases.front().v1, 22u);
    EXPECT_EQ(crease.creases.front().sharpness, 10.0f);
    EXPECT_EQ(crease.creases.back().v0, 80u);
    EXPECT_EQ(crease.creases.back().v1, 101u);
    EXPECT_FLOAT_EQ(crease.creases.back().sharpness, 0.2f);

    const ObjShape creases1 = loadShape("catmark_cube_creases1.obj");
    EXPECT_EQ(creases1.creases.size(), 12u);
    EXPECT_EQ(creases1.boundary, BoundaryInterpolation::EdgeAndCorner); // t interpolateboundary 1/0/0 2
    EXPECT_EQ(loadShape("catmark_edgecorner.obj").boundary, BoundaryInterpolation::EdgeOnly);
}

TEST(ObjShape, SmoothTrianglesTagAsOpenSubdivReadsIt) {
    // catmark_smoothtris0 says `t smoothtriangles 0/0/1 catmark`: OpenSubdiv's
    // regression reader sets TRI_SUB_CATMARK for it (smoothtris1 would say
    // `smooth`), so the tag is read but the flag stays off.
    const std::string text = test::readObjText(test::osdShapesDir() / "catmark_smoothtris0.obj");
    ASSERT_EQ(countObjLines(text).smoothTriangles, (std::vector<std::string>{"catmark"}));
    const ObjShape tris = loadShape("catmark_smoothtris0.obj");
    EXPECT_EQ(tris.faceCount(), 80u);
    EXPECT_FALSE(tris.smoothTriangles);
    // Its `smooth` twin, OpenSubdiv's Hbr int form, and the bare tag.
    const std::string smooth = text.substr(0, text.find("t smoothtriangles")) + "t smoothtriangles 0/0/1 smooth\n";
    EXPECT_TRUE(parse(smooth)->smoothTriangles);
    const std::string tri = std::string(kSquare) + "f 1 2 3\n";
    EXPECT_TRUE(parse(tri + "t smoothtriangles 1/0/0 1\n")->smoothTriangles);
    EXPECT_FALSE(parse(tri + "t smoothtriangles 1/0/0 0\n")->smoothTriangles);
    EXPECT_TRUE(parse(tri + "t smoothtriangles 0/0/0\n")->smoothTriangles);
}

TEST(ObjShape, NonQuadsKeepTheirSizesInOrder) {
    const ObjShape shape = loadShape("catmark_nonquads.obj");
    ASSERT_EQ(shape.faceCount(), 17u);
    std::map<uint32_t, size_t> sizes;
    for (uint32_t size : shape.faceSizes) ++sizes[size];
    EXPECT_EQ(sizes, (std::map<uint32_t, size_t>{{3, 7}, {4, 7}, {5, 1}, {6, 2}}));
    EXPECT_EQ(shape.boundary, BoundaryInterpolation::EdgeOnly);
}

TEST(ObjShape, EveryIndexForm) {
    const std::string forms[] = {"f 1 2 3 4\n", "f 1/1 2/2 3/3 4/4\n", "f 1//1 2//1 3//1 4//1\n",
                                 "f 1/1/1 2/2/1 3/3/1 4/4/1\n"};
    for (const std::string& face : forms) {
        SCOPED_TRACE(face);
        Result<ObjShape> shape = parse(std::string(kSquare) + face);
        ASSERT_TRUE(shape.ok()) << shape.error().message;
        EXPECT_EQ(shape->faceVertices, (std::vector<uint32_t>{0, 1, 2, 3}));
        const bool uvs = face.find("//") == std::string::npos && face.find('/') != std::string::npos;
        EXPECT_EQ(shape->faceUvs, (uvs ? std::vector<uint32_t>{0, 1, 2, 3} : std::vector<uint32_t>()));
    }
}

TEST(ObjShape, NegativeIndicesCountBackFromTheLastElementSoFar) {
    // -4 .. -1 are the four vertices (and uvs) read so far; the second face
    // comes after two more vertices, so its -1 is the sixth.
    const std::string text = std::string(kSquare) + "f -4/-4 -3/-3 -2/-2 -1/-1\n" + "v 2 0 0\nv 2 1 0\nvt 0 0\n" +
                             "f 2/-1 -2/-1 -1/-1 3/-1\n";
    Result<ObjShape> shape = parse(text);
    ASSERT_TRUE(shape.ok()) << shape.error().message;
    EXPECT_EQ(shape->faceVertices, (std::vector<uint32_t>{0, 1, 2, 3, 1, 4, 5, 2}));
    EXPECT_EQ(shape->faceUvs, (std::vector<uint32_t>{0, 1, 2, 3, 4, 4, 4, 4}));
}

TEST(ObjShape, LiberalAboutWhitespaceCommentsAndOtherStatements) {
    const std::string text = "# a comment\r\nmtllib x.mtl\r\no square\r\ng group\r\ns 1\r\nusemtl red\r\n"
                             "v\t0 0 0 1\r\nv +1 0 0   # w omitted\r\nv 1 1 0 0.5 0.5 0.5\r\nv 0 1.0e0 -0\r\n"
                             "vt 0.5\r\nvp 0 0\r\nl 1 2\r\n  f   1 2 3 4  \r\n"
                             "t creasemethod 0/0/1 chaikin\r\nt vertexedit 2/1/1 1 2 0.5 add\r\n"
                             "t crease 4/1/0 0 1 1 2 3.5\r\nt corner 2/2/0 0 2 1 -2\r\nt hole 1/0/0 0\r\n"
                             "t interpolateboundary 1/0/0 0";
    Result<ObjShape> shape = parse(text);
    ASSERT_TRUE(shape.ok()) << shape.error().message;
    EXPECT_EQ(shape->positions.size(), 4u);
    EXPECT_EQ(shape->positions[1], glm::vec3(1, 0, 0));
    ASSERT_EQ(shape->uvs.size(), 1u);
    EXPECT_EQ(shape->uvs[0], glm::vec2(0.5f, 0.0f));
    EXPECT_EQ(shape->faceCount(), 1u);
    ASSERT_EQ(shape->creases.size(), 2u);
    EXPECT_EQ(shape->creases[1].v0, 1u);
    EXPECT_EQ(shape->creases[1].v1, 2u);
    EXPECT_EQ(shape->creases[1].sharpness, 3.5f);
    ASSERT_EQ(shape->corners.size(), 2u);
    EXPECT_EQ(shape->corners[1].vertex, 2u);
    EXPECT_EQ(shape->corners[1].sharpness, 0.0f) << "a negative sharpness is clamped to 0, as OpenSubdiv does";
    EXPECT_EQ(shape->holes, (std::vector<uint32_t>{0}));
    EXPECT_EQ(shape->boundary, BoundaryInterpolation::None);
}

TEST(ObjShape, TwoFacesMeetOnAnEdgeWalkedBothWays) {
    // A closed, consistently wound tetrahedron: every edge has two faces.
    Result<ObjShape> shape = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"
                                   "t crease 2/1/0 3 0 10");
    ASSERT_TRUE(shape.ok()) << shape.error().message;
    EXPECT_EQ(shape->faceCount(), 4u);
    EXPECT_EQ(shape->creases.size(), 1u);
}
