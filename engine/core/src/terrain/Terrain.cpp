#include "tessera/terrain/Terrain.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace tessera::terrain {
namespace {

struct Child {
    uint32_t x, z;
    float distanceSq;
};

// The up-to-four children of cell (x, z) one level down, nearest first (ties
// by index, so the order is deterministic), so that front-to-back drawing lets
// early depth testing reject hidden fragments.
uint32_t nearestChildren(const MinMaxPyramid& bounds, const glm::vec3& eye, uint32_t level, uint32_t x, uint32_t z,
                         std::array<Child, 4>& children) {
    const uint32_t size = bounds.levelSize(level - 1);
    uint32_t count = 0;
    for (uint32_t cz = 2 * z; cz < std::min(2 * z + 2, size); ++cz)
        for (uint32_t cx = 2 * x; cx < std::min(2 * x + 2, size); ++cx) {
            const glm::vec3 d = bounds.cellBounds(level - 1, cx, cz).center() - eye;
            children[count++] = {cx, cz, glm::dot(d, d)};
        }
    // Children are generated in index order, so a stable sort breaks ties by index.
    std::stable_sort(children.begin(), children.begin() + count,
                     [](const Child& a, const Child& b) { return a.distanceSq < b.distanceSq; });
    return count;
}

} // namespace

Terrain::Terrain(HeightField field, uint32_t patchesPerSide)
    // Heap-allocated so the references the derived objects keep stay valid.
    : mField(std::make_unique<HeightField>(std::move(field))),
      mGrid(std::make_unique<PatchGrid>(*mField, patchesPerSide)),
      mBounds(std::make_unique<MinMaxPyramid>(*mField, *mGrid)),
      mDetail(std::make_unique<TerrainDetail>(*mField, *mGrid)) {}

void Terrain::cull(const scene::Frustum& frustum, const glm::vec3& eye, std::vector<uint32_t>& visible) const {
    const uint32_t top = mBounds->levelCount() - 1;
    cullCell(frustum, eye, top, 0, 0, false, visible);
}

void Terrain::cullCell(const scene::Frustum& frustum, const glm::vec3& eye, uint32_t level, uint32_t x, uint32_t z,
                       bool inside, std::vector<uint32_t>& visible) const {
    if (!inside) {
        switch (frustum.classify(mBounds->cellBounds(level, x, z))) {
        case scene::Frustum::Containment::Outside: return;
        // Every child's box lies in this one, so all of them are inside too.
        case scene::Frustum::Containment::Inside: inside = true; break;
        case scene::Frustum::Containment::Intersects: break;
        }
    }
    if (inside) {
        appendAll(level, x, z, visible);
        return;
    }
    if (level == 0) {
        visible.push_back(z * mGrid->patchesPerSide() + x);
        return;
    }
    std::array<Child, 4> children{};
    const uint32_t count = nearestChildren(*mBounds, eye, level, x, z, children);
    for (uint32_t c = 0; c < count; ++c)
        cullCell(frustum, eye, level - 1, children[c].x, children[c].z, false, visible);
}

void Terrain::appendAll(uint32_t level, uint32_t x, uint32_t z, std::vector<uint32_t>& visible) const {
    // Row by row, with no frustum tests. Ordering the patches too would cost a
    // box and a sort per node, much of what skipping the tests saves; the
    // blocks themselves still come near to far.
    const uint32_t p = mGrid->patchesPerSide();
    const uint32_t x0 = x << level, z0 = z << level;
    const uint32_t x1 = std::min((x + 1) << level, p), z1 = std::min((z + 1) << level, p);
    for (uint32_t pz = z0; pz < z1; ++pz)
        for (uint32_t px = x0; px < x1; ++px) visible.push_back(pz * p + px);
}

SampleRect Terrain::splat(const CraterSplat& crater) {
    const SampleRect samples = applyCrater(*mField, crater);
    // Bounds and detail change only where the surface does: the patches
    // interpolating a changed sample.
    const SampleRect patches = mGrid->patchesTouching(samples);
    mBounds->update(patches);
    mDetail->update(patches);
    mHistory.push_back(crater);
    ++mRevision;
    return samples;
}

std::vector<CraterSplat> Terrain::takePendingSplats() {
    std::vector<CraterSplat> pending(mHistory.begin() + std::ptrdiff_t(mPendingFrom), mHistory.end());
    mPendingFrom = mHistory.size();
    return pending;
}

} // namespace tessera::terrain
