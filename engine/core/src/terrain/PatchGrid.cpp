#include "tessera/terrain/PatchGrid.h"

#include "tessera/shaders/TerrainPatches.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace tessera::terrain {
namespace {

// Sample index of a world coordinate, rounded down or up and clamped to the
// field. Works in double and clamps before converting so that huge or
// negative inputs cannot overflow the integer.
uint32_t sampleIndex(double world, double spacing, uint32_t count, bool roundUp) {
    double s = world / spacing;
    s = roundUp ? std::ceil(s) : std::floor(s);
    return static_cast<uint32_t>(std::clamp(s, 0.0, double(count - 1)));
}

// Patch index containing a world coordinate, clamped to the grid.
uint32_t patchIndex(double world, double patchSize, uint32_t patchesPerSide) {
    return static_cast<uint32_t>(std::clamp(std::floor(world / patchSize), 0.0, double(patchesPerSide - 1)));
}

// One axis of the patch grid: patches of `patchSize` metres over `sampleCount`
// samples `spacing` apart.
struct Axis {
    float patchSize;
    double spacing;
    uint32_t sampleCount;
    uint32_t patchesPerSide;

    // Samples column x interpolates: floor of its lower corner to ceil of its
    // upper one. The upper corner is the next column's origin, computed the
    // same way (float(index) * size), so neighbours agree on the boundary.
    std::pair<uint32_t, uint32_t> samples(uint32_t x) const {
        return {sampleIndex(float(x) * patchSize, spacing, sampleCount, false),
                sampleIndex(float(x + 1) * patchSize, spacing, sampleCount, true)};
    }

    // Columns whose samples() meet [first, last]. A guess widened by two
    // samples each way, trimmed with samples() itself, the function that
    // defines the dependency, so float rounding at a boundary can neither drop
    // a column nor add one.
    std::pair<uint32_t, uint32_t> columnsTouching(uint32_t first, uint32_t last) const {
        uint32_t lo = patchIndex((double(first) - 2.0) * spacing, patchSize, patchesPerSide);
        uint32_t hi = patchIndex((double(last) + 2.0) * spacing, patchSize, patchesPerSide);
        while (lo < hi && samples(lo).second < first) ++lo;
        while (hi > lo && samples(hi).first > last) --hi;
        return {lo, hi};
    }
};

} // namespace

PatchGrid::PatchGrid(const HeightField& field, uint32_t patchesPerSide)
    : mField(field), mPatchesPerSide(patchesPerSide), mPatchSize(field.worldSize() / float(patchesPerSide)) {
    assert(patchesPerSide >= 1);
}

uint32_t PatchGrid::edgeCount() const {
    return shader::tsEdgeCount(mPatchesPerSide);
}

glm::vec2 PatchGrid::patchOrigin(uint32_t patch) const {
    assert(patch < patchCount());
    // float(index) * size everywhere (bounds, edges, pyramid cells), so the
    // corner two patches share is the same float in both.
    return glm::vec2(float(patch % mPatchesPerSide), float(patch / mPatchesPerSide)) * mPatchSize;
}

std::array<uint32_t, 4> PatchGrid::patchEdges(uint32_t patch) const {
    assert(patch < patchCount());
    const uint32_t x = patch % mPatchesPerSide, z = patch / mPatchesPerSide;
    std::array<uint32_t, 4> edges{};
    for (uint32_t side = 0; side < 4; ++side) edges[side] = shader::tsPatchEdge(x, z, side, mPatchesPerSide);
    return edges;
}

std::array<glm::vec2, 2> PatchGrid::edgeEndpoints(uint32_t edge) const {
    assert(edge < edgeCount());
    glm::vec2 along{0.0f};
    const glm::vec2 start = shader::tsEdgeStart(edge, mPatchesPerSide, along);
    return {start * mPatchSize, (start + along) * mPatchSize};
}

SampleRect PatchGrid::patchSamples(uint32_t patch) const {
    assert(patch < patchCount());
    const double s = mField.scale().horizontalSpacing;
    const auto [i0, i1] = Axis{mPatchSize.x, s, mField.width(), mPatchesPerSide}.samples(patch % mPatchesPerSide);
    const auto [j0, j1] = Axis{mPatchSize.y, s, mField.height(), mPatchesPerSide}.samples(patch / mPatchesPerSide);
    return {i0, j0, i1, j1};
}

SampleRect PatchGrid::patchesTouching(const SampleRect& samples) const {
    if (samples.empty()) return {};
    const double s = mField.scale().horizontalSpacing;
    const auto [x0, x1] =
        Axis{mPatchSize.x, s, mField.width(), mPatchesPerSide}.columnsTouching(samples.i0, samples.i1);
    const auto [z0, z1] =
        Axis{mPatchSize.y, s, mField.height(), mPatchesPerSide}.columnsTouching(samples.j0, samples.j1);
    return {x0, z0, x1, z1};
}

} // namespace tessera::terrain
