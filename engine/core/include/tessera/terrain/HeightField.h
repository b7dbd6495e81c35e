#pragma once
/// @file HeightField.h
/// The CPU copy of the terrain height field, for gameplay queries (ground
/// height, slope, patch bounds) and as the source of the GPU upload.

#include "tessera/terrain/TerrainScale.h"

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tessera::terrain {

/// A rectangular grid of normalised 16-bit height samples plus its world scale.
///
/// Layout: `samples()[j * width() + i]` is sample (i, j); i runs along +X and j
/// along +Z, so row j of a height-map image lies at z = j * spacing. Upload the
/// array unchanged as an R16_UNORM texture of width() x height() texels.
///
/// GPU correspondence: sampling that texture with linear filtering and
/// CLAMP_TO_EDGE at `uv = (vec2(x, z) / spacing + 0.5) / vec2(width, height)`
/// reproduces heightAt(x, z) (up to the GPU's filtering precision), and
/// normalAt() is defined only in terms of heightAt(), so a shader that uses the
/// formula documented there computes the same normal.
///
/// Out-of-range sample indices are programming errors (asserted), not checked
/// errors; world-space queries clamp to the edges instead.
class HeightField {
public:
    /// Takes ownership of `samples` (row-major, `width * height` values).
    /// Requires width >= 2, height >= 2 and a matching sample count.
    HeightField(uint32_t width, uint32_t height, std::vector<uint16_t> samples,
                TerrainScale scale = {});

    /// Number of samples along X.
    uint32_t width() const { return mWidth; }
    /// Number of samples along Z.
    uint32_t height() const { return mHeight; }
    /// World scale used by every metre-valued query.
    const TerrainScale& scale() const { return mScale; }
    /// Row-major normalised samples (see the class comment for the layout).
    const std::vector<uint16_t>& samples() const { return mSamples; }

    /// World extent in metres along X and Z: ((width-1) * spacing, (height-1) * spacing).
    glm::vec2 worldSize() const;

    /// Height of sample (i, j) in metres.
    float sampleHeight(uint32_t i, uint32_t j) const;

    /// Height in metres at world (x, z), bilinearly interpolated between the
    /// four surrounding samples. Positions outside the field are clamped to
    /// its edges, so the result is always a height of the border samples there.
    /// Exact (to float rounding) at sample positions.
    float heightAt(float x, float z) const;

    /// Unit surface normal at world (x, z), by central differences:
    ///
    ///     s  = horizontalSpacing
    ///     hL = heightAt(x - s, z)    hR = heightAt(x + s, z)
    ///     hD = heightAt(x, z - s)    hU = heightAt(x, z + s)
    ///     n  = normalize(vec3(hL - hR, 2 s, hD - hU))
    ///
    /// i.e. the normal of the tangent plane with slopes dh/dx = (hR - hL) / 2s
    /// and dh/dz = (hU - hD) / 2s. For a plane y = a x + b z it is exactly
    /// normalize(-a, 1, -b) away from the edges. At the edges the clamped taps
    /// halve the slope across the border, exactly as CLAMP_TO_EDGE does on the
    /// GPU; terrain shaders must use this same formula (taps one texel apart in
    /// uv) so lighting and collision agree.
    glm::vec3 normalAt(float x, float z) const;

    /// Overwrites sample (i, j) with a normalised value (e.g. a crater splat).
    void setSample(uint32_t i, uint32_t j, uint16_t value);

    /// Lowest and highest height in metres among the samples of the inclusive
    /// rectangle [i0, i1] x [j0, j1]; requires i0 <= i1 < width and
    /// j0 <= j1 < height. Bilinear interpolation never leaves this range, so it
    /// bounds the surface over that rectangle (used for patch bounding boxes).
    std::pair<float, float> minMaxHeight(uint32_t i0, uint32_t j0, uint32_t i1, uint32_t j1) const;

private:
    float toMetres(float normalised) const { return normalised * mMetresPerUnit; }
    uint16_t at(uint32_t i, uint32_t j) const { return mSamples[size_t(j) * mWidth + i]; }

    uint32_t mWidth = 0;
    uint32_t mHeight = 0;
    std::vector<uint16_t> mSamples;
    TerrainScale mScale;
    float mMetresPerUnit = 0.0f; ///< heightScale / 65535, cached.
};

} // namespace tessera::terrain
