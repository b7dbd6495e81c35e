#pragma once
/// @file HeightMapGenerator.h
/// Deterministic procedural height maps in the spirit of World Machine:
/// noise-built mountains and valleys, then hydraulic and thermal erosion.
///
/// Pipeline (each stage reports progress under the name in quotes):
///  1. "terrain noise": a domain-warped ridged multifractal (gradient noise)
///     for mountain ranges, blended by a low-frequency fBm mask into rolling
///     fBm hills and flat valley floors.
///  2. "hydraulic erosion": particle droplets that flow downhill, pick up
///     sediment where they speed up (eroding through a radius-3 brush) and
///     drop it where they slow down or climb. A first pass on a 4x coarser
///     copy (2x at 256; none below) carves the large valleys, whose change is
///     upsampled onto the map; the full-resolution pass then cuts the gullies.
///  3. "thermal erosion": material slides from any slope steeper than the
///     talus angle to its lower neighbours, softening the droplet gullies.
///  4. "normalise": stretched to the full 0..65535 range.
///
/// Determinism: the output depends only on the settings other than
/// threadCount; it is bit-identical for any number of threads. Work is split
/// into pieces whose results never depend on each other within a step (rows;
/// same-colour erosion tiles whose reach cannot overlap), and every float sum
/// runs in a fixed order inside one piece. Randomness comes only from
/// tessera::Random, and only exactly rounded float operations are used (no
/// libm transcendentals; the build disables FMA contraction for these
/// sources), so any IEEE-conforming build gives the same bytes as well.
///
/// The terrain is shaped as if it spanned 8192 m with 600 m of relief (the
/// default TerrainScale at 2048 samples), whatever the size: a smaller map is
/// the same landscape at lower resolution, more coarsely eroded.

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace tessera::terrain {

/// Smallest side length generateHeightMap() accepts.
inline constexpr uint32_t kMinGeneratedSize = 64;
/// Largest side length generateHeightMap() accepts.
inline constexpr uint32_t kMaxGeneratedSize = 8192;

/// Inputs of generateHeightMap().
struct HeightMapGeneratorSettings {
    /// Samples per side; a power of two in [kMinGeneratedSize, kMaxGeneratedSize].
    uint32_t size = 2048;
    /// Selects the landscape; every seed gives a different one.
    uint64_t seed = 1;
    /// Droplets of the full-resolution erosion pass; unset means
    /// defaultErosionDroplets(size), 0 disables hydraulic erosion. The coarse
    /// pass adds the same density per area (1/16 as many at 4x coarser).
    std::optional<uint32_t> erosionDroplets;
    /// Thermal erosion relaxation passes over the whole map; 0 disables it.
    uint32_t thermalIterations = 24;
    /// Steepest stable slope (rise over run) for thermal erosion; 0.8 ~ 39 degrees.
    float talusSlope = 0.8f;
    /// Worker threads including the caller; 0 means one per hardware thread.
    /// Never changes the output, only the time it takes.
    uint32_t threadCount = 0;
};

/// Droplet count used when HeightMapGeneratorSettings::erosionDroplets is
/// unset: one per four samples (1,048,576 at 2048x2048).
uint32_t defaultErosionDroplets(uint32_t size);

/// Called with the current stage name and the overall progress in [0, 1]
/// (monotonic, weighted by each stage's expected cost). Always called on the
/// thread that called generateHeightMap(), at least once per stage start and
/// once with 1.0 at the end.
using HeightMapProgress = std::function<void(std::string_view stage, float fraction)>;

/// Generates a size x size height map, row-major like HeightField::samples()
/// (row j is world z), normalised so that its lowest sample is 0 and its
/// highest 65535. A size outside the documented range is a programming error
/// (asserted); command-line tools validate it first.
std::vector<uint16_t> generateHeightMap(const HeightMapGeneratorSettings& settings,
                                        const HeightMapProgress& progress = {});

} // namespace tessera::terrain
