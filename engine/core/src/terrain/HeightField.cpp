#include "tessera/terrain/HeightField.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

namespace tessera::terrain {

HeightField::HeightField(uint32_t width, uint32_t height, std::vector<uint16_t> samples,
                         TerrainScale scale)
    : mWidth(width), mHeight(height), mSamples(std::move(samples)), mScale(scale),
      mMetresPerUnit(scale.heightScale / 65535.0f) {
    assert(width >= 2 && height >= 2);
    assert(mSamples.size() == size_t(width) * height);
    assert(scale.horizontalSpacing > 0.0f);
}

glm::vec2 HeightField::worldSize() const {
    return glm::vec2(float(mWidth - 1), float(mHeight - 1)) * mScale.horizontalSpacing;
}

float HeightField::sampleHeight(uint32_t i, uint32_t j) const {
    assert(i < mWidth && j < mHeight);
    return toMetres(float(at(i, j)));
}

float HeightField::heightAt(float x, float z) const {
    // Work in sample units and clamp there, so the edge behaviour is exactly
    // CLAMP_TO_EDGE with texel-centre addressing (see the header).
    float fx = std::clamp(x / mScale.horizontalSpacing, 0.0f, float(mWidth - 1));
    float fz = std::clamp(z / mScale.horizontalSpacing, 0.0f, float(mHeight - 1));
    // The cell origin stops one short of the last sample so that i0 + 1 is
    // valid; on the far edge the weight of that sample is then exactly 1.
    uint32_t i0 = std::min(uint32_t(fx), mWidth - 2);
    uint32_t j0 = std::min(uint32_t(fz), mHeight - 2);
    float tx = fx - float(i0);
    float tz = fz - float(j0);

    float h00 = at(i0, j0), h10 = at(i0 + 1, j0);
    float h01 = at(i0, j0 + 1), h11 = at(i0 + 1, j0 + 1);
    // a + (b - a) * t is exact at t == 0 and, for these integer-valued inputs,
    // at t == 1 too: queries at sample positions return the sample exactly.
    float near = h00 + (h10 - h00) * tx;
    float far = h01 + (h11 - h01) * tx;
    return toMetres(near + (far - near) * tz);
}

glm::vec3 HeightField::normalAt(float x, float z) const {
    const float s = mScale.horizontalSpacing;
    float hL = heightAt(x - s, z);
    float hR = heightAt(x + s, z);
    float hD = heightAt(x, z - s);
    float hU = heightAt(x, z + s);
    return glm::normalize(glm::vec3(hL - hR, 2.0f * s, hD - hU));
}

void HeightField::setSample(uint32_t i, uint32_t j, uint16_t value) {
    assert(i < mWidth && j < mHeight);
    mSamples[size_t(j) * mWidth + i] = value;
}

std::pair<float, float> HeightField::minMaxHeight(uint32_t i0, uint32_t j0, uint32_t i1,
                                                  uint32_t j1) const {
    assert(i0 <= i1 && i1 < mWidth && j0 <= j1 && j1 < mHeight);
    uint16_t lo = 65535, hi = 0;
    for (uint32_t j = j0; j <= j1; ++j) {
        const uint16_t* row = &mSamples[size_t(j) * mWidth];
        auto [rowLo, rowHi] = std::minmax_element(row + i0, row + i1 + 1);
        lo = std::min(lo, *rowLo);
        hi = std::max(hi, *rowHi);
    }
    return {toMetres(float(lo)), toMetres(float(hi))};
}

} // namespace tessera::terrain
