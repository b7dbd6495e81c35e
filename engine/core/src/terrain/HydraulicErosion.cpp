#include "HydraulicErosion.h"

#include "tessera/core/ParallelFor.h"
#include "tessera/core/Random.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::terrain {
namespace {

// Droplet model constants: Beyer's / Lague's published defaults, except the
// two that are not scale-free. Those defaults assume heights in 0..1 on a
// 256-sample map, where slopes are about 19x smaller than slopes in our cell
// units (600 m over 8192 m); gravity is scaled down and the minimum capacity
// up by that factor so droplets behave as in the reference.
constexpr int kLifetime = 30;           // Steps of at most one cell each.
constexpr int kRadius = 3;              // Erosion brush radius in cells.
constexpr float kInertia = 0.05f;       // Share of the old direction kept per step.
constexpr float kCapacityFactor = 4.0f; // Sediment per unit of descent x speed x water.
constexpr float kMinCapacity = 0.2f;    // Lets slow droplets on flats still carry a little.
constexpr float kErodeRate = 0.3f;      // Share of the free capacity eroded per step.
constexpr float kDepositRate = 0.3f;    // Share of the excess sediment dropped per step.
constexpr float kEvaporation = 0.02f;   // Share of the water lost per step.
constexpr float kGravity = 0.2f;

// Tiles are kTileSize cells on a side when the map has at least two per side.
// A droplet never reaches further than kLifetime + kRadius + 1 cells from its
// start, which must stay below half a tile so that same-colour tiles (a whole
// tile apart) never touch the same sample.
constexpr uint32_t kTileSize = 128;
constexpr uint32_t kPasses = 4;
static_assert(kLifetime + kRadius + 1 < int(kTileSize / 2));

struct BrushTap {
    int dx, dy;
    float weight;
};

// Weights fall off linearly with distance and sum to one, so a brush removes
// exactly the amount asked for (less where it hangs over the map edge).
std::vector<BrushTap> makeBrush() {
    std::vector<BrushTap> taps;
    float total = 0.0f;
    for (int dy = -kRadius; dy <= kRadius; ++dy) {
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
            float distance = std::sqrt(float(dx * dx + dy * dy));
            if (distance >= float(kRadius)) continue;
            float weight = 1.0f - distance / float(kRadius);
            taps.push_back({dx, dy, weight});
            total += weight;
        }
    }
    for (BrushTap& tap : taps) tap.weight /= total;
    return taps;
}

struct HeightAndGradient {
    float height, gradX, gradY;
};

// Bilinear height and its gradient at (x, y); requires 0 <= x, y < size - 1.
HeightAndGradient sample(const float* map, uint32_t size, float x, float y) {
    int ix = int(x), iy = int(y);
    float fx = x - float(ix), fy = y - float(iy);
    const float* p = map + size_t(iy) * size + size_t(ix);
    float nw = p[0], ne = p[1], sw = p[size], se = p[size + 1];
    return {nw * (1 - fx) * (1 - fy) + ne * fx * (1 - fy) + sw * (1 - fx) * fy + se * fx * fy,
            (ne - nw) * (1 - fy) + (se - sw) * fy, (sw - nw) * (1 - fx) + (se - ne) * fx};
}

class DropletSimulator {
public:
    DropletSimulator(float* map, uint32_t size, const std::vector<BrushTap>& brush)
        : mMap(map), mSize(size), mBrush(brush) {}

