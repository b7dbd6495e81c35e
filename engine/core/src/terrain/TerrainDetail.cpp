#include "tessera/terrain/TerrainDetail.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::terrain {
namespace {

// Steps of at most one sample spacing over `length` metres: every sample the
// surface bends at is then within half a spacing of a tested point.
uint32_t stepsOver(float length, float spacing) {
    return std::max(1u, static_cast<uint32_t>(std::ceil(length / spacing)));
}

} // namespace

TerrainDetail::TerrainDetail(const HeightField& field, const PatchGrid& grid)
    : mField(field), mGrid(grid), mEdgeError(grid.edgeCount(), 0.0f), mPatchError(grid.patchCount(), 0.0f) {
    // A full build samples the whole field about three times (2048^2 content:
    // tens of milliseconds), so it is spread over the cores. Every index writes
    // only its own entry and reads only the field, so the result does not
    // depend on the thread count.
    core::parallelFor(grid.edgeCount(), 0, [&](uint32_t e) { mEdgeError[e] = computeEdge(e); });
    core::parallelFor(grid.patchCount(), 0, [&](uint32_t p) { mPatchError[p] = computePatch(p); });
}

void TerrainDetail::update(const SampleRect& patches) {
    if (patches.empty()) return;
    const uint32_t p = mGrid.patchesPerSide();
    // A splat touches a few patches: serial is cheaper than starting threads.
    for (uint32_t z = patches.j0; z <= std::min(patches.j1, p - 1); ++z)
        for (uint32_t x = patches.i0; x <= std::min(patches.i1, p - 1); ++x) {
            const uint32_t patch = z * p + x;
            mPatchError[patch] = computePatch(patch);
            // Shared edges are recomputed once per neighbour; identical results.
            for (uint32_t edge : mGrid.patchEdges(patch)) mEdgeError[edge] = computeEdge(edge);
        }
}

float TerrainDetail::computeEdge(uint32_t edge) const {
    const auto [a, b] = mGrid.edgeEndpoints(edge);
    const float ha = mField.heightAt(a.x, a.y), hb = mField.heightAt(b.x, b.y);
    const uint32_t n = stepsOver(glm::length(b - a), mField.scale().horizontalSpacing);
    float error = 0.0f;
    // The endpoints match the straight edge exactly; test the points between.
    for (uint32_t k = 1; k < n; ++k) {
        const float t = float(k) / float(n);
        const glm::vec2 p = a + (b - a) * t;
        error = std::max(error, std::abs(mField.heightAt(p.x, p.y) - (ha + (hb - ha) * t)));
    }
    return error;
}

float TerrainDetail::computePatch(uint32_t patch) const {
    // Corners as grid coordinates times the patch size, exactly the floats
    // edgeEndpoints gives, so patch and edge errors share their corner heights.
    const uint32_t p = mGrid.patchesPerSide();
    const glm::vec2 size = mGrid.patchSize();
    const glm::vec2 lo = glm::vec2(float(patch % p), float(patch / p)) * size;
    const glm::vec2 hi = glm::vec2(float(patch % p + 1), float(patch / p + 1)) * size;
    const float h00 = mField.heightAt(lo.x, lo.y), h10 = mField.heightAt(hi.x, lo.y);
    const float h01 = mField.heightAt(lo.x, hi.y), h11 = mField.heightAt(hi.x, hi.y);
    const float spacing = mField.scale().horizontalSpacing;
    const uint32_t nu = stepsOver(size.x, spacing), nv = stepsOver(size.y, spacing);
    float error = 0.0f;
    // Interior points only: the border belongs to the edges (edgeError), so
    // this term raises the inner levels only where the inside is rough.
    for (uint32_t kv = 1; kv < nv; ++kv) {
        const float v = float(kv) / float(nv);
        for (uint32_t ku = 1; ku < nu; ++ku) {
            const float u = float(ku) / float(nu);
            const float near = h00 + (h10 - h00) * u, far = h01 + (h11 - h01) * u;
            const float h = mField.heightAt(lo.x + (hi.x - lo.x) * u, lo.y + (hi.y - lo.y) * v);
            error = std::max(error, std::abs(h - (near + (far - near) * v)));
        }
    }
    return error;
}

} // namespace tessera::terrain
