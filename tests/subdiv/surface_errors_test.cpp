// SubdivSurface::create's errors: one line naming the shape and the
// problem, for input OpenSubdiv would trust blindly (checked first) and for
// topology OpenSubdiv itself rejects (its message passed on); never a
// crash. Topology OpenSubdiv accepts (non-manifold, degenerate, mis-wound
// faces) builds a surface that evaluates to finite points.
#include "SubdivTestSupport.h"

#include <cmath>

namespace tessera::subdiv::test {
namespace {

std::string errorOf(const ObjShape& shape, const SubdivSettings& settings = {}) {
    Result<SubdivSurface> surface = SubdivSurface::create(shape, settings);
    EXPECT_FALSE(surface.ok()) << shape.name;
    return surface.ok() ? std::string() : surface.error().message;
}

ObjShape named(ObjShape shape, const std::string& name) {
    shape.name = name;
    return shape;
}

TEST(SubdivSurfaceErrors, InputOpenSubdivWouldTrust) {
    ObjShape s = named(cube(), "two.obj");
    addFace(s, {0, 1});
    EXPECT_EQ(errorOf(s), "two.obj: face 6 has 2 vertices (a face needs at least 3)");

    s = named(cube(), "big.obj");
    s.faceSizes.push_back(65);
    for (uint32_t i = 0; i < 65; ++i) s.faceVertices.push_back(i % 8);
    EXPECT_EQ(errorOf(s), "big.obj: face 6 has 65 vertices, more than 64");

    s = named(cube(), "range.obj");
    s.faceVertices[5] = 8;
    EXPECT_EQ(errorOf(s), "range.obj: face 1 uses vertex 8 but the shape has 8 vertices");

    s = named(cube(), "counts.obj");
    s.faceVertices.pop_back();
    EXPECT_EQ(errorOf(s), "counts.obj: the face sizes add up to 24 vertices but 23 face vertices are given");

    s = named(cube(), "nan.obj");
    s.positions[2].z = std::numeric_limits<float>::infinity();
    EXPECT_EQ(errorOf(s), "nan.obj: vertex 2 has a non-finite position");

    s = named(cube(), "crease.obj");
    s.creases = {{0, 1, 1.0f}, {3, 9, 1.0f}};
    EXPECT_EQ(errorOf(s), "crease.obj: crease 1 names vertex 9 but the shape has 8 vertices");
    s.creases = {{0, 1, -1.0f}};
    EXPECT_EQ(errorOf(s), "crease.obj: crease 0 has a negative or non-finite sharpness");

    s = named(cube(), "corner.obj");
    s.corners = {{8, 1.0f}};
    EXPECT_EQ(errorOf(s), "corner.obj: corner 0 names vertex 8 but the shape has 8 vertices");
    s.corners = {{1, std::nanf("")}};
    EXPECT_EQ(errorOf(s), "corner.obj: corner 0 has a negative or non-finite sharpness");

    s = named(cube(), "hole.obj");
    s.holes = {6};
    EXPECT_EQ(errorOf(s), "hole.obj: a hole names face 6 but the shape has 6 faces");
}

TEST(SubdivSurfaceErrors, SettingsOutOfRange) {
    EXPECT_EQ(errorOf(cube(), {0, 0}), "cube: isolation level 0 is outside 1 .. 10");
    EXPECT_EQ(errorOf(cube(), {11, 2}), "cube: isolation level 11 is outside 1 .. 10");
    EXPECT_EQ(errorOf(cube(), {2, 3}), "cube: smooth isolation level 3 is outside 1 .. 2 (the isolation level)");
}

TEST(SubdivSurfaceErrors, TopologyOpenSubdivRejects) {
    ObjShape empty;
    empty.name = "empty.obj";
    EXPECT_EQ(errorOf(empty), "empty.obj: OpenSubdiv cannot build the topology: Failure in "
                              "TopologyRefinerFactory<>::Create() -- mesh contains no vertices.");
    ObjShape points = named(ObjShape{}, "points.obj");
    points.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(errorOf(points), "points.obj: OpenSubdiv cannot build the topology: Failure in "
                               "TopologyRefinerFactory<>::Create() -- meshes without faces not yet supported.");
    // A crease on an edge that does not exist (a face diagonal): OpenSubdiv
    // only warns and drops it; here it is an error.
    ObjShape diagonal = named(cube(), "diagonal.obj");
    diagonal.creases = {{0, 6, 2.0f}};
    EXPECT_EQ(errorOf(diagonal),
              "diagonal.obj: OpenSubdiv cannot build the topology: Edge 0 specified to be sharp does not exist (0, 6)");
    // A vertex shared by 65536 faces, one more than OpenSubdiv's valence limit.
    ObjShape fan = named(ObjShape{}, "fan.obj");
    const uint32_t n = 65536;
    fan.positions.push_back({0, 0, 0});
    for (uint32_t i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        fan.positions.push_back({float(std::cos(a)), float(std::sin(a)), 0.0f});
    }
    for (uint32_t i = 0; i < n; ++i) addFace(fan, {0, 1 + i, 1 + (i + 1) % n});
    EXPECT_EQ(errorOf(fan), "fan.obj: OpenSubdiv cannot build the topology: Failure in "
                            "TopologyRefinerFactory<>::Create() -- vertex with valence 65536 > 65535 max.");
}

void expectFinitePatches(const ObjShape& shape) {
    Result<SubdivSurface> surface = SubdivSurface::create(shape);
    ASSERT_TRUE(surface.ok()) << surface.error().message;
    ASSERT_FALSE(surface->patches().empty()) << shape.name;
    for (uint32_t p = 0; p < surface->patches().size(); ++p)
        for (glm::dvec2 st : {glm::dvec2(0, 0), glm::dvec2(0.5, 0.5), glm::dvec2(1, 1)}) {
            const LimitPoint x = surface->evaluatePatch(p, st);
            ASSERT_TRUE(std::isfinite(x.position.x + x.position.y + x.position.z + x.du.x + x.dv.y))
                << shape.name << ": patch " << p;
        }
}

TEST(SubdivSurfaceErrors, TopologyOpenSubdivAcceptsBuildsFinitePatches) {
    ObjShape fin = named(cube(), "fin.obj"); // two triangles hanging off one cube edge
    fin.positions.push_back({0, 0, 3});
    addFace(fin, {4, 5, 8});
    addFace(fin, {5, 4, 8});
    expectFinitePatches(fin);
    ObjShape book = named(ObjShape{}, "book.obj"); // an edge shared by three faces
    book.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    addFace(book, {0, 1, 2});
    addFace(book, {1, 0, 3});
    addFace(book, {0, 1, 4});
    expectFinitePatches(book);
    ObjShape degenerate = named(cube(), "degenerate.obj"); // a face using a vertex twice
    addFace(degenerate, {0, 1, 1, 2});
    expectFinitePatches(degenerate);
    ObjShape flipped = named(cube(), "flipped.obj"); // one face wound against its neighbours
    std::swap(flipped.faceVertices[1], flipped.faceVertices[3]);
    expectFinitePatches(flipped);
}

} // namespace
} // namespace tessera::subdiv::test
