#include "tessera/character/ImpostorBaker.h"

#include "ImpostorLayerImage.h"
#include "ImpostorRasterizer.h"
#include "ImpostorTexture.h"

#include "tessera/character/AnimatedBounds.h"
#include "tessera/character/SkinnedVertex.h"
#include "tessera/core/ParallelFor.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessera::character {
namespace {

constexpr uint32_t kCell = TS_IMPOSTOR_CELL;
constexpr uint32_t kBorder = TS_IMPOSTOR_BORDER;
using Raster = ImpostorRasterizer;

// What the middle tier draws without a base colour map (GpuCharacter's
// constant texture): the card must not change shade where the tiers meet.
constexpr float kNoMapGrey = 150.0f;

bool usableBaseColor(const CharacterAsset& asset) {
    const auto& t = asset.baseColor;
    return t && !t->empty() && t->format == TextureFormat::Rgba8 &&
           t->bytes.size() == size_t(t->width) * t->height * t->bytesPerTexel();
}

// How many times to halve the base colour map so one of its texels is about
// one impostor sample: the cage's mean texels per model unit (texture area
// over surface area, bind pose) times the sample pitch (the sphere's
// diameter over the samples a side), halved while it is two or more.
uint32_t textureLevels(const CharacterAsset& asset, float radius) {
    const TextureImage& map = *asset.baseColor;
    const CageMesh& cage = asset.cage;
    double surface = 0.0, texels = 0.0;
    for (size_t t = 0; t + 2 < cage.indices.size(); t += 3) {
        const CageVertex& a = cage.vertices[cage.indices[t]];
        const CageVertex& b = cage.vertices[cage.indices[t + 1]];
        const CageVertex& c = cage.vertices[cage.indices[t + 2]];
        surface += 0.5 * double(glm::length(glm::cross(b.position - a.position, c.position - a.position)));
        const glm::dvec2 ab = glm::dvec2(b.uv - a.uv) * glm::dvec2(map.width, map.height);
        const glm::dvec2 ac = glm::dvec2(c.uv - a.uv) * glm::dvec2(map.width, map.height);
        texels += 0.5 * std::abs(ab.x * ac.y - ab.y * ac.x);
    }
    if (!(surface > 0.0) || !(texels > 0.0)) return 0;
    double footprint = std::sqrt(texels / surface) * 2.0 * double(radius) / double(Raster::kSide);
    uint32_t levels = 0;
    while (footprint >= 2.0 && levels < 16) {
        footprint *= 0.5;
        ++levels;
    }
    return levels;
}

ImpostorTexture baseColour(const CharacterAsset& asset, float radius) {
    if (!usableBaseColor(asset)) return ImpostorTexture(glm::vec3(kNoMapGrey));
    return ImpostorTexture(*asset.baseColor, textureLevels(asset, radius));
}

// Everything a layer's bake reads, shared read-only by the threads.
struct BakeInputs {
    const CharacterAsset& asset;
    const BakedAnimation& baked;
    const ImpostorTexture& texture;
    glm::vec3 centre;
    float radius;
};

// Resolves cell `cell`'s samples into its texels of `image`: coverage, the
// mean base colour and the normalised mean normal of the covered samples.
void resolveCell(const Raster& raster, const BakeInputs& in, const std::vector<SkinnedVertex>& skinned, glm::uvec2 cell,
                 ImpostorLayerImage& image) {
    const std::vector<uint32_t>& indices = in.asset.cage.indices;
    constexpr uint32_t n = Raster::kSamplesPerTexel;
    for (uint32_t ty = 0; ty < Raster::kInnerTexels; ++ty) {
        for (uint32_t tx = 0; tx < Raster::kInnerTexels; ++tx) {
            glm::vec3 colour(0.0f), normal(0.0f);
            uint32_t covered = 0;
            for (uint32_t sy = 0; sy < n; ++sy) {
                for (uint32_t sx = 0; sx < n; ++sx) {
                    const Raster::Sample& s = raster.sample(tx * n + sx, ty * n + sy);
                    if (s.triangle == Raster::kNone) continue;
                    const SkinnedVertex& a = skinned[indices[3 * size_t(s.triangle)]];
                    const SkinnedVertex& b = skinned[indices[3 * size_t(s.triangle) + 1]];
                    const SkinnedVertex& c = skinned[indices[3 * size_t(s.triangle) + 2]];
                    const float w0 = 1.0f - s.weight1 - s.weight2;
                    colour += in.texture.sample(a.uv * w0 + b.uv * s.weight1 + c.uv * s.weight2);
                    const glm::vec3 nrm = a.normal * w0 + b.normal * s.weight1 + c.normal * s.weight2;
                    const float l = glm::length(nrm);
                    if (l > 1e-12f) normal += nrm / l;
                    ++covered;
                }
            }
            if (!covered) continue;
            ImpostorTexel& texel = image.at(cell.x * kCell + kBorder + tx, cell.y * kCell + kBorder + ty);
            texel.coverage = float(covered) / float(n * n);
            texel.colour = colour / float(covered);
            const float l = glm::length(normal);
            texel.normal = l > 1e-12f ? normal / l : glm::vec3(0.0f, 1.0f, 0.0f);
        }
    }
}

// Layer `layer` (clip-major, phase-minor) into `atlas`. Reads only `in` and
// writes only its own layer's bytes, so layers may run in any order on any
// thread.
void bakeLayer(const BakeInputs& in, uint32_t layer, ImpostorAtlas& atlas) {
    const CharacterAsset& asset = in.asset;
    const uint32_t clipIndex = layer / TS_IMPOSTOR_PHASES, phaseIndex = layer % TS_IMPOSTOR_PHASES;
    const uint32_t clip = asset.clips.empty() ? kBakedRestPose : bakedClipIndex(clipIndex);
    const bool looping = in.baked.clips[clip].frames.w != 0u;
    const float phase = float(phaseIndex) / float(looping ? TS_IMPOSTOR_PHASES : TS_IMPOSTOR_PHASES - 1u);
    std::vector<glm::mat4> palette;
    evaluateBakedPalette(in.baked, clip, phase, palette);
    std::vector<SkinnedVertex> skinned(asset.cage.vertices.size());
    for (size_t v = 0; v < skinned.size(); ++v) skinned[v] = skinVertex(asset.cage.vertices[v], palette);

    ImpostorLayerImage image;
    Raster raster;
    std::vector<glm::vec3> projected(skinned.size());
    const std::vector<uint32_t>& indices = asset.cage.indices;
    for (uint32_t row = 0; row < TS_IMPOSTOR_VIEWS; ++row) {
        for (uint32_t column = 0; column < TS_IMPOSTOR_VIEWS; ++column) {
            const glm::uvec2 cell(column, row);
            const glm::vec3 d = shader::tsImpostorCellDirection(cell);
            for (size_t v = 0; v < skinned.size(); ++v)
                projected[v] = shader::tsImpostorProject(skinned[v].position, d, in.centre, in.radius);
            raster.clear();
            for (uint32_t t = 0; 3 * size_t(t) + 2 < indices.size(); ++t)
                raster.draw(t, projected[indices[3 * size_t(t)]], projected[indices[3 * size_t(t) + 1]],
                            projected[indices[3 * size_t(t) + 2]]);
            resolveCell(raster, in, skinned, cell, image);
            // A cell nothing covers shows grey facing its viewer.
            image.dilateCell(cell, glm::vec3(kNoMapGrey), d);
        }
    }
    image.store(atlas, layer);
}

} // namespace

