#include "tessera/terrain/TerrainTiles.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::terrain {

TerrainTiles::TerrainTiles(scene::SceneGraph& scene, const HeightField& field, uint32_t tilesPerSide)
    : mScene(scene), mField(field), mTilesPerSide(tilesPerSide) {
    assert(tilesPerSide > 0);
    mRoot = scene.createNode("terrain");
    mNodes.reserve(tileCount());
    for (uint32_t t = 0; t < tileCount(); ++t) {
        scene::NodeId node = scene.createNode("terrain.tile" + std::to_string(t), mRoot);
        scene.setTag(node, kNodeKind, t);
        mNodes.push_back(node);
        computeBounds(t);
    }
    scene.updateTransforms();
}

const scene::Aabb& TerrainTiles::tileBounds(uint32_t tile) const { return mScene.node(mNodes[tile]).worldBounds; }

void TerrainTiles::computeBounds(uint32_t tile) {
    const uint32_t tx = tile % mTilesPerSide, tz = tile / mTilesPerSide;
    const glm::vec2 size = mField.worldSize();
    const float tileX = size.x / float(mTilesPerSide), tileZ = size.y / float(mTilesPerSide);
    const float spacing = mField.scale().horizontalSpacing;
    // Every sample the tile's surface can interpolate lies in this rectangle.
    auto sampleIndex = [&](float world, uint32_t limit, bool upper) {
        float s = world / spacing;
        long v = upper ? long(std::ceil(s)) : long(std::floor(s));
        return uint32_t(std::clamp<long>(v, 0, long(limit) - 1));
    };
    const uint32_t i0 = sampleIndex(tx * tileX, mField.width(), false), i1 = sampleIndex((tx + 1) * tileX, mField.width(), true);
    const uint32_t j0 = sampleIndex(tz * tileZ, mField.height(), false), j1 = sampleIndex((tz + 1) * tileZ, mField.height(), true);
    auto [lo, hi] = mField.minMaxHeight(i0, j0, i1, j1);
    mScene.setLocalBounds(mNodes[tile], scene::Aabb::fromMinMax({tx * tileX, lo, tz * tileZ},
                                                                {(tx + 1) * tileX, hi, (tz + 1) * tileZ}));
}

void TerrainTiles::refreshBounds(uint32_t i0, uint32_t j0, uint32_t i1, uint32_t j1) {
    const glm::vec2 size = mField.worldSize();
    const float spacing = mField.scale().horizontalSpacing;
    const float tileX = size.x / float(mTilesPerSide), tileZ = size.y / float(mTilesPerSide);
    auto tileOf = [&](uint32_t sample, float tileSize) {
        return std::min<uint32_t>(uint32_t(float(sample) * spacing / tileSize), mTilesPerSide - 1);
    };
    // A sample on a tile border belongs to both neighbours; widen by one.
    const uint32_t tx0 = tileOf(i0 ? i0 - 1 : 0, tileX), tx1 = tileOf(i1 + 1, tileX);
    const uint32_t tz0 = tileOf(j0 ? j0 - 1 : 0, tileZ), tz1 = tileOf(j1 + 1, tileZ);
    for (uint32_t tz = tz0; tz <= tz1; ++tz)
        for (uint32_t tx = tx0; tx <= tx1; ++tx) computeBounds(tz * mTilesPerSide + tx);
    mScene.updateTransforms();
}

void TerrainTiles::cull(const scene::Frustum& frustum, const glm::vec3& eye, std::vector<uint32_t>& visible) const {
    mScratch.clear();
    mScene.cull(frustum, mScratch);
    const size_t first = visible.size();
    for (scene::NodeId id : mScratch) {
        const auto& node = mScene.node(id);
        if (node.kind == kNodeKind) visible.push_back(node.payload);
    }
    std::sort(visible.begin() + static_cast<std::ptrdiff_t>(first), visible.end(), [&](uint32_t a, uint32_t b) {
        const float da = glm::dot(tileBounds(a).center() - eye, tileBounds(a).center() - eye);
        const float db = glm::dot(tileBounds(b).center() - eye, tileBounds(b).center() - eye);
        return da != db ? da < db : a < b;
    });
}

} // namespace tessera::terrain
