#include "tessera/scene/CascadeSplits.h"

#include <cassert>
#include <cmath>

namespace tessera::scene {

std::vector<float> practicalCascadeSplits(float nearDistance, float farDistance, uint32_t count, float lambda) {
    assert(nearDistance > 0.0f && nearDistance < farDistance && "practicalCascadeSplits: need 0 < near < far");
    assert(count >= 1 && "practicalCascadeSplits: need at least one cascade");
    assert(lambda >= 0.0f && lambda <= 1.0f && "practicalCascadeSplits: lambda outside 0..1");
    std::vector<float> splits(count + 1);
    // In double: (f / n)^(i / count) over a 20 km far plane and a 0.5 m near
    // one loses the last digits in float, and the ends must be exact.
    const double n = nearDistance;
    const double f = farDistance;
    for (uint32_t i = 1; i < count; ++i) {
        const double t = double(i) / double(count);
        const double logarithmic = n * std::pow(f / n, t);
        const double uniform = n + (f - n) * t;
        splits[i] = float(lambda * logarithmic + (1.0 - lambda) * uniform);
    }
    splits.front() = nearDistance;
    splits.back() = farDistance;
    return splits;
}

} // namespace tessera::scene
