// The 128-bit compressed vertex format (CompressedVertex.h) as C++: the bit
// layout field by field, determinism, and round-trip error bounds derived
// from the quantisation steps.
#include "tessera/character/CompressionError.h"
#include "tessera/core/Random.h"

#include "tessera/shaders/CompressedVertex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

using namespace tessera;
using namespace tessera::character;
using namespace tessera::shader;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;
// Per-axis position and uv error: half a 16-bit step of the range.
constexpr double kHalfStep16 = 0.5 / 65535.0;
// Normal: each SNORM component is off by at most half a step (1/511 for the
// 10-bit x, 1/1023 for the 11-bit y and z), so the decoded vector is within
// E of the unit input and the angle is at most asin(E).
const double kNormalBoundDeg = std::asin(std::sqrt(std::pow(0.5 / 511.0, 2) + 2.0 * std::pow(0.5 / 1023.0, 2))) * kDeg;
// Tangent: theta is off by at most pi/510 (half of pi/255), phi by pi/255
// (half of 2pi/255); the geodesic is at most dTheta + sin(theta') * dPhi.
const double kTangentBoundDeg = (kPi / 510.0 + kPi / 255.0) * kDeg;
// Float evaluation of the formulas (trigonometry, division, normalise).
constexpr double kAngleSlackDeg = 1e-3;

struct Decoded {
    vec3 position, normal, tangent;
    vec2 uv;
};

struct Ranges {
    vec3 boxMin{0.0f}, boxMax{1.0f};
    vec2 uvMin{0.0f}, uvMax{1.0f};
};

Decoded roundTrip(const CageVertex& v, const Ranges& r, uvec4* wordOut = nullptr) {
    const uvec4 word = tsPackVertex(v.position, v.normal, vec3(v.tangent), v.uv, r.boxMin, r.boxMax, r.uvMin, r.uvMax);
    if (wordOut) *wordOut = word;
    Decoded d;
    tsUnpackVertex(word, r.boxMin, r.boxMax, r.uvMin, r.uvMax, d.position, d.normal, d.tangent, d.uv);
    return d;
}

double angleDeg(glm::dvec3 a, glm::dvec3 b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * kDeg;
}

glm::vec3 randomUnit(Random& rng) {
    for (;;) {
        const glm::vec3 v(rng.range(-1.0f, 1.0f), rng.range(-1.0f, 1.0f), rng.range(-1.0f, 1.0f));
        const float len = glm::length(v);
        if (len > 0.05f && len <= 1.0f) return v / len;
    }
}

CageVertex makeVertex(glm::vec3 p, glm::vec3 n, glm::vec3 t, glm::vec2 uv) {
    CageVertex v;
    v.position = p;
    v.normal = n;
    v.tangent = glm::vec4(t, 1.0f);
    v.uv = uv;
    return v;
}

// Checks one vertex against every bound, naming the input on a failure so a
// sweep reports the offending vertex.
void expectWithinBounds(const CageVertex& v, const Ranges& r) {
    const Decoded d = roundTrip(v, r);
    for (int axis = 0; axis < 3; ++axis) {
        const double extent = double(r.boxMax[axis]) - double(r.boxMin[axis]);
        const double slack =
            8.0 * FLT_EPSILON * std::max({std::abs(double(r.boxMin[axis])), std::abs(double(r.boxMax[axis])), extent});
        EXPECT_LE(std::abs(double(d.position[axis]) - double(v.position[axis])), kHalfStep16 * extent + slack)
            << "axis " << axis << " position " << v.position[axis];
    }
    for (int axis = 0; axis < 2; ++axis) {
        const double range = double(r.uvMax[axis]) - double(r.uvMin[axis]);
        EXPECT_LE(std::abs(double(d.uv[axis]) - double(v.uv[axis])), kHalfStep16 * range + 4.0 * FLT_EPSILON * range)
            << "uv axis " << axis;
    }
    EXPECT_LE(angleDeg(v.normal, d.normal), kNormalBoundDeg + kAngleSlackDeg);
    EXPECT_LE(angleDeg(glm::vec3(v.tangent), d.tangent), kTangentBoundDeg + kAngleSlackDeg)
        << "tangent " << v.tangent.x << " " << v.tangent.y << " " << v.tangent.z;
    EXPECT_NEAR(glm::length(d.normal), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(d.tangent), 1.0f, 1e-6f);
}

} // namespace

