#include "tessera/tessellator/Tessellator.h"

#include "PatchFactors.h"
#include "QuadPattern.h"
#include "TrianglePattern.h"

namespace tessera::tessellator {
namespace {

// The reference tessellator lists each triangle "clockwise" as D3D draws its
// domain (u right, v up in the reference's own (u, v) numbers: the first quad
// triangle is (0,0), (1,0), (0,1)). Vulkan's default `ccw` with the upper-left
// domain origin is the opposite order, as lavapipe's transform-feedback output
// shows, so every triangle is emitted reversed.
constexpr bool kReverseReferenceWinding = true;

} // namespace

TessellatedPatch Tessellator::tessellate(Domain domain, Partitioning partitioning, const TessFactors& factors) {
    const detail::PatchFactors processed(domain, partitioning, factors);
    if (processed.culled()) return {};
    return domain == Domain::Quad ? detail::QuadPattern::build(processed, kReverseReferenceWinding)
                                  : detail::TrianglePattern::build(processed, kReverseReferenceWinding);
}

uint32_t Tessellator::countTriangles(Domain domain, Partitioning partitioning, const TessFactors& factors) {
    const detail::PatchFactors processed(domain, partitioning, factors);
    return domain == Domain::Quad ? detail::QuadPattern::countTriangles(processed)
                                  : detail::TrianglePattern::countTriangles(processed);
}

uint32_t Tessellator::countPoints(Domain domain, Partitioning partitioning, const TessFactors& factors) {
    const detail::PatchFactors processed(domain, partitioning, factors);
    return domain == Domain::Quad ? detail::QuadPattern::countPoints(processed)
                                  : detail::TrianglePattern::countPoints(processed);
}

} // namespace tessera::tessellator
