#pragma once
// floor() to an integer without the library's general rounding.

#include <cstdint>

namespace tessera::crowd {

/// int32_t(std::floor(v)) for |v| < 2^31, bit for bit: truncation, one
/// lower where that rounded a negative value up. Every agent turns
/// positions into cells many times a step; without SSE4.1's roundss,
/// std::floor is a dozen instructions and a branch (8% of a step's samples).
inline int32_t floorToInt(float v) {
    const int32_t truncated = int32_t(v);
    return truncated - int32_t(v < float(truncated));
}

} // namespace tessera::crowd
