#pragma once
/// @file CascadeSplits.h
/// Where a view's shadow cascades begin and end: the practical split scheme.

#include <cstdint>
#include <vector>

namespace tessera::scene {

/// The distances along the view axis that cut [nearDistance, farDistance]
/// into `count` cascades with the practical split scheme (Zhang et al.,
/// "Parallel-Split Shadow Maps", 2006; the Froblins' cascades): split i of
/// `count` is `lambda * n * (f / n)^(i / count) + (1 - lambda) * (n + (f - n)
/// * i / count)`, a blend of the logarithmic scheme (lambda = 1: every
/// cascade spends its texels on the same range of screen sizes, so near
/// cascades get very thin) and the uniform one (lambda = 0: distant texels
/// as sharp as near ones, wasted).
///
/// Returns `count + 1` increasing distances, the first `nearDistance` and the
/// last `farDistance` exactly. Asserts 0 < nearDistance < farDistance,
/// count >= 1 and 0 <= lambda <= 1.
std::vector<float> practicalCascadeSplits(float nearDistance, float farDistance, uint32_t count, float lambda);

} // namespace tessera::scene