    void run(float x, float y) {
        const float limit = float(mSize - 1);
        float dirX = 0.0f, dirY = 0.0f, speed = 1.0f, water = 1.0f, sediment = 0.0f;
        for (int step = 0; step < kLifetime; ++step) {
            int nodeX = int(x), nodeY = int(y);
            float cellX = x - float(nodeX), cellY = y - float(nodeY);
            HeightAndGradient here = sample(mMap, mSize, x, y);

            dirX = dirX * kInertia - here.gradX * (1.0f - kInertia);
            dirY = dirY * kInertia - here.gradY * (1.0f - kInertia);
            float length = std::sqrt(dirX * dirX + dirY * dirY);
            if (length == 0.0f) break; // A perfectly flat spot: nowhere to go.
            dirX /= length;
            dirY /= length;
            x += dirX;
            y += dirY;
            if (x < 0.0f || y < 0.0f || x >= limit || y >= limit) break;

            float deltaHeight = sample(mMap, mSize, x, y).height - here.height;
            float capacity = std::max(-deltaHeight * speed * water * kCapacityFactor, kMinCapacity);
            if (sediment > capacity || deltaHeight > 0.0f) {
                // Uphill: fill the pit behind up to the step (not more, or the
                // droplet would build a mound). Otherwise drop part of the excess.
                float amount = deltaHeight > 0.0f ? std::min(deltaHeight, sediment)
                                                  : (sediment - capacity) * kDepositRate;
                sediment -= amount;
                deposit(nodeX, nodeY, cellX, cellY, amount);
            } else {
                // Never erode more than the descent, or the droplet digs a hole.
                float amount = std::min((capacity - sediment) * kErodeRate, -deltaHeight);
                sediment += erode(nodeX, nodeY, amount);
            }
            speed = std::sqrt(std::max(0.0f, speed * speed - deltaHeight * kGravity));
            water *= 1.0f - kEvaporation;
        }
    }

private:
    void deposit(int nodeX, int nodeY, float cellX, float cellY, float amount) {
        float* p = mMap + size_t(nodeY) * mSize + size_t(nodeX);
        p[0] += amount * (1 - cellX) * (1 - cellY);
        p[1] += amount * cellX * (1 - cellY);
        p[mSize] += amount * (1 - cellX) * cellY;
        p[mSize + 1] += amount * cellX * cellY;
    }

    float erode(int nodeX, int nodeY, float amount) {
        float removed = 0.0f;
        const int size = int(mSize);
        const bool interior = nodeX >= kRadius && nodeY >= kRadius && nodeX < size - kRadius &&
                              nodeY < size - kRadius;
        float* centre = mMap + size_t(nodeY) * mSize + size_t(nodeX);
        for (const BrushTap& tap : mBrush) {
            // Away from the border (nearly always) skip the per-tap bounds test.
            if (!interior) {
                int bx = nodeX + tap.dx, by = nodeY + tap.dy;
                if (bx < 0 || by < 0 || bx >= size || by >= size) continue;
            }
            float& h = centre[tap.dy * size + tap.dx];
            float take = std::min(h, amount * tap.weight);
            h -= take;
            removed += take;
        }
        return removed;
    }

    float* mMap;
    uint32_t mSize;
    const std::vector<BrushTap>& mBrush;
};

} // namespace

void erodeHydraulic(std::vector<float>& heights, uint32_t size, uint32_t dropletCount,
                    uint64_t seed, uint32_t threadCount,
                    const std::function<void(float)>& onProgress) {
    assert(heights.size() == size_t(size) * size);
    if (dropletCount == 0) return;
    const std::vector<BrushTap> brush = makeBrush();
    const uint32_t tilesPerSide = size >= 2 * kTileSize ? size / kTileSize : 1;
    const uint32_t tileSize = size / tilesPerSide;
    const uint32_t tileCount = tilesPerSide * tilesPerSide;
    const uint32_t itemCount = kPasses * tileCount;

    // Tiles of each checkerboard colour, in a fixed order.
    std::vector<uint32_t> colours[4];
    for (uint32_t t = 0; t < tileCount; ++t)
        colours[(t % tilesPerSide & 1u) + 2u * (t / tilesPerSide & 1u)].push_back(t);

    uint32_t itemsDone = 0;
    for (uint32_t pass = 0; pass < kPasses; ++pass) {
        for (const std::vector<uint32_t>& tiles : colours) {
            auto runTile = [&](uint32_t k) {
                const uint32_t tile = tiles[k];
                // The droplet budget is split over (pass, tile) items in a fixed
                // order; the first `remainder` items take one extra droplet.
                const uint32_t item = pass * tileCount + tile;
                const uint32_t count = dropletCount / itemCount + (item < dropletCount % itemCount);
                const float originX = float(tile % tilesPerSide * tileSize);
                const float originY = float(tile / tilesPerSide * tileSize);
                Random random(seed, item);
                DropletSimulator droplets(heights.data(), size, brush);
                for (uint32_t d = 0; d < count; ++d) {
                    float x, y;
                    do { // Redraw the rare start on the last row/column (no cell there).
                        x = originX + random.range(0.0f, float(tileSize));
                        y = originY + random.range(0.0f, float(tileSize));
                    } while (x >= float(size - 1) || y >= float(size - 1));
                    droplets.run(x, y);
                }
            };
            const uint32_t before = itemsDone;
            core::parallelFor(uint32_t(tiles.size()), threadCount, runTile, [&](uint32_t done) {
                if (onProgress) onProgress(float(before + done) / float(itemCount));
            });
            itemsDone += uint32_t(tiles.size());
        }
    }
}

} // namespace tessera::terrain
