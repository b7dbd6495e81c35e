#include "tessera/terrain/HeightMapGenerator.h"

#include "HydraulicErosion.h"
#include "tessera/core/ParallelFor.h"
#include "TerrainNoise.h"
#include "ThermalErosion.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::terrain {
namespace {

// The landscape is laid out for this world, whatever the sample count (see
// the header): erosion works on slopes, so it needs metres per cell.
constexpr float kWorldExtent = 8192.0f; // metres across
constexpr float kRelief = 600.0f;       // metres per unit of terrainShape()

// Measured share of the run time of each stage at the default settings, so
// that the overall progress fraction advances evenly.
constexpr float kNoiseWeight = 0.33f;
constexpr float kHydraulicWeight = 0.43f;
constexpr float kThermalWeight = 0.23f;
constexpr float kNormaliseWeight = 0.01f;

// Seed salts: each stage draws from its own stream of the seed.
constexpr uint64_t kNoiseSalt = 0x6e6f697365ULL;          // "noise"
constexpr uint64_t kErosionSalt = 0x65726f6465ULL;        // "erode"
constexpr uint64_t kCoarseErosionSalt = 0x636f61727365ULL; // "coarse"

constexpr uint32_t kRowsPerItem = 16;

float smoothstep(float edge0, float edge1, float x) {
    float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Relative height (0 to about 1.4) at map coordinates (u, v) in [0, 1)^2.
float terrainShape(const TerrainNoise& noise, glm::vec2 uv) {
    const glm::vec2 p = uv * 4.0f;
    // Large-scale relief: where the ranges rise and where the lowlands lie.
    float base = std::clamp(0.55f + 1.2f * noise.fbmGradient(p * 0.3f + glm::vec2(-71.4f, 9.2f), 4), 0.0f, 1.0f);
    float mountains = smoothstep(0.2f, 0.7f, base);
    // Domain warp: bend the ridge lines so ranges curve and branch instead of
    // following the noise lattice.
    glm::vec2 warp(noise.fbmValue(p * 0.5f + glm::vec2(17.3f, 4.1f), 2),
                   noise.fbmValue(p * 0.5f + glm::vec2(-8.6f, 31.7f), 2));
    float ridges = noise.ridged(p + warp * 0.5f, 8);
    float hills = 0.5f + 0.5f * noise.fbmGradient(p * 1.3f + glm::vec2(53.1f, -12.9f), 6);
    float h = 0.3f * base + mountains * (0.8f * ridges + 0.15f * hills);
    // h^1.5 widens valley floors and sharpens the peaks above them.
    return h * std::sqrt(h);
}

void generateNoise(std::vector<float>& heights, uint32_t size, uint64_t seed, float relief,
                   uint32_t threads, const std::function<void(float)>& onProgress) {
    const TerrainNoise noise(seed ^ kNoiseSalt);
    const uint32_t items = size / kRowsPerItem;
    const float inverse = 1.0f / float(size);
    core::parallelFor(
        items, threads,
        [&](uint32_t item) {
            for (uint32_t y = item * kRowsPerItem; y < (item + 1) * kRowsPerItem; ++y)
                for (uint32_t x = 0; x < size; ++x)
                    heights[size_t(y) * size + x] =
                        relief * terrainShape(noise, glm::vec2(float(x), float(y)) * inverse);
        },
        [&](uint32_t done) { onProgress(float(done) / float(items)); });
}

// Carves the large drainage network that droplets of a few dozen cells cannot:
// erodes a copy `factor` times coarser (box-filtered; heights rescaled to its
// larger cells) and adds the bilinearly upsampled change to the full map.
void erodeCoarse(std::vector<float>& heights, uint32_t size, uint32_t factor, uint32_t droplets,
                 uint64_t seed, uint32_t threads, const std::function<void(float)>& onProgress) {
    const uint32_t coarseSize = size / factor;
    const float average = 1.0f / float(factor * factor * factor); // mean, then / factor for units
    std::vector<float> coarse(size_t(coarseSize) * coarseSize);
    for (uint32_t cy = 0; cy < coarseSize; ++cy)
        for (uint32_t cx = 0; cx < coarseSize; ++cx) {
            float sum = 0.0f;
            for (uint32_t y = cy * factor; y < (cy + 1) * factor; ++y)
                for (uint32_t x = cx * factor; x < (cx + 1) * factor; ++x)
                    sum += heights[size_t(y) * size + x];
            coarse[size_t(cy) * coarseSize + cx] = sum * average;
        }
    std::vector<float> change = coarse;
    erodeHydraulic(coarse, coarseSize, droplets, seed, threads, onProgress);
    for (size_t k = 0; k < change.size(); ++k) change[k] = (coarse[k] - change[k]) * float(factor);

    const float step = 1.0f / float(factor);
    const float last = float(coarseSize - 1);
    core::parallelFor(size / kRowsPerItem, threads, [&](uint32_t item) {
        for (uint32_t y = item * kRowsPerItem; y < (item + 1) * kRowsPerItem; ++y) {
            // Fine sample centres in coarse sample coordinates.
            float fy = std::clamp((float(y) + 0.5f) * step - 0.5f, 0.0f, last);
            uint32_t y0 = std::min(uint32_t(fy), coarseSize - 2);
            float ty = fy - float(y0);
            const float* r0 = &change[size_t(y0) * coarseSize];
            const float* r1 = r0 + coarseSize;
            for (uint32_t x = 0; x < size; ++x) {
                float fx = std::clamp((float(x) + 0.5f) * step - 0.5f, 0.0f, last);
                uint32_t x0 = std::min(uint32_t(fx), coarseSize - 2);
                float tx = fx - float(x0);
                float a = r0[x0] + (r0[x0 + 1] - r0[x0]) * tx;
                float b = r1[x0] + (r1[x0 + 1] - r1[x0]) * tx;
                heights[size_t(y) * size + x] += a + (b - a) * ty;
            }
        }
    });
}

std::vector<uint16_t> normalise(const std::vector<float>& heights) {
    auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
    const float low = *lo;
    const float scale = *hi > low ? 65535.0f / (*hi - low) : 0.0f;
    std::vector<uint16_t> samples(heights.size());
    for (size_t k = 0; k < heights.size(); ++k)
        samples[k] = uint16_t(std::min(65535.0f, std::floor((heights[k] - low) * scale + 0.5f)));
    return samples;
}

} // namespace

uint32_t defaultErosionDroplets(uint32_t size) { return uint32_t(uint64_t(size) * size / 4); }

std::vector<uint16_t> generateHeightMap(const HeightMapGeneratorSettings& settings,
                                        const HeightMapProgress& progress) {
    const uint32_t size = settings.size;
    assert(size >= kMinGeneratedSize && size <= kMaxGeneratedSize && (size & (size - 1)) == 0);
    const uint32_t threads = settings.threadCount != 0
                                 ? settings.threadCount
                                 : core::hardwareThreads();
    const uint32_t droplets = settings.erosionDroplets.value_or(defaultErosionDroplets(size));

    // Progress plumbing: each stage maps its own 0..1 onto its share of the whole.
    float stageStart = 0.0f;
    auto report = [&](std::string_view stage, float weight) {
        if (progress) progress(stage, stageStart);
        return [&progress, stage, weight, start = stageStart](float fraction) {
            if (progress) progress(stage, start + weight * fraction);
        };
    };

    // Heights in cell units (metres / metres per cell): slopes are plain differences.
    const float metresPerCell = kWorldExtent / float(size);
    std::vector<float> heights(size_t(size) * size);
    generateNoise(heights, size, settings.seed, kRelief / metresPerCell, threads,
                  report("terrain noise", kNoiseWeight));
    stageStart += kNoiseWeight;

    {
        // The coarse pass gets the same droplet density per square metre as the
        // fine one; its share of the progress bar follows its droplet count.
        auto hydraulic = report("hydraulic erosion", kHydraulicWeight);
        const uint32_t factor = size >= 512 ? 4 : size >= 256 ? 2 : 1;
        const uint32_t coarseDroplets = factor > 1 ? droplets / (factor * factor) : 0;
        const float coarseShare =
            droplets > 0 ? float(coarseDroplets) / float(coarseDroplets + droplets) : 0.0f;
        if (coarseDroplets > 0)
            erodeCoarse(heights, size, factor, coarseDroplets, settings.seed ^ kCoarseErosionSalt,
                        threads, [&](float f) { hydraulic(coarseShare * f); });
        erodeHydraulic(heights, size, droplets, settings.seed ^ kErosionSalt, threads,
                       [&](float f) { hydraulic(coarseShare + (1.0f - coarseShare) * f); });
    }
    stageStart += kHydraulicWeight;

    erodeThermal(heights, size, settings.thermalIterations, settings.talusSlope, threads,
                 report("thermal erosion", kThermalWeight));
    stageStart += kThermalWeight;

    report("normalise", kNormaliseWeight);
    std::vector<uint16_t> samples = normalise(heights);
    if (progress) progress("normalise", 1.0f);
    return samples;
}

} // namespace tessera::terrain
