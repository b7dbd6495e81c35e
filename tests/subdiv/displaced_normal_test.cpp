// The displaced surface's tangents (tsDisplacedTangents, section 5.1)
// against central differences of f = s + N D, with the base surface from
// Far and D from converted tiles: the Weingarten term makes them agree, and
// Blinn's approximation (section 5.2) is measurably off where D is large.
#include "TileTestSupport.h"

#include "tessera/subdiv/DisplacementConversion.h"
#include "tessera/subdiv/ProceduralDisplacement.h"

#include <cstdio>

namespace tessera::subdiv::test {
namespace {

TEST(DisplacedNormal, TangentsMatchFiniteDifferences) {
    // Regular B-spline patches only: Far's derivatives are exact there
    // (Gregory end caps' are OpenSubdiv's approximation).
    for (const ObjShape& shape : {torus(8, 6, 0.0f, "torus"), grid(4, BoundaryInterpolation::EdgeAndCorner, "grid")}) {
        const SubdivSurface surface = build(shape);
        const PtexTopology topology = topologyOf(shape);
        DisplacementTiles tiles = makeTiles(topology, DisplacementTiles::uniformLog2Sizes(topology, 3));
        ProceduralDisplacement::Settings settings;
        settings.amplitude = 0.05;
        const ProceduralDisplacement field(surface, settings);
        convertDisplacement(tiles, field.sampler());
        const auto displaced = [&](uint32_t tile, glm::dvec2 uv) {
            const LimitPoint p = *surface.evaluatePtex(tile, uv);
            const double d = tiles.evaluateLevel(tile, 0, glm::vec2(uv)).value.x;
            return p.position + glm::normalize(p.normal()) * d;
        };
        double worst = 0.0, blinn = 0.0;
        const double h = 1e-3;
        for (uint32_t t = 0; t < topology.tileCount(); ++t)
            for (glm::dvec2 uv : {glm::dvec2(0.3, 0.6), glm::dvec2(0.71, 0.23)}) {
                const LimitPoint p = *surface.evaluatePtex(t, uv);
                const glm::vec4 d = tiles.evaluateLevel(t, 0, glm::vec2(uv)).value;
                glm::vec3 fu, fv, bu, bv;
                shader::tsDisplacedTangents(glm::vec3(p.du), glm::vec3(p.dv), glm::vec3(p.duu), glm::vec3(p.duv),
                                            glm::vec3(p.dvv), glm::vec3(d), true, fu, fv);
                shader::tsDisplacedTangents(glm::vec3(p.du), glm::vec3(p.dv), glm::vec3(p.duu), glm::vec3(p.duv),
                                            glm::vec3(p.dvv), glm::vec3(d), false, bu, bv);
                const glm::dvec3 du =
                    (displaced(t, uv + glm::dvec2(h, 0)) - displaced(t, uv - glm::dvec2(h, 0))) / (2 * h);
                const glm::dvec3 dv =
                    (displaced(t, uv + glm::dvec2(0, h)) - displaced(t, uv - glm::dvec2(0, h))) / (2 * h);
                const double scale = std::max(glm::length(du), glm::length(dv));
                worst = std::max(
                    {worst, glm::length(glm::dvec3(fu) - du) / scale, glm::length(glm::dvec3(fv) - dv) / scale});
                blinn = std::max(
                    {blinn, glm::length(glm::dvec3(bu) - du) / scale, glm::length(glm::dvec3(bv) - dv) / scale});
            }
        EXPECT_LT(worst, 1e-4) << shape.name;
        EXPECT_GT(blinn, 5.0 * worst) << shape.name;
        std::printf("[ normal ] %-8s tangents vs central differences: Weingarten %.1e, Blinn's approximation %.1e\n",
                    shape.name.c_str(), worst, blinn);
    }
}

} // namespace
} // namespace tessera::subdiv::test