TEST(CompressedVertex, DerivedBoundsMeetTheBrief) {
    EXPECT_LT(kNormalBoundDeg, 0.25);
    EXPECT_LT(kTangentBoundDeg + kNormalBoundDeg, 1.5);
}

TEST(CompressedVertex, BitLayoutFieldByField) {
    const Ranges r;
    uvec4 w;
    roundTrip(makeVertex({1.0f, 0.0f, 0.5f}, {1, 0, 0}, {0, 0, 1}, {0.25f, 1.0f}), r, &w);
    EXPECT_EQ(w.x, 0xffff0000u);               // X = 65535, Y = 0
    EXPECT_EQ(w.y, (0x8000u << 16) | 0x0080u); // Z = 32768 (half up), theta 0, phi 0 at the pole -> 128
    EXPECT_EQ(w.z, 511u << 22);                // Nx = +511 (SNORM one), Ny = Nz = 0
    EXPECT_EQ(w.w, (0x4000u << 16) | 0xffffu); // U = 16384, V = 65535

    roundTrip(makeVertex({0.0f, 1.0f, 0.0f}, {0, -1, 0}, {0, 1, 0}, {0.0f, 0.0f}), r, &w);
    EXPECT_EQ(w.x, 0x0000ffffu);
    EXPECT_EQ(w.y, (128u << 8) | 128u);           // theta pi/2, phi 0 (+y)
    EXPECT_EQ(w.z, (0x7ffu & uint(-1023)) << 11); // Ny = -1023 in 11-bit two's complement
    EXPECT_EQ(w.w, 0u);

    roundTrip(makeVertex({0.0f, 0.0f, 1.0f}, {0, 0, -1}, {0, -1, 0}, {1.0f, 0.0f}), r, &w);
    EXPECT_EQ(w.y, (0xffffu << 16) | (128u << 8) | 255u); // phi = pi -> 255
    EXPECT_EQ(w.z, 0x7ffu & uint(-1023));
    EXPECT_EQ(w.w, 0xffff0000u);

    roundTrip(makeVertex({0.0f, 0.0f, 0.0f}, {0, 0, 1}, {1, 0, 0}, {0.0f, 0.0f}), r, &w);
    EXPECT_EQ(w.y & 0xffffu, (128u << 8) | 191u); // phi = pi/2: 0.75 * 255 = 191.25
    roundTrip(makeVertex({0.0f, 0.0f, 0.0f}, {-1, 0, 0}, {-1, 0, 0}, {0.0f, 0.0f}), r, &w);
    EXPECT_EQ(w.y & 0xffffu, (128u << 8) | 64u); // phi = -pi/2: 63.75
    EXPECT_EQ(w.z, (0x3ffu & uint(-511)) << 22);
    roundTrip(makeVertex({0.0f, 0.0f, 0.0f}, {0, 0, 1}, {0, 0, -1}, {0.0f, 0.0f}), r, &w);
    EXPECT_EQ(w.y & 0xffffu, (255u << 8) | 128u); // theta = pi
}

