#pragma once
/// @file BakeDilation.h
/// Grows known texel values into unknown ones, ring by ring: the baker's miss
/// filling and gutter padding.

#include <cstdint>
#include <utility>
#include <vector>

namespace tessera::creature {

/// Sets every unknown texel with `grow` set and a known 8-neighbour to the
/// mean of its known neighbours, then marks it known; repeats for up to
/// `maxRings` rings or until nothing changes. Each ring reads only values
/// known before it (Jacobi order), so the result is independent of scan
/// order. Returns the number of texels filled.
template <class T>
uint64_t dilateInto(std::vector<T>& values, std::vector<uint8_t>& known, const std::vector<uint8_t>& grow,
                    uint32_t size, uint32_t maxRings) {
    std::vector<uint32_t> pending;
    for (uint32_t i = 0; i < values.size(); ++i) {
        if (grow[i] && !known[i]) pending.push_back(i);
    }
    uint64_t filled = 0;
    std::vector<std::pair<uint32_t, T>> ring;
    for (uint32_t r = 0; r < maxRings && !pending.empty(); ++r) {
        ring.clear();
        std::vector<uint32_t> still;
        for (uint32_t index : pending) {
            int x = static_cast<int>(index % size), y = static_cast<int>(index / size);
            T sum{};
            int n = 0;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    int nx = x + dx, ny = y + dy;
                    if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= static_cast<int>(size) ||
                        ny >= static_cast<int>(size))
                        continue;
                    uint32_t ni = static_cast<uint32_t>(ny) * size + static_cast<uint32_t>(nx);
                    if (!known[ni]) continue;
                    sum += values[ni];
                    ++n;
                }
            }
            if (n > 0) {
                ring.emplace_back(index, sum / static_cast<float>(n));
            } else {
                still.push_back(index);
            }
        }
        if (ring.empty()) break;
        for (const auto& [index, value] : ring) {
            values[index] = value;
            known[index] = 1;
        }
        filled += ring.size();
        pending.swap(still);
    }
    return filled;
}

} // namespace tessera::creature
