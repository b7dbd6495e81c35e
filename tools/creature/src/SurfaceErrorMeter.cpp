#include "SurfaceErrorMeter.h"

#include "BakeBilinear.h"
#include "SubdivSampleTable.h"
#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace tessera::creature {

namespace {

struct Partial {
    double sumSquares = 0.0;
    double max = 0.0;
    uint64_t samples = 0;
    uint64_t unmeasured = 0;

    void add(const std::optional<float>& distance) {
        if (!distance) {
            ++unmeasured;
            return;
        }
        const double d = std::abs(double(*distance));
        sumSquares += d * d;
        max = std::max(max, d);
        ++samples;
    }
};

SurfaceError reduce(const std::vector<Partial>& parts) {
    SurfaceError e;
    double sum = 0.0;
    for (const Partial& p : parts) {
        sum += p.sumSquares;
        e.max = std::max(e.max, p.max);
        e.samples += p.samples;
        e.unmeasured += p.unmeasured;
    }
    e.rms = e.samples ? std::sqrt(sum / double(e.samples)) : 0.0;
    return e;
}

SurfaceError measure(uint32_t faces, uint32_t threads, const std::function<void(uint32_t, Partial&)>& face) {
    std::vector<Partial> parts(faces);
    core::parallelFor(faces, threads, [&](uint32_t f) { face(f, parts[f]); });
    return reduce(parts);
}

} // namespace

SurfaceError measureSubdivError(const subdiv::SubdivSurface& surface, const subdiv::DisplacementTiles* tiles,
                                const Bvh& bvh, float search, uint32_t grid, uint32_t threads) {
    return measure(surface.ptexFaceCount(), threads, [&](uint32_t f, Partial& part) {
        for (uint32_t j = 0; j < grid; ++j)
            for (uint32_t i = 0; i < grid; ++i) {
                const glm::dvec2 uv((i + 0.5) / grid, (j + 0.5) / grid);
                std::optional<LimitFrame> frame = limitFrame(surface, f, uv);
                if (!frame) continue;
                if (tiles) frame->position += frame->normal * double(tiles->evaluateLevel(f, 0, glm::vec2(uv)).value.x);
                part.add(castToSculpt(bvh, *frame, search));
            }
    });
}

SurfaceError measurePlanarError(const character::CageMesh& cage, const character::DisplacementMap& displacement,
                                const Bvh& bvh, float search, uint32_t grid, uint32_t threads) {
    const character::TextureImage& image = displacement.image;
    if (image.format != character::TextureFormat::R16 || image.width == 0 || image.width != image.height) return {};
    std::vector<float> map(size_t(image.width) * image.height);
    for (size_t i = 0; i < map.size(); ++i)
        map[i] = float(uint32_t(image.bytes[2 * i]) | (uint32_t(image.bytes[2 * i + 1]) << 8)) / 65535.0f;
    return measure(cage.triangleCount(), threads, [&](uint32_t t, Partial& part) {
        const character::CageVertex& v0 = cage.vertices[cage.indices[3 * t]];
        const character::CageVertex& v1 = cage.vertices[cage.indices[3 * t + 1]];
        const character::CageVertex& v2 = cage.vertices[cage.indices[3 * t + 2]];
        auto sampleAt = [&](float b1, float b2) {
            const float b0 = 1.0f - b1 - b2;
            const glm::vec3 n = b0 * v0.normal + b1 * v1.normal + b2 * v2.normal;
            const float len = glm::length(n);
            if (!(len > 0.0f)) return;
            const glm::vec2 uv = b0 * v0.uv + b1 * v1.uv + b2 * v2.uv;
            const float d = sampleBilinear(map, image.width, uv) * displacement.scale + displacement.bias;
            LimitFrame frame;
            frame.normal = glm::dvec3(n / len);
            frame.position = glm::dvec3(b0 * v0.position + b1 * v1.position + b2 * v2.position) + frame.normal * double(d);
            part.add(castToSculpt(bvh, frame, search));
        };
        // Stratified: the centroids of the grid^2 sub-triangles of a
        // regular split, upright and inverted.
        const float g = float(grid);
        for (uint32_t i = 0; i < grid; ++i)
            for (uint32_t j = 0; i + j < grid; ++j) {
                sampleAt((float(i) + 1.0f / 3.0f) / g, (float(j) + 1.0f / 3.0f) / g);
                if (i + j + 1 < grid) sampleAt((float(i) + 2.0f / 3.0f) / g, (float(j) + 2.0f / 3.0f) / g);
            }
    });
}

} // namespace tessera::creature