TEST(CompressedVertex, HandBuiltWordsDecode) {
    const Ranges r{{-2.0f, 0.0f, 10.0f}, {2.0f, 4.0f, 12.0f}, {-1.0f, 0.0f}, {3.0f, 2.0f}};
    vec3 p, n, t;
    vec2 uv;
    tsUnpackVertex(uvec4(0xffff0000u, (0x0000u << 16) | (0u << 8) | 128u, 511u << 22, 0x0000ffffu), r.boxMin, r.boxMax,
                   r.uvMin, r.uvMax, p, n, t, uv);
    EXPECT_EQ(p, vec3(2.0f, 0.0f, 10.0f));
    EXPECT_EQ(n, vec3(1.0f, 0.0f, 0.0f));
    EXPECT_NEAR(t.z, 1.0f, 1e-7f);
    EXPECT_EQ(uv, vec2(-1.0f, 2.0f));
    // The most negative 10-bit code (-512) is unused by packing and clamps to -1.
    EXPECT_EQ(tsDequantizeSnorm(0x200u << 22, 31u, 10u), -1.0f);
}

TEST(CompressedVertex, AxisNormalsAndRangeEndsAreExact) {
    const Ranges r{{-3.0f, -1.0f, 0.5f}, {5.0f, 2.0f, 0.75f}, {-2.0f, 0.5f}, {4.0f, 1.5f}};
    const vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const vec3& axis : axes) {
        for (int corner = 0; corner < 8; ++corner) {
            const vec3 p((corner & 1) ? r.boxMax.x : r.boxMin.x, (corner & 2) ? r.boxMax.y : r.boxMin.y,
                         (corner & 4) ? r.boxMax.z : r.boxMin.z);
            const vec2 uv((corner & 1) ? r.uvMax.x : r.uvMin.x, (corner & 2) ? r.uvMax.y : r.uvMin.y);
            const CageVertex v = makeVertex(p, axis, glm::vec3(axis.z, axis.x, axis.y), uv);
            const Decoded d = roundTrip(v, r);
            EXPECT_EQ(d.position, p);
            EXPECT_EQ(d.uv, uv);
            EXPECT_EQ(d.normal, axis);
            expectWithinBounds(v, r);
        }
    }
}

TEST(CompressedVertex, PolesAndDegenerateInputs) {
    const Ranges r;
    // s == 0 tangents (the poles): phi is defined as 0, no NaN.
    for (float z : {1.0f, -1.0f}) {
        const Decoded d = roundTrip(makeVertex({0.5f, 0.5f, 0.5f}, {1, 0, 0}, {0, 0, z}, {0.5f, 0.5f}), r);
        EXPECT_NEAR(d.tangent.z, z, 1e-6f);
        EXPECT_TRUE(std::isfinite(d.tangent.x) && std::isfinite(d.tangent.y));
    }
    // Nearly polar: s is tiny but positive.
    expectWithinBounds(makeVertex({0.5f, 0.5f, 0.5f}, {1, 0, 0}, glm::normalize(glm::vec3(1e-20f, 0, 1)), {0, 0}), r);
    // Zero vectors read as +z; a flat box axis and uv range decode to their value.
    const Ranges flat{{0.0f, 1.0f, 2.0f}, {1.0f, 1.0f, 3.0f}, {0.5f, 0.0f}, {0.5f, 1.0f}};
    const Decoded d = roundTrip(makeVertex({0.25f, 1.0f, 2.5f}, {0, 0, 0}, {0, 0, 0}, {0.5f, 0.25f}), flat);
    EXPECT_EQ(d.normal, vec3(0, 0, 1));
    EXPECT_NEAR(d.tangent.z, 1.0f, 1e-6f);
    EXPECT_EQ(d.position.y, 1.0f);
    EXPECT_EQ(d.uv.x, 0.5f);
    // Outside the ranges: clamps to the faces.
    const Decoded out = roundTrip(makeVertex({-5.0f, 7.0f, 0.5f}, {0, 1, 0}, {1, 0, 0}, {-1.0f, 2.0f}), r);
    EXPECT_EQ(out.position.x, 0.0f);
    EXPECT_EQ(out.position.y, 1.0f);
    EXPECT_EQ(out.uv, vec2(0.0f, 1.0f));
}

