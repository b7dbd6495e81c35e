#include "tessera/subdiv/BfrReference.h"

#include "SubdivSurfaceImpl.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>

#include <cassert>
#include <vector>

namespace tessera::subdiv {

namespace Bfr = OpenSubdiv::Bfr;

namespace {

Bfr::SurfaceFactory::Options factoryOptions(const SubdivSettings& settings) {
    Bfr::SurfaceFactory::Options options;
    // The same depths as Far's isolation: smooth irregular features stop at
    // the secondary level, sharp ones at the primary.
    options.SetApproxLevelSmooth(int(settings.smoothIsolationLevel));
    options.SetApproxLevelSharp(int(settings.isolationLevel));
    return options;
}

} // namespace

struct BfrReference::Impl {
    const SubdivSurface::Impl& surface;
    Bfr::RefinerSurfaceFactory<> factory;

    explicit Impl(const SubdivSurface::Impl& s) : surface(s), factory(*s.refiner, factoryOptions(s.settings)) {}
};

BfrReference::BfrReference(const SubdivSurface& surface) : mImpl(std::make_unique<Impl>(*surface.mImpl)) {}
BfrReference::BfrReference(BfrReference&&) noexcept = default;
BfrReference& BfrReference::operator=(BfrReference&&) noexcept = default;
BfrReference::~BfrReference() = default;

bool BfrReference::hasLimitSurface(uint32_t face) const {
    return face < mImpl->surface.faceSizes.size() && mImpl->factory.FaceHasLimitSurface(Far::Index(face));
}

bool BfrReference::canEvaluate(uint32_t face) const {
    if (!hasLimitSurface(face)) return false;
    const Far::TopologyLevel& base = mImpl->surface.refiner->GetLevel(0);
    int valence2 = 0;
    for (Far::Index v : base.GetFaceVertices(Far::Index(face)))
        if (base.GetVertexFaces(v).size() == 2 && !base.IsVertexBoundary(v) && !base.IsVertexNonManifold(v)) ++valence2;
    return valence2 < 2;
}

std::optional<LimitPoint> BfrReference::evaluate(uint32_t face, glm::dvec2 uv) const {
    LimitPoint point;
    if (!evaluate(face, std::span<const glm::dvec2>(&uv, 1), std::span<LimitPoint>(&point, 1))) return std::nullopt;
    return point;
}

bool BfrReference::evaluate(uint32_t face, std::span<const glm::dvec2> uvs, std::span<LimitPoint> out) const {
    assert(out.size() >= uvs.size());
    if (!canEvaluate(face)) return false;
    Bfr::Surface<double> surface;
    if (!mImpl->factory.InitVertexSurface<double>(Far::Index(face), &surface)) return false;

    // Gather the face's control points (in double) and let Bfr derive the
    // rest of its patch points from them.
    const std::vector<glm::vec3>& base = mImpl->surface.basePositions;
    std::vector<Far::Index> controls(size_t(surface.GetNumControlPoints()));
    surface.GetControlPointIndices(controls.data());
    std::vector<double> patchPoints(size_t(surface.GetNumPatchPoints()) * 3);
    for (size_t i = 0; i < controls.size(); ++i)
        for (int c = 0; c < 3; ++c) patchPoints[3 * i + c] = double(base[size_t(controls[i])][c]);
    const Bfr::Surface<double>::PointDescriptor xyz(3);
    surface.ComputePatchPoints(patchPoints.data(), xyz);

    for (size_t i = 0; i < uvs.size(); ++i) {
        const double uv[2] = {uvs[i].x, uvs[i].y};
        double d[6][3];
        surface.Evaluate(uv, patchPoints.data(), xyz, d[0], d[1], d[2], d[3], d[4], d[5]);
        LimitPoint& p = out[i];
        glm::dvec3* fields[6] = {&p.position, &p.du, &p.dv, &p.duu, &p.duv, &p.dvv};
        for (int k = 0; k < 6; ++k) *fields[k] = glm::dvec3(d[k][0], d[k][1], d[k][2]);
    }
    return true;
}

} // namespace tessera::subdiv
