#pragma once
// Appends fixed-point domain points to a pattern as the floats the hardware
// hands to the evaluation shader.

#include "FixedPoint.h"

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace tessera::tessellator::detail {

class PointWriter {
public:
    explicit PointWriter(std::vector<glm::vec2>& uv) : mUv(uv) {}

    /// Adds (u, v) and returns its index.
    uint32_t add(Fxp u, Fxp v) {
        mUv.emplace_back(toFloat(u), toFloat(v));
        return static_cast<uint32_t>(mUv.size() - 1);
    }
    uint32_t next() const { return static_cast<uint32_t>(mUv.size()); }

private:
    std::vector<glm::vec2>& mUv;
};

} // namespace tessera::tessellator::detail
