#include "tessera/subdiv/SubdivSurface.h"

#include "OsdMessages.h"
#include "ShapeRefiner.h"
#include "SubdivSurfaceImpl.h"

#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/stencilTableFactory.h>

#include <cassert>
#include <cmath>

namespace tessera::subdiv {

namespace {

using detail::OsdPoint;

Far::PatchTableFactory::Options patchOptions(const SubdivSettings& settings) {
    Far::PatchTableFactory::Options options(settings.isolationLevel);
    options.SetEndCapType(settings.endCap == EndCap::GregoryBasis
                              ? Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS
                              : Far::PatchTableFactory::Options::ENDCAP_BSPLINE_BASIS);
    // Must match the refinement (ShapeRefiner.cpp).
    options.useInfSharpPatch = true;
    options.useSingleCreasePatch = false;
    // Adjacent Gregory patches share their edge points, so both sides of an
    // end-cap edge read the same control points.
    options.shareEndCapPatchPoints = true;
    // The legacy option makes smooth corners sharp; Bfr (and the true limit
    // surface) do not.
    options.generateLegacySharpCornerPatches = false;
    options.generateVaryingTables = false;
    return options;
}

// Base vertices to everything the patches index: identity rows for the base
// vertices, every refined level, then the local points, all factorized to
// base vertices so an update is one pass. Through the float instantiation
// (StencilTableReal<float>), not the compatibility StencilTable: Far's
// wrappers static_cast the tables they build to that subclass, which UBSan's
// vptr check rightly reports (the object is never a StencilTable).
std::unique_ptr<const FloatStencils> createStencils(const Far::TopologyRefiner& refiner,
                                                    const Far::PatchTable& patchTable) {
    using Factory = Far::StencilTableFactoryReal<float>;
    Factory::Options options;
    options.generateOffsets = true;
    options.generateControlVerts = true;
    options.generateIntermediateLevels = true;
    options.factorizeIntermediateLevels = true;
    std::unique_ptr<const FloatStencils> vertices(Factory::Create(refiner, options));
    const FloatStencils* local = patchTable.GetLocalPointStencilTable<float>();
    if (!local || local->GetNumStencils() == 0) return vertices;
    return std::unique_ptr<const FloatStencils>(Factory::AppendLocalPointStencilTable(refiner, vertices.get(), local));
}

bool finite(const glm::vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

} // namespace

Result<SubdivSurface> SubdivSurface::create(const ObjShape& shape, const SubdivSettings& settings) {
    if (Status valid = detail::validateShape(shape, settings); !valid) return valid.error();
    Result<std::unique_ptr<Far::TopologyRefiner>> refiner = detail::createRefiner(shape, settings);
    if (!refiner) return refiner.error();

    auto impl = std::make_unique<Impl>();
    impl->name = shape.name;
    impl->settings = settings;
    impl->faceSizes = shape.faceSizes;
    impl->basePositions = shape.positions;
    impl->refiner = std::move(refiner.value());
    const Far::TopologyRefiner& topology = *impl->refiner;

    {
        detail::OsdMessages messages;
        impl->patchTable.reset(Far::PatchTableFactory::Create(topology, patchOptions(settings)));
        if (impl->patchTable) impl->stencils = createStencils(topology, *impl->patchTable);
        if (!impl->patchTable || !impl->stencils || !messages.empty())
            return fail(shape.name, ": OpenSubdiv cannot build the patches: ",
                        messages.empty() ? std::string("no reason given") : messages.joined());
    }
    const Far::PatchTable& table = *impl->patchTable;
    impl->refinedVertexCount = uint32_t(topology.GetNumVerticesTotal());
    impl->localPointCount = uint32_t(table.GetNumLocalPoints());
    const uint32_t pointCount = impl->refinedVertexCount + impl->localPointCount;
    assert(uint32_t(impl->stencils->GetNumStencils()) == pointCount);

    Result<detail::PatchArrays> patches = detail::PatchArrays::fromTable(table, pointCount, shape.name);
    if (!patches) return patches.error();
    impl->patches = std::move(patches.value());
    if (!impl->patches.patches.empty()) impl->patchMap = std::make_unique<Far::PatchMap>(table);

    const Far::PtexIndices ptex(topology);
    for (uint32_t f = 0; f < shape.faceCount(); ++f) impl->firstPtex.push_back(uint32_t(ptex.GetFaceId(int(f))));
    impl->firstPtex.push_back(uint32_t(ptex.GetNumFaces()));

    // The first control points come from refining level by level and
    // Far's local-point stencils, independently of the factorized table
    // updates use, so the tests cross-check the two.
    std::vector<OsdPoint>& points = impl->scratch;
    points.resize(pointCount);
    for (size_t v = 0; v < shape.positions.size(); ++v)
        points[v] = {shape.positions[v].x, shape.positions[v].y, shape.positions[v].z};
    const Far::PrimvarRefinerReal<float> primvar(topology);
    OsdPoint* source = points.data();
    for (int level = 1; level <= topology.GetMaxLevel(); ++level) {
        OsdPoint* destination = source + topology.GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, source, destination);
        source = destination;
    }
    if (impl->localPointCount > 0)
        table.ComputeLocalPointValues(points.data(), points.data() + impl->refinedVertexCount);
    impl->publishControlPoints();
    return SubdivSurface(std::move(impl));
}

SubdivSurface::SubdivSurface(std::unique_ptr<Impl> impl) : mImpl(std::move(impl)) {}
SubdivSurface::SubdivSurface(SubdivSurface&&) noexcept = default;
SubdivSurface& SubdivSurface::operator=(SubdivSurface&&) noexcept = default;
SubdivSurface::~SubdivSurface() = default;

void SubdivSurface::Impl::publishControlPoints() {
    controlPoints.resize(scratch.size());
    for (size_t i = 0; i < scratch.size(); ++i) controlPoints[i] = {scratch[i].x, scratch[i].y, scratch[i].z};
    bounds = scene::Aabb::empty();
    for (uint32_t index : patches.indices) bounds.expand(controlPoints[index]);
}

Status SubdivSurface::updateControlPoints(std::span<const glm::vec3> basePositions) {
    Impl& impl = *mImpl;
    if (basePositions.size() != impl.basePositions.size())
        return fail(impl.name, ": ", std::to_string(basePositions.size()), " base positions given for ",
                    std::to_string(impl.basePositions.size()), " vertices");
    for (size_t v = 0; v < basePositions.size(); ++v)
        if (!finite(basePositions[v])) return fail(impl.name, ": base vertex ", std::to_string(v), " is not finite");
    impl.basePositions.assign(basePositions.begin(), basePositions.end());
    std::vector<OsdPoint> base(basePositions.size());
    for (size_t v = 0; v < base.size(); ++v) base[v] = {basePositions[v].x, basePositions[v].y, basePositions[v].z};
    impl.stencils->UpdateValues(base.data(), impl.scratch.data());
    impl.publishControlPoints();
    return {};
}

RefineStencils SubdivSurface::refineStencils() const {
    const FloatStencils& table = *mImpl->stencils;
    RefineStencils result;
    for (int i = 0; i < table.GetNumStencils(); ++i) {
        const Far::StencilReal<float> stencil = table.GetStencil(Far::Index(i));
        result.offsets.push_back(uint32_t(result.indices.size()));
        result.sizes.push_back(uint32_t(stencil.GetSize()));
        for (int k = 0; k < stencil.GetSize(); ++k) {
            result.indices.push_back(uint32_t(stencil.GetVertexIndices()[k]));
            result.weights.push_back(stencil.GetWeights()[k]);
        }
    }
    return result;
}

const std::string& SubdivSurface::name() const {
    return mImpl->name;
}
const SubdivSettings& SubdivSurface::settings() const {
    return mImpl->settings;
}
uint32_t SubdivSurface::baseVertexCount() const {
    return uint32_t(mImpl->basePositions.size());
}
uint32_t SubdivSurface::baseFaceCount() const {
    return uint32_t(mImpl->faceSizes.size());
}
uint32_t SubdivSurface::baseFaceSize(uint32_t face) const {
    return mImpl->faceSizes.at(face);
}
bool SubdivSurface::isHole(uint32_t face) const {
    return face < baseFaceCount() && mImpl->refiner->GetLevel(0).IsFaceHole(Far::Index(face));
}
std::span<const glm::vec3> SubdivSurface::basePositions() const {
    return mImpl->basePositions;
}
std::span<const glm::vec3> SubdivSurface::controlPoints() const {
    return mImpl->controlPoints;
}
uint32_t SubdivSurface::refinedVertexCount() const {
    return mImpl->refinedVertexCount;
}
uint32_t SubdivSurface::localPointCount() const {
    return mImpl->localPointCount;
}
uint32_t SubdivSurface::maxDepth() const {
    return uint32_t(mImpl->refiner->GetMaxLevel());
}
std::span<const Patch> SubdivSurface::patches() const {
    return mImpl->patches.patches;
}
std::span<const uint32_t> SubdivSurface::patchPointIndices() const {
    return mImpl->patches.indices;
}
std::span<const PatchRange> SubdivSurface::patchRanges() const {
    return mImpl->patches.ranges;
}
uint32_t SubdivSurface::ptexFaceCount() const {
    return mImpl->firstPtex.back();
}
uint32_t SubdivSurface::firstPtexFace(uint32_t face) const {
    return mImpl->firstPtex.at(face);
}
scene::Aabb SubdivSurface::bounds() const {
    return mImpl->bounds;
}

std::span<const uint32_t> SubdivSurface::patchPoints(uint32_t patch) const {
    const Patch& p = mImpl->patches.patches.at(patch);
    return std::span<const uint32_t>(mImpl->patches.indices).subspan(p.firstIndex, controlPointsOf(p.type));
}

double SubdivSurface::boundsDiagonal() const {
    const scene::Aabb& b = mImpl->bounds;
    return b.isEmpty() ? 0.0 : glm::length(glm::dvec3(b.max) - glm::dvec3(b.min));
}

} // namespace tessera::subdiv
