#pragma once
/// @file CharacterHoles.h
/// Finds holes in a character drawn on a magenta background: magenta pixels
/// the background cannot reach from the image border. A crack between
/// patches, with back faces culled, shows the clear colour through the
/// surface, enclosed by the character's own pixels; the background around the
/// silhouette, however ragged, touches the border.

#include "tessera/core/ImageFile.h"

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::test {

/// The clear colour 1,0,1 as it reads back, give or take rounding.
inline bool isMagentaPixel(const uint8_t* p) {
    return p[0] > 240 && p[1] < 16 && p[2] > 240;
}

/// One enclosed patch of background (8-connected hole pixels).
struct HoleComponent {
    size_t pixels = 0;
    uint32_t minX = 0, minY = 0, maxX = 0, maxY = 0; ///< inclusive bounding box
};

struct HoleReport {
    size_t magenta = 0;               ///< all background pixels
    size_t holePixels = 0;            ///< magenta pixels not reachable from the border
    std::vector<HoleComponent> holes; ///< largest first

    /// "N hole pixels in K holes (largest: P px at x0..x1, y0..y1)", for messages.
    std::string describe() const {
        std::ostringstream out;
        out << holePixels << " hole pixels in " << holes.size() << " holes";
        if (!holes.empty()) {
            const HoleComponent& h = holes.front();
            out << " (largest: " << h.pixels << " px at x " << h.minX << ".." << h.maxX << ", y " << h.minY << ".."
                << h.maxY << ")";
        }
        return out.str();
    }
};

/// Flood-fills the background from every magenta border pixel through
/// 4-connected magenta pixels (4, not 8: a one-pixel diagonal crack must not
/// leak the fill through the surface), then groups what the fill did not
/// reach into 8-connected holes.
/// With `enclosed`, also marks every hole pixel (1) in a mask of the image's size.
inline HoleReport findHoles(const Rgba8Image& image, std::vector<uint8_t>* enclosed = nullptr) {
    HoleReport report;
    const uint32_t w = image.width, h = image.height;
    if (w == 0 || h == 0 || image.pixels.size() < size_t(w) * h * 4) return report;
    // 0: surface, 1: background not yet reached, 2: reached from the border.
    std::vector<uint8_t> state(size_t(w) * h);
    for (size_t i = 0; i < state.size(); ++i) {
        state[i] = isMagentaPixel(&image.pixels[i * 4]) ? 1 : 0;
        report.magenta += state[i];
    }
    std::vector<size_t> stack;
    auto reach = [&](size_t i) {
        if (state[i] == 1) {
            state[i] = 2;
            stack.push_back(i);
        }
    };
    for (uint32_t x = 0; x < w; ++x) {
        reach(x);
        reach(size_t(h - 1) * w + x);
    }
    for (uint32_t y = 0; y < h; ++y) {
        reach(size_t(y) * w);
        reach(size_t(y) * w + w - 1);
    }
    while (!stack.empty()) {
        const size_t i = stack.back();
        stack.pop_back();
        const uint32_t x = uint32_t(i % w), y = uint32_t(i / w);
        if (x > 0) reach(i - 1);
        if (x + 1 < w) reach(i + 1);
        if (y > 0) reach(i - w);
        if (y + 1 < h) reach(i + w);
    }
    if (enclosed) {
        enclosed->assign(state.size(), 0);
        for (size_t i = 0; i < state.size(); ++i) (*enclosed)[i] = state[i] == 1 ? 1 : 0;
    }
    // What is left at 1 is enclosed; label it (3: labelled).
    for (size_t seed = 0; seed < state.size(); ++seed) {
        if (state[seed] != 1) continue;
        HoleComponent hole;
        hole.minX = hole.maxX = uint32_t(seed % w);
        hole.minY = hole.maxY = uint32_t(seed / w);
        state[seed] = 3;
        stack.push_back(seed);
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            const uint32_t x = uint32_t(i % w), y = uint32_t(i / w);
            ++hole.pixels;
            hole.minX = std::min(hole.minX, x);
            hole.maxX = std::max(hole.maxX, x);
            hole.minY = std::min(hole.minY, y);
            hole.maxY = std::max(hole.maxY, y);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = int(x) + dx, ny = int(y) + dy;
                    if (nx < 0 || ny < 0 || nx >= int(w) || ny >= int(h)) continue;
                    const size_t n = size_t(ny) * w + size_t(nx);
                    if (state[n] == 1) {
                        state[n] = 3;
                        stack.push_back(n);
                    }
                }
        }
        report.holePixels += hole.pixels;
        report.holes.push_back(hole);
    }
    std::stable_sort(report.holes.begin(), report.holes.end(),
                     [](const HoleComponent& a, const HoleComponent& b) { return a.pixels > b.pixels; });
    return report;
}

} // namespace tessera::test