TEST(CompressedVertex, RandomRoundTripsStayWithinTheDerivedBounds) {
    Random rng(20260523u);
    for (int i = 0; i < 20000; ++i) {
        Ranges r;
        r.boxMin = vec3(rng.range(-10.0f, 0.0f), rng.range(-10.0f, 0.0f), rng.range(-10.0f, 0.0f));
        r.boxMax = r.boxMin + vec3(rng.range(0.1f, 10.0f), rng.range(0.1f, 10.0f), rng.range(0.1f, 10.0f));
        r.uvMin = vec2(rng.range(-2.0f, 0.5f), rng.range(-2.0f, 0.5f));
        r.uvMax = r.uvMin + vec2(rng.range(0.5f, 4.0f), rng.range(0.5f, 4.0f));
        const vec3 p = glm::mix(r.boxMin, r.boxMax, vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()));
        const vec2 uv = glm::mix(r.uvMin, r.uvMax, vec2(rng.nextFloat(), rng.nextFloat()));
        const vec3 n = randomUnit(rng);
        const vec3 t = glm::normalize(glm::cross(n, randomUnit(rng)));
        const CageVertex v = makeVertex(p, n, t, uv);
        expectWithinBounds(v, r);
        if (HasFailure()) FAIL() << "vertex " << i;
    }
}

TEST(CompressedVertex, PackingIsDeterministic) {
    Random a(7u), b(7u);
    for (int i = 0; i < 1000; ++i) {
        const CageVertex va = makeVertex({a.nextFloat(), a.nextFloat(), a.nextFloat()}, randomUnit(a), randomUnit(a),
                                         {a.nextFloat(), a.nextFloat()});
        const CageVertex vb = makeVertex({b.nextFloat(), b.nextFloat(), b.nextFloat()}, randomUnit(b), randomUnit(b),
                                         {b.nextFloat(), b.nextFloat()});
        uvec4 wa, wb;
        roundTrip(va, Ranges{}, &wa);
        roundTrip(vb, Ranges{}, &wb);
        ASSERT_EQ(wa, wb);
    }
}

TEST(CompressedVertex, MeasuredErrorStaysWithinTheBounds) {
    Random rng(99u);
    std::vector<CageVertex> vertices;
    for (int i = 0; i < 5000; ++i) {
        const vec3 n = randomUnit(rng);
        vertices.push_back(makeVertex({rng.range(-1.0f, 1.0f), rng.range(0.0f, 2.0f), rng.range(-0.5f, 0.5f)}, n,
                                      glm::normalize(glm::cross(n, randomUnit(rng))),
                                      {rng.range(0.0f, 1.5f), rng.range(-0.5f, 1.0f)}));
    }
    const scene::Aabb box = positionBounds(vertices);
    const UvRange uv = uvBounds(vertices);
    EXPECT_GE(uv.min.x, 0.0f);
    EXPECT_LE(uv.max.x, 1.5f);
    const CompressionErrorStats stats = measureCompressionError(vertices, box, uv);
    EXPECT_EQ(stats.vertexCount, 5000u);
    // Euclidean over three axes, each half a step of at most the largest extent.
    EXPECT_LE(stats.maxPositionError, std::sqrt(3.0) * kHalfStep16 + 1e-6);
    EXPECT_GT(stats.maxPositionError, 0.0);
    EXPECT_LE(stats.maxNormalAngleDeg, kNormalBoundDeg + kAngleSlackDeg);
    // After Gram-Schmidt against the decoded normal: at most the tangent's own
    // error plus the normal's tilt of the plane (first order).
    EXPECT_LE(stats.maxTangentAngleDeg, kTangentBoundDeg + kNormalBoundDeg + 0.01);
    EXPECT_LE(stats.maxUvError, kHalfStep16 * 1.5 + 1e-6);
    EXPECT_TRUE(positionBounds({}).isEmpty());
    // A tangent parallel to its normal has no frame but must not make NaN.
    const CageVertex parallel = makeVertex({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0});
    const CompressionErrorStats degenerate = measureCompressionError({&parallel, 1}, box, uv);
    EXPECT_TRUE(std::isfinite(degenerate.maxTangentAngleDeg));
}
