#include "tessera/subdiv/SubdivLod.h"

#include "tessera/tessellator/Tessellator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera::subdiv {

namespace {

float largestScale(const glm::mat4& m) {
    return std::max({glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

/// The refined points the prediction reads: base vertices (support boxes)
/// and corner points (levels); control points stay zero.
std::vector<glm::vec4> lodPoints(const SubdivGpuMesh& mesh, std::span<const glm::vec3> base) {
    std::vector<glm::vec4> points(mesh.refinedPointCount(), glm::vec4(0.0f));
    for (uint32_t v = 0; v < mesh.baseVertexCount; ++v) points[v] = glm::vec4(base[v], 1.0f);
    for (uint32_t i = mesh.controlPointCount; i < mesh.refinedPointCount(); ++i) {
        const glm::uvec4 s = mesh.stencils[i];
        glm::vec3 sum(0.0f);
        for (uint32_t k = 0; k < s.y; ++k) {
            const glm::uvec2 e = mesh.stencilEntries[s.x + k];
            sum += std::bit_cast<float>(e.y) * base[e.x];
        }
        points[i] = glm::vec4(sum, std::bit_cast<float>(s.z));
    }
    return points;
}

} // namespace

SubdivPrediction SubdivLod::predict(const SubdivGpuMesh& mesh, std::span<const glm::vec4> refined,
                                    const shader::SubdivUniforms& u) {
    SubdivPrediction prediction;
    for (const shader::SubdivDomain& d : mesh.domains) {
        if (d.topology.w & TS_SUBDIV_DOMAIN_HOLE) continue;
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (uint32_t k = 0; k < d.topology.z; ++k) {
            const glm::vec3 p(refined[mesh.support[d.topology.y + k]]);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        if (!shader::tsSubdivBoxVisible(lo, hi, u)) continue;
        glm::vec4 corner;
        for (int c = 0; c < 4; ++c) {
            const glm::vec4 point = refined[d.corners[c]];
            const glm::vec3 world(u.model * glm::vec4(glm::vec3(point), 1.0f));
            corner[c] = shader::tsSubdivCornerLevel(world, point.w, u);
        }
        glm::vec4 outer;
        glm::vec2 inner;
        shader::tsSubdivDomainLevels(corner, outer, inner);
        tessellator::TessFactors factors;
        factors.outer = {outer.x, outer.y, outer.z, outer.w};
        factors.inner = {inner.x, inner.y};
        ++prediction.domainsVisible;
        prediction.triangles += tessellator::Tessellator::countTriangles(tessellator::Domain::Quad,
                                                                         tessellator::Partitioning::FractionalOdd,
                                                                         factors);
    }
    return prediction;
}

SubdivLodFrame SubdivLod::plan(const SubdivGpuMesh& mesh, std::span<const glm::vec3> base, const glm::mat4& model,
                               const SubdivView& view, const SubdivLodSettings& settings) {
    SubdivLodFrame frame;
    shader::SubdivUniforms& u = frame.uniforms;
    u.model = model;
    u.normalMatrix = glm::transpose(glm::inverse(model));
    for (int i = 0; i < 6; ++i) u.planes[i] = view.frustum.planes()[i];
    u.eye = glm::vec4(view.eye, view.pixelsPerMetre);
    u.lod = glm::vec4(std::max(settings.targetPixels, 0.25f), std::max(settings.levelCap, 1.0f), 1.0f,
                      settings.fixedLevel);
    u.placement = glm::vec4(largestScale(model), settings.displacementScale,
                            std::abs(settings.maxDisplacement * settings.displacementScale), 0.0f);
    u.modes = glm::uvec4(settings.normals, settings.mipSelection ? 1u : 0u, settings.view, mesh.domainCount());
    u.albedo = glm::vec4(settings.albedo, 1.0f);

    const std::vector<glm::vec4> points = lodPoints(mesh, base);
    frame.prediction = predict(mesh, points, u);
    // Triangles grow with the square of the level: scale by the square
    // root of the overshoot, a few times, as levels clamp at 1.
    for (int round = 0; round < 8 && settings.triangleBudget > 0 && frame.prediction.triangles > settings.triangleBudget;
         ++round) {
        const double ratio = double(settings.triangleBudget) / double(frame.prediction.triangles);
        frame.budgetScale *= float(std::sqrt(ratio)) * (round < 4 ? 1.0f : 0.8f);
        u.lod.z = frame.budgetScale;
        if (u.lod.w > 0.0f) u.lod.w = std::max(1.0f, u.lod.w * float(std::sqrt(ratio)));
        frame.prediction = predict(mesh, points, u);
    }
    return frame;
}

} // namespace tessera::subdiv
