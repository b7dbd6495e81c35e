#pragma once
// Unsigned 16.16 fixed point, the number format of the D3D11 reference
// tessellator. Every rule here is bit-exact with it: the float conversion
// rounds to nearest even, reciprocals are rounded to nearest, and products
// wrap in 32 bits exactly as the reference's unsigned arithmetic does.

#include <cmath>
#include <cstdint>

namespace tessera::tessellator::detail {

using Fxp = uint32_t;

inline constexpr int kFractionBits = 16;
inline constexpr Fxp kFxpOne = Fxp{1} << kFractionBits;
inline constexpr Fxp kFxpHalf = kFxpOne >> 1;
inline constexpr Fxp kFxpFractionMask = kFxpOne - 1;
inline constexpr Fxp kFxpIntegerMask = 0x7fff0000u; // 15 integer bits
/// 1/3 and 2/3 truncated, as the reference's triangle centre and ring inset use.
inline constexpr Fxp kFxpOneThird = 0x5555u;
inline constexpr Fxp kFxpTwoThirds = 0xaaaau;

/// float -> 16.16. NaN, zero and negatives give 0, values below 2^-17 give 0,
/// values from 2^15 saturate to all ones; the rest round to nearest, ties to
/// even. Levels reach here already clamped to [1, 64], where the scaling by
/// 2^16 is exact in double, so the rounding below is the only one.
inline Fxp toFixed(float value) {
    if (!(value > 0.0f)) return 0;
    if (value >= 32768.0f) return 0xffffffffu;
    const double scaled = static_cast<double>(value) * 65536.0;
    const double below = std::floor(scaled);
    auto result = static_cast<Fxp>(below);
    const double rest = scaled - below;
    if (rest > 0.5 || (rest == 0.5 && (result & 1u))) ++result;
    return result;
}

/// 16.16 -> float, exact for every value the tessellator produces (at most 24
/// significant bits), computed the way the reference does.
inline float toFloat(Fxp value) {
    return static_cast<float>(value >> kFractionBits) +
           static_cast<float>(value & kFxpFractionMask) / static_cast<float>(kFxpOne);
}

inline Fxp fxpFloor(Fxp value) {
    return value & kFxpIntegerMask;
}

inline Fxp fxpCeil(Fxp value) {
    return (value & kFxpFractionMask) ? (value & kFxpIntegerMask) + kFxpOne : value;
}

/// 1/n in 16.16 rounded to nearest (n = 1..64); the reference keeps a table of
/// exactly these values (no ties occur for n <= 64).
inline constexpr Fxp fxpReciprocal(uint32_t n) {
    return (kFxpOne + n / 2) / n;
}

} // namespace tessera::tessellator::detail
