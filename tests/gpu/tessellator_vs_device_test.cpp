// The emulated tessellator against the device's fixed-function one: for a
// sweep of levels, both domains and all three spacings, the domain points
// captured through transform feedback must be the emulation's points exactly
// (as sets), the non-degenerate triangle counts must agree, and the pipeline
// statistics must count what Tessellator::countTriangles/countPoints predict.
#include "TessellationCaptureFixture.h"

#include "tessera/core/Random.h"
#include "tessera/tessellator/Tessellator.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>
#include <utility>

using namespace tessera;
using namespace tessera::test;
using tessellator::Domain;
using tessellator::Partitioning;
using tessellator::TessFactors;
using tessellator::Tessellator;

namespace {

using PointSet = std::set<std::pair<float, float>>;

struct Case {
    Domain domain;
    Partitioning partitioning;
    TessFactors factors;
};

CaptureDomain toCapture(Domain d) { return d == Domain::Quad ? CaptureDomain::Quad : CaptureDomain::Triangle; }

CaptureSpacing toCapture(Partitioning p) {
    switch (p) {
    case Partitioning::Integer: return CaptureSpacing::Equal;
    case Partitioning::FractionalOdd: return CaptureSpacing::FractionalOdd;
    case Partitioning::FractionalEven: return CaptureSpacing::FractionalEven;
    }
    return CaptureSpacing::Equal;
}

std::string describe(const Case& c) {
    static const char* spacing[] = {"integer", "fractional_odd", "fractional_even"};
    char text[200];
    std::snprintf(text, sizeof text, "%s %s outer {%.4g %.4g %.4g %.4g} inner {%.4g %.4g}",
                  c.domain == Domain::Quad ? "quad" : "triangle", spacing[int(c.partitioning)], c.factors.outer[0],
                  c.factors.outer[1], c.factors.outer[2], c.factors.outer[3], c.factors.inner[0], c.factors.inner[1]);
    return text;
}

// Twice the signed area in the (u, v) plane; zero for the degenerate
// triangles both tessellators emit at some fractional levels.
bool hasArea(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    const glm::vec2 e0 = b - a, e1 = c - a;
    return e0.x * e1.y - e0.y * e1.x != 0.0f;
}

struct Comparison {
    PointSet devicePoints, emulatedPoints;
    uint32_t deviceSolid = 0, emulatedSolid = 0;
};

Comparison compare(const TessellationCaptureResult& device, const tessellator::TessellatedPatch& emulated) {
    Comparison c;
    for (size_t i = 0; i + 2 < device.vertices.size(); i += 3) {
        const glm::vec2 a(device.vertices[i]), b(device.vertices[i + 1]), d(device.vertices[i + 2]);
        c.devicePoints.emplace(a.x, a.y);
        c.devicePoints.emplace(b.x, b.y);
        c.devicePoints.emplace(d.x, d.y);
        if (hasArea(a, b, d)) ++c.deviceSolid;
    }
    for (size_t i = 0; i + 2 < emulated.indices.size(); i += 3) {
        const glm::vec2 a = emulated.uv[emulated.indices[i]], b = emulated.uv[emulated.indices[i + 1]],
                        d = emulated.uv[emulated.indices[i + 2]];
        if (hasArea(a, b, d)) ++c.emulatedSolid;
    }
    // Every emulated point is used by a triangle (checked by the unit tests),
    // so the triangles' points are all the points.
    for (const auto& p : emulated.uv) c.emulatedPoints.emplace(p.x, p.y);
    return c;
}

std::vector<Case> sweep() {
    std::vector<Case> cases;
    const Domain domains[] = {Domain::Triangle, Domain::Quad};
    const Partitioning spacings[] = {Partitioning::Integer, Partitioning::FractionalOdd, Partitioning::FractionalEven};
    const float uniform[] = {1.0f, 1.5f, 2.0f, 2.3f, 3.0f, 4.7f, 7.5f, 14.99f, 15.0f, 33.3f, 64.0f};
    Random rng(20261122u);
    auto level = [](Random& r) { return r.range(0.5f, 20.0f); };
    for (Domain d : domains)
        for (Partitioning p : spacings) {
            for (float l : uniform) cases.push_back({d, p, {{l, l, l, l}, {l, l}}});
            // Mixed levels, as adaptive draws make them: every edge its own.
            for (int i = 0; i < 25; ++i) {
                TessFactors f;
                for (float& o : f.outer) o = level(rng);
                for (float& in : f.inner) in = level(rng);
                cases.push_back({d, p, f});
            }
        }
    return cases;
}

} // namespace

using TessellatorVsDevice = TessellationCaptureFixture;

TEST_F(TessellatorVsDevice, SamePointsTrianglesAndCountsOverASweep) {
    const bool exactInvocations = device->features().isCpu;
    size_t compared = 0;
    for (const Case& c : sweep()) {
        auto captured = capture->run(toCapture(c.domain), toCapture(c.partitioning), c.factors.outer, c.factors.inner);
        ASSERT_TRUE(captured.ok()) << captured.error().message;
        const auto& device = captured.value();
        const auto emulated = Tessellator::tessellate(c.domain, c.partitioning, c.factors);
        const Comparison cmp = compare(device, emulated);
        const std::string what = describe(c);

        EXPECT_EQ(cmp.devicePoints, cmp.emulatedPoints) << what;
        EXPECT_EQ(cmp.deviceSolid, cmp.emulatedSolid) << what << ": non-degenerate triangles";
        EXPECT_EQ(device.primitivesWritten, Tessellator::countTriangles(c.domain, c.partitioning, c.factors)) << what;
        EXPECT_EQ(device.primitivesWritten, emulated.triangleCount()) << what;
        // Vulkan lets an implementation run the evaluation shader more than
        // once per point (or share it through a cache); a CPU driver runs it
        // exactly once per tessellator point, as the emulation counts them.
        const uint32_t points = Tessellator::countPoints(c.domain, c.partitioning, c.factors);
        if (exactInvocations)
            EXPECT_EQ(device.evaluationInvocations, points) << what;
        else
            EXPECT_GE(device.evaluationInvocations, uint64_t(cmp.devicePoints.size())) << what;
        ++compared;
        if (HasFailure()) break; // one case's diagnosis is enough
    }
    EXPECT_EQ(compared, sweep().size());
}

TEST_F(TessellatorVsDevice, CulledPatchesAgree) {
    for (Domain d : {Domain::Triangle, Domain::Quad}) {
        const TessFactors culled{{4.0f, 0.0f, 4.0f, 4.0f}, {4.0f, 4.0f}};
        auto captured = capture->run(toCapture(d), CaptureSpacing::FractionalOdd, culled.outer, culled.inner);
        ASSERT_TRUE(captured.ok()) << captured.error().message;
        EXPECT_EQ(captured.value().primitivesWritten, 0u);
        EXPECT_EQ(Tessellator::countTriangles(d, Partitioning::FractionalOdd, culled), 0u);
    }
}