ImpostorSphere impostorSphere(const CharacterAsset& asset) {
    return impostorSphere(animatedBounds(asset));
}

ImpostorSphere impostorSphere(const scene::Aabb& box) {
    if (box.isEmpty()) return {};
    const glm::vec3 centre = box.center();
    return {centre.y, glm::length(box.extents()) + glm::length(glm::vec2(centre.x, centre.z))};
}

uint32_t impostorLayerCount(uint32_t clips) {
    return std::max(clips, 1u) * TS_IMPOSTOR_PHASES;
}

ImpostorAtlas bakeImpostors(const CharacterAsset& asset, const ImpostorBakeSettings& settings) {
    ImpostorAtlas atlas;
    if (asset.cage.triangleCount() == 0) return atlas;
    const ImpostorSphere sphere = impostorSphere(asset);
    atlas.size = TS_IMPOSTOR_VIEWS * kCell;
    atlas.layers = impostorLayerCount(uint32_t(asset.clips.size()));
    atlas.centreY = sphere.centreY;
    atlas.radius = sphere.radius;
    atlas.albedo.resize(TS_IMPOSTOR_MIPS);
    atlas.normal.resize(TS_IMPOSTOR_MIPS);
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        atlas.albedo[m].resize(size_t(atlas.layerBytes(m)) * atlas.layers);
        atlas.normal[m].resize(size_t(atlas.layerBytes(m)) * atlas.layers);
    }
    const BakedAnimation baked = bakeAnimation(asset, settings.animation);
    // A degenerate cage (every vertex at one point) still divides by a
    // positive radius; its cells stay empty.
    const float radius = std::max(sphere.radius, 1e-6f);
    const ImpostorTexture texture = baseColour(asset, radius);
    const BakeInputs in{asset, baked, texture, glm::vec3(0.0f, sphere.centreY, 0.0f), radius};
    // The rest pose's phases are one pose: bake it once and copy it.
    const uint32_t distinct = asset.clips.empty() ? 1u : atlas.layers;
    core::parallelForRanges(distinct, 1, settings.threads, [&](core::IndexRange range) {
        for (uint32_t layer = range.begin; layer < range.end; ++layer) bakeLayer(in, layer, atlas);
    });
    for (uint32_t layer = distinct; layer < atlas.layers; ++layer) {
        for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
            const size_t bytes = size_t(atlas.layerBytes(m));
            std::memcpy(atlas.albedo[m].data() + bytes * layer, atlas.albedo[m].data(), bytes);
            std::memcpy(atlas.normal[m].data() + bytes * layer, atlas.normal[m].data(), bytes);
        }
    }
    return atlas;
}

} // namespace tessera::character
