#include "CreatureTexture.h"

#include "FeatureColour.h"
#include "SdfNoise.h"
#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

namespace {

glm::vec3 skinColour(const glm::vec3& p, const SkinSample& s, const CreatureParams& c) {
    float hue = 0.5f + 0.5f * c.skinHue;
    glm::vec3 olive(0.40f, 0.45f, 0.22f), greyGreen(0.38f, 0.45f, 0.36f);
    glm::vec3 colour = olive + (greyGreen - olive) * hue;
    // Blotches and a fine mottle.
    float blotch = noise::fbm(p * 6.0f, c.seed * 31u + 7u, 3);
    float mottle = noise::gradient(p * 45.0f, c.seed * 31u + 9u);
    colour *= 1.0f + 0.22f * blotch + 0.06f * mottle;
    // Paler belly and throat.
    float belly = std::clamp((p.z - c.at(Joint::Spine).z - 0.12f) * 8.0f, 0.0f, 1.0f) *
                  std::clamp((c.at(Joint::Chest).y - p.y) * 6.0f, 0.0f, 1.0f);
    colour += (glm::vec3(0.55f, 0.55f, 0.36f) - colour) * (0.35f * belly);
    colour *= 1.0f - 0.45f * s.crease;
    glm::vec3 wart(0.44f, 0.36f, 0.22f);
    colour += (wart - colour) * std::min(1.0f, s.wart * 1.5f);
    return glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
}

/// Where the near tier shows this texel: the baker measures the sculpt
/// along the cage's normal, so colour the shape's point along that normal
/// too (a projection along the field's gradient lands a few millimetres
/// off, which at close range puts a pupil or a stitch beside its relief).
glm::vec3 onShapeAlongNormal(const CreatureSdf& sdf, const glm::vec3& q, const glm::vec3& n) {
    float len = glm::length(n);
    if (len < 1e-6f) return sdf.project(q, 1, 0.04f, nullptr);
    glm::vec3 dir = n / len;
    // Secant-free steps: the field is close to a distance, so stepping by
    // it along a ray that meets the surface near-perpendicularly converges;
    // the cap keeps a grazing ray from running off.
    float t = 0.0f;
    for (int k = 0; k < 4; ++k) t = std::clamp(t - sdf.distance(q + dir * t), -0.04f, 0.04f);
    return q + dir * t;
}

} // namespace

character::TextureImage paintBaseColor(const character::CageMesh& cage, const CreatureSdf& sdf,
                                       const SkinDetail& skin, const CreatureParams& params, uint32_t size) {
    const size_t texels = static_cast<size_t>(size) * size;
    std::vector<glm::vec3> where(texels), normal(texels);
    std::vector<uint8_t> covered(texels, 0);
    const float fs = static_cast<float>(size);
    for (size_t t = 0; t < cage.indices.size(); t += 3) {
        const auto& a = cage.vertices[cage.indices[t]];
        const auto& b = cage.vertices[cage.indices[t + 1]];
        const auto& c = cage.vertices[cage.indices[t + 2]];
        glm::vec2 pa = a.uv * fs, pb = b.uv * fs, pc = c.uv * fs;
        float area = (pb.x - pa.x) * (pc.y - pa.y) - (pc.x - pa.x) * (pb.y - pa.y);
        if (std::abs(area) < 1e-12f) continue;
        int x0 = std::max(0, static_cast<int>(std::floor(std::min({pa.x, pb.x, pc.x}))));
        int x1 = std::min(static_cast<int>(size) - 1, static_cast<int>(std::ceil(std::max({pa.x, pb.x, pc.x}))));
        int y0 = std::max(0, static_cast<int>(std::floor(std::min({pa.y, pb.y, pc.y}))));
        int y1 = std::min(static_cast<int>(size) - 1, static_cast<int>(std::ceil(std::max({pa.y, pb.y, pc.y}))));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                glm::vec2 q(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                float w1 = ((q.x - pa.x) * (pc.y - pa.y) - (pc.x - pa.x) * (q.y - pa.y)) / area;
                float w2 = ((pb.x - pa.x) * (q.y - pa.y) - (q.x - pa.x) * (pb.y - pa.y)) / area;
                float w0 = 1.0f - w1 - w2;
                if (w0 < -1e-4f || w1 < -1e-4f || w2 < -1e-4f) continue;
                size_t i = static_cast<size_t>(y) * size + static_cast<size_t>(x);
                where[i] = a.position * w0 + b.position * w1 + c.position * w2;
                normal[i] = a.normal * w0 + b.normal * w1 + c.normal * w2;
                covered[i] = 1;
            }
        }
    }

    std::vector<glm::vec3> colour(texels, glm::vec3(0.0f));
    core::parallelForRanges(uint32_t(texels), 256, 0, [&](core::IndexRange range) {
        const size_t begin = range.begin, end = range.end;
        for (size_t i = begin; i < end; ++i) {
            if (!covered[i]) continue;
            glm::vec3 p = onShapeAlongNormal(sdf, where[i], normal[i]);
            SkinSample s = skin.sample(p);
            colour[i] = featureColour(s.feature, p, params, skinColour(p, s, params));
        }
    });

    // Gutter dilation: grow the charts a texel per pass into empty texels.
    std::vector<uint8_t> filled = covered;
    for (int pass = 0; pass < 16; ++pass) {
        std::vector<uint8_t> next = filled;
        std::vector<glm::vec3> grown = colour;
        for (uint32_t y = 0; y < size; ++y) {
            for (uint32_t x = 0; x < size; ++x) {
                size_t i = static_cast<size_t>(y) * size + x;
                if (filled[i]) continue;
                glm::vec3 sum(0.0f);
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        int nx = static_cast<int>(x) + dx, ny = static_cast<int>(y) + dy;
                        if (nx < 0 || ny < 0 || nx >= static_cast<int>(size) || ny >= static_cast<int>(size)) continue;
                        size_t j = static_cast<size_t>(ny) * size + static_cast<size_t>(nx);
                        if (filled[j]) { sum += colour[j]; ++count; }
                    }
                if (count > 0) { grown[i] = sum / static_cast<float>(count); next[i] = 1; }
            }
        }
        filled = std::move(next);
        colour = std::move(grown);
    }
    glm::vec3 fallback = skinColour(params.at(Joint::Spine), SkinSample{}, params);

    character::TextureImage image;
    image.width = image.height = size;
    image.format = character::TextureFormat::Rgba8;
    image.bytes.resize(texels * 4);
    for (size_t i = 0; i < texels; ++i) {
        glm::vec3 c = filled[i] ? colour[i] : fallback;
        for (int k = 0; k < 3; ++k) image.bytes[i * 4 + static_cast<size_t>(k)] = static_cast<uint8_t>(std::lround(c[k] * 255.0f));
        image.bytes[i * 4 + 3] = 255;
    }
    return image;
}

} // namespace tessera::creature
