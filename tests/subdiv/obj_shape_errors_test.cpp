// The .obj reader on bad input: each error the contract lists, with a
// one-line message naming the file, the line and the problem; missing and
// unreadable files; and truncations and byte flips of the real shapes,
// which must come back ok or as an error, never as a crash (the
// tessera_subdiv_asan_tests build runs this file under ASan and UBSan).
#include "ObjShapeTestFiles.h"
#include "TestFiles.h"

#include "tessera/core/Random.h"
#include "tessera/subdiv/ObjShape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace tessera;
using namespace tessera::subdiv;

namespace {

// Lines 1..9; a face after it is line 10, a tag after that line 11.
const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n";
const std::string kQuad = kSquare + "f 1 2 3 4\n";

struct BadInput {
    std::string text;
    std::string message; ///< the whole expected prefix "inline.obj:<line>: <problem start>"
};

std::string errorOf(const std::string& text) {
    Result<ObjShape> shape = parseObjShape(text, "inline.obj");
    return shape.ok() ? std::string("(loaded)") : shape.error().message;
}

/// `count` vertices on a circle and one face through all of them.
std::string polygon(int count) {
    std::string text, face = "f";
    for (int i = 0; i < count; ++i) {
        // Appended piece by piece: GCC 12 warns (-Wrestrict, a false
        // positive) on `" " + std::to_string(...)`.
        text.append("v ").append(std::to_string(std::cos(i * 0.1))).append(" ");
        text.append(std::to_string(std::sin(i * 0.1))).append(" 0\n");
        face.append(" ").append(std::to_string(i + 1));
    }
    return text + face + "\n";
}

/// What every shape the reader returns must satisfy, whatever it was fed.
void expectConsistent(const ObjShape& shape) {
    ASSERT_FALSE(shape.positions.empty());
    ASSERT_FALSE(shape.faceSizes.empty());
    size_t corners = 0;
    for (uint32_t size : shape.faceSizes) {
        ASSERT_GE(size, 3u);
        ASSERT_LE(size, kMaxFaceVertices);
        corners += size;
    }
    ASSERT_EQ(shape.faceVertices.size(), corners);
    ASSERT_TRUE(shape.faceUvs.empty() || shape.faceUvs.size() == corners);
    for (uint32_t v : shape.faceVertices) ASSERT_LT(v, shape.positions.size());
    for (uint32_t t : shape.faceUvs) ASSERT_LT(t, shape.uvs.size());
    for (const glm::vec3& p : shape.positions)
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    for (const Crease& c : shape.creases) ASSERT_TRUE(c.v0 < shape.positions.size() && c.v1 < shape.positions.size());
    for (const Corner& c : shape.corners) ASSERT_LT(c.vertex, shape.positions.size());
    for (uint32_t hole : shape.holes) ASSERT_LT(hole, shape.faceCount());
}

} // namespace

