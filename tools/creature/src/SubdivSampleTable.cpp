#include "SubdivSampleTable.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

std::optional<LimitFrame> limitFrame(const subdiv::SubdivSurface& surface, uint32_t ptexFace, glm::dvec2 uv) {
    const std::optional<subdiv::LimitPoint> p = surface.evaluatePtex(ptexFace, uv);
    if (!p) return std::nullopt;
    const glm::dvec3 n = p->normal();
    const double len = glm::length(n);
    if (!(len > 1e-30)) return std::nullopt;
    return LimitFrame{p->position, n / len};
}

std::optional<float> castToSculpt(const Bvh& bvh, const LimitFrame& frame, float search) {
    const std::optional<BvhHit> hit =
        bvh.nearestHit(glm::vec3(frame.position), glm::vec3(frame.normal), -search, search, 0.0f);
    if (!hit) return std::nullopt;
    return hit->t;
}

SubdivSampleTable::SubdivSampleTable(const subdiv::SubdivSurface& surface, const subdiv::DisplacementTiles& tiles,
                                     const Bvh& bvh, float search, uint32_t threads)
    : mSurface(surface), mTiles(tiles), mBvh(bvh), mSearch(search) {
    mValues.assign(tiles.allCoefficients().size(), 0.0f);
    std::vector<uint8_t> hit(mValues.size(), 0);
    // Each tile writes only its own texels: the same table for any schedule.
    core::parallelFor(tiles.tileCount(), threads, [&](uint32_t t) {
        const uint32_t n = tiles.tileSize(t);
        const size_t first = tiles.firstCoefficient(t);
        for (uint32_t y = 0; y < n; ++y)
            for (uint32_t x = 0; x < n; ++x) {
                const glm::dvec2 uv((x + 0.5) / n, (y + 0.5) / n);
                const std::optional<LimitFrame> frame = limitFrame(surface, t, uv);
                const std::optional<float> d = frame ? castToSculpt(bvh, *frame, search) : std::nullopt;
                if (d) {
                    mValues[first + size_t(y) * n + x] = *d;
                    hit[first + size_t(y) * n + x] = 1;
                }
            }
    });
    for (uint8_t h : hit) mMisses += h ? 0 : 1;
    for (uint32_t t = 0; t < tiles.tileCount(); ++t) fillMisses(t, hit);
}

void SubdivSampleTable::fillMisses(uint32_t tile, std::vector<uint8_t>& hit) {
    const int n = int(mTiles.tileSize(tile));
    const size_t first = mTiles.firstCoefficient(tile);
    auto at = [&](int x, int y) { return first + size_t(y) * size_t(n) + size_t(x); };
    bool missing = true;
    while (missing) {
        missing = false;
        std::vector<std::pair<size_t, float>> filled;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                if (hit[at(x, y)]) continue;
                missing = true;
                float sum = 0.0f;
                int count = 0;
                for (glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
                    const int nx = x + d.x, ny = y + d.y;
                    if (nx < 0 || ny < 0 || nx >= n || ny >= n || !hit[at(nx, ny)]) continue;
                    sum += mValues[at(nx, ny)];
                    ++count;
                }
                if (count > 0) filled.emplace_back(at(x, y), sum / float(count));
            }
        if (filled.empty()) break;
        for (auto [index, value] : filled) {
            mValues[index] = value;
            hit[index] = 1;
            ++mFromNeighbours;
        }
    }
    if (!missing) return;
    // No hit anywhere in the tile: the limit surface itself (0).
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            if (!hit[at(x, y)]) {
                mValues[at(x, y)] = 0.0f;
                hit[at(x, y)] = 1;
                ++mZero;
            }
}

double SubdivSampleTable::sample(uint32_t ptexFace, glm::dvec2 uv) const {
    const uint32_t n = mTiles.tileSize(ptexFace);
    const glm::dvec2 texel = uv * double(n) - 0.5;
    const glm::dvec2 nearest = glm::clamp(glm::round(texel), glm::dvec2(0.0), glm::dvec2(n - 1));
    const size_t index = mTiles.firstCoefficient(ptexFace) + size_t(nearest.y) * n + size_t(nearest.x);
    if (glm::all(glm::lessThan(glm::abs(texel - nearest), glm::dvec2(1e-9)))) return mValues[index];
    const std::optional<LimitFrame> frame = limitFrame(mSurface, ptexFace, uv);
    const std::optional<float> d = frame ? castToSculpt(mBvh, *frame, mSearch) : std::nullopt;
    return d ? *d : mValues[index];
}

} // namespace tessera::creature
