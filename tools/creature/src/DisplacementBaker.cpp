#include "creature/DisplacementBaker.h"

#include "BakeDilation.h"
#include "BakeRayCaster.h"
#include "UvRasterizer.h"
#include "creature/Bvh.h"
#include "creature/SeamFixer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tessera::creature {

namespace {

constexpr uint32_t kMaxResolution = 2048;
/// Seam constraints per texel of edge length, and the denser sampling the
/// mismatch is measured with (points the fix never saw).
constexpr float kSeamPairsPerTexel = 6.0f;
constexpr float kSeamMeasurePerTexel = 7.0f;
constexpr uint32_t kSeamIterations = 250;

Status validate(const character::CageMesh& cage, const SculptMesh& sculpt, const BakeOptions& o) {
    const std::string where = "bakeDisplacement: ";
    if (o.resolution < 1 || o.resolution > kMaxResolution) {
        return fail(where, "resolution ", std::to_string(o.resolution), " is outside 1..2048");
    }
    if (o.normalResolution > kMaxResolution) {
        return fail(where, "normal resolution ", std::to_string(o.normalResolution), " exceeds 2048");
    }
    if (!(o.outerEnvelope > 0.0f) || !(o.innerEnvelope > 0.0f) || !std::isfinite(o.outerEnvelope) ||
        !std::isfinite(o.innerEnvelope)) {
        return fail(where, "envelopes must be positive and finite (outer ", std::to_string(o.outerEnvelope),
                    ", inner ", std::to_string(o.innerEnvelope), ")");
    }
    if (cage.indices.empty() || cage.indices.size() % 3 != 0) {
        return fail(where, "cage has no triangles or a partial one (", std::to_string(cage.indices.size()),
                    " indices)");
    }
    for (uint32_t i : cage.indices) {
        if (i >= cage.vertices.size()) return fail(where, "cage index ", std::to_string(i), " out of range");
    }
    bool anyUvArea = false;
    for (const character::CageVertex& v : cage.vertices) {
        if (!(v.uv.x >= 0.0f && v.uv.x <= 1.0f && v.uv.y >= 0.0f && v.uv.y <= 1.0f)) {
            return fail(where, "cage UV (", std::to_string(v.uv.x), ", ", std::to_string(v.uv.y),
                        ") is outside [0, 1]");
        }
    }
    for (uint32_t t = 0; t < cage.triangleCount() && !anyUvArea; ++t) {
        glm::vec2 a = cage.vertices[cage.indices[3 * t]].uv, b = cage.vertices[cage.indices[3 * t + 1]].uv,
                  c = cage.vertices[cage.indices[3 * t + 2]].uv;
        glm::vec2 e1 = b - a, e2 = c - a;
        anyUvArea = e1.x * e2.y - e1.y * e2.x != 0.0f;
    }
    if (!anyUvArea) return fail(where, "cage has no UVs (every triangle's UV area is zero)");
    if (sculpt.indices.empty() || sculpt.indices.size() % 3 != 0) {
        return fail(where, "sculpt has no triangles or a partial one");
    }
    for (uint32_t i : sculpt.indices) {
        if (i >= sculpt.positions.size()) return fail(where, "sculpt index ", std::to_string(i), " out of range");
    }
    return {};
}

std::vector<uint16_t> quantise(const std::vector<float>& values, float bias, float scale) {
    std::vector<uint16_t> out(values.size(), 0);
    if (scale <= 0.0f) return out;
    for (size_t i = 0; i < values.size(); ++i) {
        float s = std::clamp((values[i] - bias) / scale, 0.0f, 1.0f);
        out[i] = static_cast<uint16_t>(std::lround(s * 65535.0f));
    }
    return out;
}

/// What the shader reads back: sample * scale + bias.
std::vector<float> dequantise(const std::vector<uint16_t>& samples, float bias, float scale) {
    std::vector<float> out(samples.size());
    for (size_t i = 0; i < samples.size(); ++i) out[i] = static_cast<float>(samples[i]) / 65535.0f * scale + bias;
    return out;
}

std::pair<float, float> range(const std::vector<float>& values) {
    auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    return {*lo, *hi};
}

/// Fills missed texels from their hit neighbours; texels of an island with
/// no hit at all fall back to zero displacement and the cage normal.
template <class T>
void fillMisses(std::vector<T>& values, const std::vector<TexelState>& state, uint32_t size, T fallback) {
    std::vector<uint8_t> known(state.size()), grow(state.size());
    for (size_t i = 0; i < state.size(); ++i) {
        known[i] = state[i] == TexelState::Hit;
        grow[i] = state[i] != TexelState::Unbaked;
    }
    dilateInto(values, known, grow, size, std::numeric_limits<uint32_t>::max());
    for (size_t i = 0; i < state.size(); ++i) {
        if (grow[i] && !known[i]) values[i] = fallback;
    }
}

/// Pads charts by `gutter` rings, then sets the rest of the map to `rest`.
template <class T>
void padCharts(std::vector<T>& values, std::vector<uint8_t> chart, uint32_t size, uint32_t gutter, T rest) {
    std::vector<uint8_t> grow(values.size(), 1);
    dilateInto(values, chart, grow, size, gutter);
    for (size_t i = 0; i < values.size(); ++i) {
        if (!chart[i]) values[i] = rest;
    }
}

character::TextureImage encodeNormals(const std::vector<glm::vec3>& normals, uint32_t size) {
    character::TextureImage image{size, size, character::TextureFormat::Rgba8, {}};
    image.bytes.resize(normals.size() * 4);
    for (size_t i = 0; i < normals.size(); ++i) {
        float len = glm::length(normals[i]);
        glm::vec3 n = len > 0.0f ? normals[i] / len : glm::vec3(0.0f, 0.0f, 1.0f);
        for (int c = 0; c < 3; ++c) {
            image.bytes[4 * i + c] =
                static_cast<uint8_t>(std::lround(std::clamp(n[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
        }
        image.bytes[4 * i + 3] = 255;
    }
    return image;
}

std::vector<uint8_t> chartMask(const std::vector<TexelState>& state) {
    std::vector<uint8_t> mask(state.size());
    for (size_t i = 0; i < state.size(); ++i) mask[i] = state[i] != TexelState::Unbaked;
    return mask;
}

} // namespace

Result<BakeResult> bakeDisplacement(const character::CageMesh& cage, const SculptMesh& sculpt,
                                    const BakeOptions& options, const BakeProgressFn& progress) {
    if (Status status = validate(cage, sculpt, options); !status) return status.error();
    auto report = [&](float f) {
        if (progress) progress(f);
    };
    const uint32_t size = options.resolution;
    const uint32_t normalSize = options.normalResolution ? options.normalResolution : size;
    const uint32_t threads = options.threads; // 0: every hardware thread (core::parallelFor)
    report(0.0f);
    const Bvh bvh(sculpt.positions, sculpt.indices);
    const std::vector<glm::vec3> sculptNormals = sculptVertexNormals(sculpt);
    report(0.1f);

    const float castShare = normalSize == size ? 0.8f : 0.4f;
    const UvRasterizer raster(cage, size);
    BakedTexels baked = castTexelRays(cage, raster, bvh, sculpt, sculptNormals, options.innerEnvelope,
                                      options.outerEnvelope, threads,
                                      [&](float f) { report(0.1f + castShare * f); });
    BakeResult result;
    BakeStats& stats = result.stats;
    stats.texelsCovered = raster.insideCount();
    stats.texelsDilated = raster.dilatedCount();
    stats.misses = baked.misses;
    stats.missesPerTriangle.assign(cage.triangleCount(), 0);
    for (uint32_t i = 0; i < baked.state.size(); ++i) {
        if (baked.state[i] == TexelState::Miss) ++stats.missesPerTriangle[static_cast<size_t>(raster.at(i).triangle)];
    }

    std::vector<float>& displacement = baked.displacement;
    fillMisses(displacement, baked.state, size, 0.0f);

    // Seams: measure the map as the shader would read it, fix, measure again.
    const SeamFixer seams(cage, size);
    stats.seamEdges = seams.seamEdgeCount();
    stats.seamVertices = seams.seamVertexCount();
    auto [lo0, hi0] = range(displacement);
    stats.seamMismatchBefore =
        seams.maxMismatch(dequantise(quantise(displacement, lo0, hi0 - lo0), lo0, hi0 - lo0), kSeamMeasurePerTexel);
    std::vector<uint8_t> chart = chartMask(baked.state);
    stats.seamTexelsFixed =
        seams.fix(displacement, chart, kSeamPairsPerTexel, kSeamIterations, (hi0 - lo0) * 1e-7f);

    // The rest of the map gets the charts' mean so coarse mips stay plausible.
    double sum = 0.0;
    uint64_t chartTexels = 0;
    for (size_t i = 0; i < displacement.size(); ++i) {
        if (chart[i]) {
            sum += displacement[i];
            ++chartTexels;
        }
    }
    padCharts(displacement, chart, size, options.gutter,
              chartTexels ? static_cast<float>(sum / static_cast<double>(chartTexels)) : 0.0f);

    auto [lo, hi] = range(displacement);
    const float scale = hi - lo;
    const std::vector<uint16_t> samples = quantise(displacement, lo, scale);
    stats.minDisplacement = lo;
    stats.maxDisplacement = hi;
    stats.seamMismatchAfter = seams.maxMismatch(dequantise(samples, lo, scale), kSeamMeasurePerTexel);
    result.displacement.scale = scale;
    result.displacement.bias = lo;
    result.displacement.image = {size, size, character::TextureFormat::R16, {}};
    result.displacement.image.bytes.resize(samples.size() * 2);
    for (size_t i = 0; i < samples.size(); ++i) {
        result.displacement.image.bytes[2 * i] = static_cast<uint8_t>(samples[i] & 0xffu);
        result.displacement.image.bytes[2 * i + 1] = static_cast<uint8_t>(samples[i] >> 8);
    }
    report(0.1f + castShare);

    if (normalSize != size) {
        const UvRasterizer normalRaster(cage, normalSize);
        baked = castTexelRays(cage, normalRaster, bvh, sculpt, sculptNormals, options.innerEnvelope,
                              options.outerEnvelope, threads,
                              [&](float f) { report(0.5f + castShare * f); });
    }
    fillMisses(baked.normal, baked.state, normalSize, glm::vec3(0.0f, 0.0f, 1.0f));
    padCharts(baked.normal, chartMask(baked.state), normalSize, options.gutter, glm::vec3(0.0f, 0.0f, 1.0f));
    result.normalMap = encodeNormals(baked.normal, normalSize);
    report(1.0f);
    return result;
}

} // namespace tessera::creature