TEST(ObjShapeErrors, EachBadInputNamesTheFileTheLineAndTheProblem) {
    const std::string v5 = "v 0 0 1\n"; // line 10 after kSquare
    const BadInput cases[] = {
        {"", "inline.obj: empty file"},
        {" \r\n\t\n", "inline.obj: empty file"},
        {"# comment only\n", "inline.obj: no vertices"},
        {"vt 0 0\nvt 1 1\n", "inline.obj: no vertices"},
        {kSquare, "inline.obj: no faces"},
        {kSquare + "f 1 2\n", "inline.obj:10: face with 2 vertices (3 to 64)"},
        {"v 0 0 0\nf\n", "inline.obj:2: face with 0 vertices"},
        {polygon(65), "inline.obj:66: face with 65 vertices (3 to 64)"},
        {kSquare + "f 0 1 2\n", "inline.obj:10: vertex index 0 out of range (4 so far"},
        {kSquare + "f 1 2 5\n", "inline.obj:10: vertex index 5 out of range (4 so far"},
        {kSquare + "f -5 1 2\n", "inline.obj:10: vertex index -5 out of range"},
        {"f 1 2 3\n" + kSquare, "inline.obj:1: vertex index 1 out of range (0 so far"},
        {kSquare + "f 1/9 2/1 3/1\n", "inline.obj:10: texture coordinate index 9 out of range (4 so far"},
        {kSquare + "f 1/0 2/1 3/1\n", "inline.obj:10: texture coordinate index 0 out of range"},
        {kSquare + "f 1//2 2//1 3//1\n", "inline.obj:10: normal index 2 out of range (1 so far"},
        {kSquare + "f 99999999999999999999 1 2\n", "inline.obj:10: malformed face vertex '99999999999999999999'"},
        {kSquare + "f 1/ 2 3\n", "inline.obj:10: malformed face vertex '1/'"},
        {kSquare + "f 1/1/1/1 2 3\n", "inline.obj:10: malformed face vertex '1/1/1/1'"},
        {kSquare + "f /1 2 3\n", "inline.obj:10: malformed face vertex '/1'"},
        {kSquare + "f a b c\n", "inline.obj:10: malformed face vertex 'a'"},
        {kSquare + "f 1.5 2 3\n", "inline.obj:10: malformed face vertex '1.5'"},
        {kSquare + "f 1 2 1\n", "inline.obj:10: degenerate face: uses vertex 1 twice"},
        {kSquare + "f 1 2 3 -3\n", "inline.obj:10: degenerate face: uses vertex 2 twice"},
        {kSquare + "f 1 2 3\nf 1 2 4\n", "inline.obj:11: non-manifold edge 1-2: a second face runs it the same way"},
        {kSquare + v5 + "f 1 2 3\nf 2 1 4\nf 2 1 5\n",
         "inline.obj:13: non-manifold edge 2-1: shared by more than two faces"},
        {kSquare + v5 + "f 1 2 3\nf 2 1 4\nf 1 2 5\n",
         "inline.obj:13: non-manifold edge 1-2: shared by more than two faces"},
        {"v 1 2 x\n", "inline.obj:1: malformed or out-of-range number 'x'"},
        {"v 1,5 2 3\n", "inline.obj:1: malformed or out-of-range number '1,5'"},
        {"v 1 2 3 4 y\n", "inline.obj:1: malformed or out-of-range number 'y'"},
        {"v 1e999 2 3\n", "inline.obj:1: malformed or out-of-range number '1e999'"},
        {"vt 0 -\n", "inline.obj:1: malformed or out-of-range number '-'"},
        {"v 1 2\n", "inline.obj:1: vertex with 2 coordinates (needs 3)"},
        {"vt\n", "inline.obj:1: texture coordinate with 0 coordinates (needs 1)"},
        {"v 1 nan 3\n", "inline.obj:1: non-finite coordinate 'nan' in vertex"},
        {"v 0 0 -inf\n", "inline.obj:1: non-finite coordinate '-inf' in vertex"},
        {"v 1e39 0 0\n", "inline.obj:1: non-finite coordinate '1e39' in vertex"},
        {"vt 0 infinity\n", "inline.obj:1: non-finite coordinate 'infinity' in texture coordinate"},
        {kSquare + "f 1/1 2/2 3/3\nf 1 3 4\n", "inline.obj:11: face without texture coordinates after faces with"},
        {kSquare + "f 1 2 3\nf 1/1 3/3 4/4\n", "inline.obj:11: face with texture coordinates after faces without"},
        {kSquare + "f 1/1 2 3/3\n", "inline.obj:10: face gives texture coordinates for some vertices but not all"},
        {kQuad + "t crease 2/1/0 0 9 1\n", "inline.obj:11: crease tag names missing vertex 9 (4 vertices, 0-based)"},
        {kQuad + "t crease 2/1/0 -1 0 1\n", "inline.obj:11: crease tag names missing vertex -1"},
        {kQuad + "t crease 2/1/0 0 2 1\n", "inline.obj:11: crease tag names edge 0-2, which no face has"},
        {kQuad + "t crease 2/1/0 1 1 1\n", "inline.obj:11: crease tag names edge 1-1, which no face has"},
        {kQuad + "t crease 3/1/0 0 1 2 1\n", "inline.obj:11: crease tag needs vertex pairs, has 3 ints"},
        {kQuad + "t crease 4/3/0 0 1 1 2 1 2 3\n", "inline.obj:11: crease tag needs 1 sharpness or 1 per vertex pair"},
        {kQuad + "t crease 2/1/0 0 1 nan\n", "inline.obj:11: crease tag: non-finite sharpness"},
        {kQuad + "t corner 1/1/0 4 1\n", "inline.obj:11: corner tag names missing vertex 4 (4 vertices, 0-based)"},
        {kQuad + "t corner 0/1/0 1\n", "inline.obj:11: corner tag names no vertex"},
        {kQuad + "t corner 1/1/0 0 abc\n", "inline.obj:11: tag 'corner': malformed float 'abc'"},
        {kQuad + "t hole 1/0/0 1\n", "inline.obj:11: hole tag names missing face 1 (1 faces, 0-based)"},
        {kQuad + "t hole 1/0/0 x\n", "inline.obj:11: tag 'hole': malformed int 'x'"},
        {kQuad + "t hole 1/1/0 0 1\n", "inline.obj:11: hole tag takes no floats"},
        {kQuad + "t interpolateboundary 1/0/0 3\n", "inline.obj:11: interpolateboundary tag: 3 is not 0"},
        {kQuad + "t interpolateboundary 0/0/0\n", "inline.obj:11: interpolateboundary tag needs 1 int, has 0"},
        {kQuad + "t smoothtriangles 0/0/1 maybe\n", "inline.obj:11: smoothtriangles tag: 'maybe' is not 'smooth'"},
        {kQuad + "t crease 2/1/0 0 1\n", "inline.obj:11: tag 'crease': counts '2/1/0' do not match its 2 values"},
        {kQuad + "t crease 2/1/0 0 1 2 3\n", "inline.obj:11: tag 'crease': counts '2/1/0' do not match its 4 values"},
        {kQuad + "t crease 2/1 0 1 2\n", "inline.obj:11: tag 'crease': missing or malformed counts"},
        {kQuad + "t crease\n", "inline.obj:11: tag 'crease': missing or malformed counts"},
        {kQuad + "t crease -1/1/0 1\n", "inline.obj:11: tag 'crease': missing or malformed counts"},
        {kQuad + "t mystery 9223372036854775807/9223372036854775807/2 a b\n",
         "inline.obj:11: tag 'mystery': counts '9223372036854775807/922337203685...' do not match its 2 values"},
        {kQuad + "t mystery 1/0/0\n", "inline.obj:11: tag 'mystery': counts '1/0/0' do not match its 0 values"},
        {kQuad + "t\n", "inline.obj:11: tag without a name"},
        // A tag before the faces is checked once they are all read, at its own line.
        {kSquare + "t hole 1/0/0 1\nf 1 2 3 4\n", "inline.obj:10: hole tag names missing face 1"},
        // Hostile bytes in a word stay on one line of the message.
        {std::string("v 1 2 \x1b\n\x01", 9), "inline.obj:1: malformed or out-of-range number '?'"},
    };
    for (const BadInput& bad : cases) {
        SCOPED_TRACE(bad.text.substr(0, 200));
        const std::string message = errorOf(bad.text);
        EXPECT_EQ(message.substr(0, bad.message.size()), bad.message) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
    }
}

