#include "ThermalErosion.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cassert>

namespace tessera::terrain {
namespace {

// Share of the excess over the talus height moved per neighbour pair and pass.
// With 8 neighbours, 0.1 keeps the explicit update stable (a sample can never
// give away more than its excess, so no oscillation).
constexpr float kTransferRate = 0.1f;
constexpr uint32_t kRowsPerItem = 16;

// The talus height to a diagonal neighbour is sqrt(2) times longer.
constexpr float kSqrt2 = 1.41421356f;

struct Neighbour {
    int dx, dy;
    bool diagonal;
};

constexpr Neighbour kNeighbours[8] = {{-1, -1, true}, {0, -1, false}, {1, -1, true},
                                      {-1, 0, false}, {1, 0, false},  {-1, 1, true},
                                      {0, 1, false},  {1, 1, true}};

// Material moving from the higher to the lower of two samples, signed so that
// a positive value flows into `centre`. Branch-free (the branches were
// unpredictable) and written so that swapping the pair flips only the sign
// (IEEE a - b == -(b - a)), which keeps mass exact.
float transfer(float centre, float neighbour, float talusHeight) {
    float difference = neighbour - centre;
    return kTransferRate * (std::max(0.0f, difference - talusHeight) -
                            std::max(0.0f, -difference - talusHeight));
}

float relaxSample(const float* in, uint32_t size, uint32_t x, uint32_t y, float talusSlope) {
    const float centre = in[size_t(y) * size + x];
    const float straight = talusSlope, diagonal = talusSlope * kSqrt2;
    const bool interior = x > 0 && y > 0 && x + 1 < size && y + 1 < size;
    float change = 0.0f;
    if (interior) {
        // Same neighbour order as the border path below, so both give the
        // same float sum for the same inputs.
        const float* up = in + size_t(y - 1) * size + x;
        const float* mid = up + size;
        const float* down = mid + size;
        change += transfer(centre, up[-1], diagonal);
        change += transfer(centre, up[0], straight);
        change += transfer(centre, up[1], diagonal);
        change += transfer(centre, mid[-1], straight);
        change += transfer(centre, mid[1], straight);
        change += transfer(centre, down[-1], diagonal);
        change += transfer(centre, down[0], straight);
        change += transfer(centre, down[1], diagonal);
        return centre + change;
    }
    const int last = int(size) - 1;
    for (const Neighbour& n : kNeighbours) {
        int nx = int(x) + n.dx, ny = int(y) + n.dy;
        if (nx < 0 || ny < 0 || nx > last || ny > last) continue;
        change += transfer(centre, in[size_t(ny) * size + size_t(nx)], n.diagonal ? diagonal : straight);
    }
    return centre + change;
}

void relaxRows(const float* in, float* out, uint32_t size, uint32_t rowBegin, uint32_t rowEnd,
               float talusSlope) {
    for (uint32_t y = rowBegin; y < rowEnd; ++y)
        for (uint32_t x = 0; x < size; ++x)
            out[size_t(y) * size + x] = relaxSample(in, size, x, y, talusSlope);
}

} // namespace

void erodeThermal(std::vector<float>& heights, uint32_t size, uint32_t iterations,
                  float talusSlope, uint32_t threadCount,
                  const std::function<void(float)>& onProgress) {
    assert(heights.size() == size_t(size) * size);
    std::vector<float> scratch(heights.size());
    const uint32_t items = (size + kRowsPerItem - 1) / kRowsPerItem;
    for (uint32_t pass = 0; pass < iterations; ++pass) {
        const float* in = heights.data();
        float* out = scratch.data();
        core::parallelFor(items, threadCount, [&](uint32_t item) {
            uint32_t begin = item * kRowsPerItem;
            relaxRows(in, out, size, begin, std::min(size, begin + kRowsPerItem), talusSlope);
        });
        heights.swap(scratch);
        if (onProgress) onProgress(float(pass + 1) / float(iterations));
    }
}

} // namespace tessera::terrain
