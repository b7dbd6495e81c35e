#pragma once
/// @file HydraulicErosion.h
/// Internal: particle-based hydraulic erosion for the height-map generator.

#include <cstdint>
#include <functional>
#include <vector>

namespace tessera::terrain {

/// Erodes a size x size height map in place with `dropletCount` water droplets
/// (after Hans Beyer, "Implementation of a method for hydraulic erosion", 2015).
///
/// Heights are in cell units (metres divided by the sample spacing), so a
/// height difference between neighbours is the slope. Each droplet starts at
/// a random point, follows the bilinear gradient with a little inertia for up
/// to kLifetime steps of one cell, and carries sediment up to a capacity that
/// grows with its speed, water and descent: below capacity it erodes through
/// a radius-kRadius brush, above it (or going uphill) it deposits bilinearly
/// at its position, filling pits first.
///
/// Determinism with threads: the map is cut into square tiles coloured 2x2 like
/// a checkerboard. Droplets start inside their tile and cannot travel further
/// than kLifetime cells, so tiles of one colour (two tiles apart) never touch
/// the same samples and run in parallel; colours run one after another, in
/// several passes. Each (pass, tile) draws its droplets from its own Random
/// stream, so the result is independent of the thread count.
///
/// `onProgress(fraction)` runs on the calling thread.
void erodeHydraulic(std::vector<float>& heights, uint32_t size, uint32_t dropletCount,
                    uint64_t seed, uint32_t threadCount,
                    const std::function<void(float)>& onProgress);

} // namespace tessera::terrain