TEST(ObjShapeErrors, TheLargestFaceLoadsAndOneMoreVertexDoesNot) {
    Result<ObjShape> largest = parseObjShape(polygon(int(kMaxFaceVertices)), "polygon.obj");
    ASSERT_TRUE(largest.ok()) << largest.error().message;
    EXPECT_EQ(largest->faceSizes, std::vector<uint32_t>{kMaxFaceVertices});
    EXPECT_FALSE(parseObjShape(polygon(int(kMaxFaceVertices) + 1), "polygon.obj").ok());
}

TEST(ObjShapeErrors, MissingOrUnreadableFilesAreErrorsNamingThePath) {
    const std::filesystem::path missing = test::osdShapesDir() / "no_such_shape.obj";
    Result<ObjShape> shape = readObjShape(missing);
    ASSERT_FALSE(shape.ok());
    EXPECT_EQ(shape.error().message, missing.string() + ": no such file");

    shape = readObjShape(test::osdShapesDir());
    ASSERT_FALSE(shape.ok());
    EXPECT_EQ(shape.error().message, test::osdShapesDir().string() + ": not a regular file");

    shape = readObjShape("/dev/null");
    ASSERT_FALSE(shape.ok());
    EXPECT_EQ(shape.error().message, "/dev/null: not a regular file");

    // A parse error in a file names the path as given, and the line.
    const std::filesystem::path bad = test::testOutputDir("subdiv") / "two_coordinates.obj";
    std::ofstream(bad) << "# a vertex short of a coordinate\nv 1 2\n";
    shape = readObjShape(bad);
    ASSERT_FALSE(shape.ok());
    EXPECT_EQ(shape.error().message, bad.string() + ":2: vertex with 2 coordinates (needs 3)");
}

TEST(ObjShapeErrors, TruncationsAndByteFlipsOfTheShapesNeverCrash) {
    size_t loaded = 0, refused = 0;
    auto feed = [&](const std::string& text, const std::string& name) {
        Result<ObjShape> shape = parseObjShape(text, name);
        if (shape.ok()) {
            ++loaded;
            expectConsistent(shape.value());
        } else {
            ++refused;
            const std::string& message = shape.error().message;
            EXPECT_EQ(message.rfind(name + ":", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    };
    Random random(20240611);
    // Bytes that matter to the syntax, more often than any other byte.
    std::string syntax = "0123456789-+./#\n \t\refvtn";
    syntax.push_back('\0');
    for (const std::filesystem::path& file : test::osdShapeFiles()) {
        const std::string text = test::readObjText(file);
        const std::string name = file.filename().string();
        // Every prefix of the small files, ~1500 of the large ones.
        const size_t step = std::max<size_t>(1, text.size() / 1500);
        for (size_t length = 0; length <= text.size(); length += step) feed(text.substr(0, length), name);
        for (int trial = 0; trial < 400; ++trial) {
            std::string mutated = text;
            const int flips = 1 + int(random.below(4));
            for (int i = 0; i < flips; ++i) {
                const size_t at = random.below(uint32_t(mutated.size()));
                mutated[at] = random.below(2) ? syntax[random.below(uint32_t(syntax.size()))] : char(random.below(256));
            }
            feed(mutated, name);
        }
    }
    std::printf("truncations and byte flips: %zu loaded, %zu refused\n", loaded, refused);
    EXPECT_GT(loaded, 0u);
    EXPECT_GT(refused, 0u);
}
