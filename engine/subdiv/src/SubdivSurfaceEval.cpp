// SubdivSurface's CPU evaluation through Far's patch table: the same basis
// (EvaluateBasis) and the same control points a GPU evaluates, in double.
#include "SubdivSurfaceImpl.h"

#include "tessera/subdiv/FaceParameterization.h"

#include <cassert>

namespace tessera::subdiv {

int SubdivSurface::Impl::findPatch(uint32_t ptexFace, glm::dvec2 uv) const {
    if (!patchMap || ptexFace >= firstPtex.back()) return -1;
    uv = glm::clamp(uv, 0.0, 1.0);
    const Far::PatchMap::Handle* handle = patchMap->FindPatch(int(ptexFace), uv.x, uv.y);
    return handle ? int(handle->patchIndex) : -1;
}

LimitPoint SubdivSurface::Impl::evaluate(uint32_t patch, glm::dvec2 uv) const {
    constexpr int kMaxPoints = 20;
    double w[6][kMaxPoints];
    // EvaluateBasis takes ptex-face coordinates, maps them into the patch
    // itself (PatchParam::Normalize), folds phantom boundary points and
    // scales derivatives back to the ptex face.
    patchTable->EvaluateBasis(patches.handles[patch], uv.x, uv.y, w[0], w[1], w[2], w[3], w[4], w[5]);
    const Patch& p = patches.patches[patch];
    const uint32_t* points = patches.indices.data() + p.firstIndex;
    LimitPoint result;
    glm::dvec3* out[6] = {&result.position, &result.du, &result.dv, &result.duu, &result.duv, &result.dvv};
    for (uint32_t i = 0; i < controlPointsOf(p.type); ++i) {
        const glm::dvec3 point(controlPoints[points[i]]);
        for (int k = 0; k < 6; ++k) *out[k] += w[k][i] * point;
    }
    // Far (and OsdEvaluatePatchBasis in GLSL) scale derivatives by 2^depth
    // while positions take the sub-face's own [0, 1] coordinates, whose
    // patches are 2^(depth - 1) to a side: for non-quad faces the
    // derivatives come out per half-size tile (Bfr's u, v), twice the
    // sub-face's. Undo that here so ptex derivatives match ptex positions
    // (the tests check against finite differences).
    if (p.param.nonQuadRoot()) {
        result.du *= 0.5, result.dv *= 0.5;
        result.duu *= 0.25, result.duv *= 0.25, result.dvv *= 0.25;
    }
    return result;
}

LimitPoint SubdivSurface::evaluatePatch(uint32_t patch, glm::dvec2 st) const {
    assert(patch < mImpl->patches.patches.size());
    const PatchParam& param = mImpl->patches.patches[patch].param;
    // Patch-local to ptex: both are exact in double (power-of-two scale).
    const glm::dvec2 uv = (glm::dvec2(param.u(), param.v()) + st) * param.paramFraction();
    return mImpl->evaluate(patch, uv);
}

std::optional<uint32_t> SubdivSurface::findPatch(uint32_t ptexFace, glm::dvec2 uv) const {
    const int patch = mImpl->findPatch(ptexFace, uv);
    if (patch < 0) return std::nullopt;
    return uint32_t(patch);
}

std::optional<LimitPoint> SubdivSurface::evaluatePtex(uint32_t ptexFace, glm::dvec2 uv) const {
    const int patch = mImpl->findPatch(ptexFace, uv);
    if (patch < 0) return std::nullopt;
    return mImpl->evaluate(uint32_t(patch), glm::clamp(uv, 0.0, 1.0));
}

std::optional<LimitPoint> SubdivSurface::evaluateFace(uint32_t face, glm::dvec2 uv) const {
    if (face >= baseFaceCount()) return std::nullopt;
    const FaceParameterization param(mImpl->faceSizes[face]);
    const SubFaceCoord coord = param.toSubFace(uv);
    std::optional<LimitPoint> result = evaluatePtex(mImpl->firstPtex[face] + coord.subFace, coord.st);
    if (!result) return std::nullopt;
    // Chain rule from the sub-face's (s, t) to Bfr's (u, v).
    const double k = param.derivativeScale();
    result->du *= k;
    result->dv *= k;
    result->duu *= k * k;
    result->duv *= k * k;
    result->dvv *= k * k;
    return result;
}

} // namespace tessera::subdiv
