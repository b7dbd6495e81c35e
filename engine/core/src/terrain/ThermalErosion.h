#pragma once
/// @file ThermalErosion.h
/// Internal: talus-angle thermal erosion for the height-map generator.

#include <cstdint>
#include <functional>
#include <vector>

namespace tessera::terrain {

/// Relaxes slopes steeper than `talusSlope` (rise over run) in a size x size
/// map of heights in cell units: on each of `iterations` passes every pair of
/// 8-neighbours whose difference exceeds the talus height for their distance
/// moves a fixed fraction of the excess downhill.
///
/// Each pass reads only the previous pass's buffer and computes every sample
/// from its own neighbourhood in a fixed order (Jacobi, not Gauss-Seidel), so
/// rows can be split among threads without changing a bit of the result. The
/// flux between two samples is the same float in both of their updates, so
/// material is conserved.
///
/// `onProgress(fraction)` runs on the calling thread.
void erodeThermal(std::vector<float>& heights, uint32_t size, uint32_t iterations,
                  float talusSlope, uint32_t threadCount,
                  const std::function<void(float)>& onProgress);

} // namespace tessera::terrain
