#include "DetailTextureGenerator.h"

#include <algorithm>
#include <cmath>

namespace tessera::texgen {

namespace {

/// splitmix64's finaliser: a well-mixed 64-bit hash of the lattice point.
uint64_t mix(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/// Value noise on a lattice of `cells` x `cells` that wraps, so the texture
/// tiles; `stream` separates the octaves and materials.
class TileableNoise {
public:
    TileableNoise(uint64_t seed, uint64_t stream) : mKey(mix(seed ^ mix(stream))) {}

    /// Lattice value in [0, 1) at integer (x, y), both wrapped to `cells`.
    double lattice(int64_t x, int64_t y, int64_t cells) const {
        const uint64_t wx = uint64_t(((x % cells) + cells) % cells);
        const uint64_t wy = uint64_t(((y % cells) + cells) % cells);
        return double(mix(mKey ^ mix(wx * 0x1f1f1f1full + wy) ^ uint64_t(cells)) >> 11) * (1.0 / 9007199254740992.0);
    }

    /// Smooth value noise at (u, v) in [0,1)^2 with `cells` lattice cells per side.
    double value(double u, double v, int64_t cells) const {
        const double x = u * double(cells), y = v * double(cells);
        const double fx = std::floor(x), fy = std::floor(y);
        const int64_t ix = int64_t(fx), iy = int64_t(fy);
        const double tx = x - fx, ty = y - fy;
        const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
        const double a = lattice(ix, iy, cells), b = lattice(ix + 1, iy, cells);
        const double c = lattice(ix, iy + 1, cells), d = lattice(ix + 1, iy + 1, cells);
        return (a + (b - a) * sx) * (1.0 - sy) + (c + (d - c) * sx) * sy;
    }

    /// Fractal sum of `octaves` octaves from `cells` cells, each twice as fine
    /// and half as strong; in [0, 1].
    double fbm(double u, double v, int64_t cells, int octaves, int64_t maxCells) const {
        double sum = 0.0, weight = 0.5, total = 0.0;
        for (int o = 0; o < octaves && cells <= maxCells; ++o, cells *= 2, weight *= 0.5) {
            sum += weight * value(u, v, cells);
            total += weight;
        }
        return total > 0.0 ? sum / total : 0.5;
    }

private:
    uint64_t mKey;
};

struct Rgb {
    double r, g, b;
};

Rgb lerp(const Rgb& a, const Rgb& b, double t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

Rgb scale(const Rgb& c, double s) { return {c.r * s, c.g * s, c.b * s}; }

double smooth(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// The colour of `material` at (u, v); colours are sRGB values in [0, 255].
Rgb shade(DetailMaterial material, const TileableNoise& a, const TileableNoise& b, double u, double v, int64_t size) {
    switch (material) {
    case DetailMaterial::Grass: {
        // Patches of lush and dry grass, blades as fine streaks.
        const double patches = a.fbm(u, v, 4, 5, size);
        const double blades = b.fbm(u, v, 64, 3, size);
        Rgb c = lerp({36, 62, 24}, {72, 92, 44}, smooth(0.35, 0.7, patches));
        return scale(c, 0.78 + 0.44 * blades);
    }
    case DetailMaterial::Dirt: {
        // Loam with lighter pebbles where a fine noise peaks.
        const double soil = a.fbm(u, v, 4, 6, size);
        const double grains = b.value(u, v, std::min<int64_t>(size / 4, 128));
        Rgb c = lerp({62, 56, 38}, {98, 88, 62}, soil);
        c = lerp(c, {120, 112, 96}, smooth(0.78, 0.9, grains) * 0.8);
        return scale(c, 0.85 + 0.3 * b.fbm(u, v, 32, 3, size));
    }
    case DetailMaterial::Rock: {
        // Strata bent by noise, ridged cracks, lichen-free granite greys.
        const double warp = a.fbm(u, v, 2, 5, size);
        const double strata = 0.5 + 0.5 * std::sin((v * 6.0 + warp * 3.0) * 2.0 * 3.14159265358979);
        const double ridged = 1.0 - std::abs(2.0 * b.fbm(u, v, 8, 5, size) - 1.0);
        Rgb c = lerp({92, 88, 82}, {150, 142, 130}, 0.55 * strata + 0.45 * warp);
        return scale(c, 0.65 + 0.45 * smooth(0.55, 0.95, ridged));
    }
    case DetailMaterial::Snow:
    default: {
        // Wind-packed snow: faint blue hollows, bright crusts.
        const double drift = a.fbm(u, v, 4, 5, size);
        const double crust = b.fbm(u, v, 32, 3, size);
        const Rgb c = lerp({206, 216, 232}, {238, 240, 244}, drift);
        return scale(c, 0.96 + 0.06 * crust);
    }
    }
}

} // namespace

std::string_view materialName(DetailMaterial material) {
    switch (material) {
    case DetailMaterial::Grass: return "grass";
    case DetailMaterial::Dirt: return "dirt";
    case DetailMaterial::Rock: return "rock";
    case DetailMaterial::Snow: return "snow";
    }
    return "unknown";
}

Rgba8Image generateDetailTexture(DetailMaterial material, uint32_t size, uint64_t seed) {
    const uint64_t stream = uint64_t(material) * 2;
    const TileableNoise a(seed, stream), b(seed, stream + 1);
    Rgba8Image image;
    image.width = size;
    image.height = size;
    image.pixels.resize(size_t(size) * size * 4);
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            const double u = (double(x) + 0.5) / double(size), v = (double(y) + 0.5) / double(size);
            const Rgb c = shade(material, a, b, u, v, int64_t(size));
            uint8_t* p = &image.pixels[(size_t(y) * size + x) * 4];
            p[0] = uint8_t(std::clamp(std::lround(c.r), 0l, 255l));
            p[1] = uint8_t(std::clamp(std::lround(c.g), 0l, 255l));
            p[2] = uint8_t(std::clamp(std::lround(c.b), 0l, 255l));
            p[3] = 255;
        }
    }
    return image;
}

} // namespace tessera::texgen
