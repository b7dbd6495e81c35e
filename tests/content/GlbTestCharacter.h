#pragma once
/// @file GlbTestCharacter.h
/// A small synthetic character for the .glb exporter tests: a skinned tube
/// with a UV seam, three joints plus one plain node, three clips (linear,
/// step and cubic-spline keys, translation, rotation and scale) and small
/// base colour, normal and 16-bit displacement maps.

#include "tessera/character/CharacterAsset.h"
#include "tessera/core/Random.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace tessera::test {

inline character::TextureImage makeTestImage(uint32_t width, uint32_t height, character::TextureFormat format,
                                             uint32_t salt) {
    character::TextureImage image;
    image.width = width;
    image.height = height;
    image.format = format;
    image.bytes.resize(size_t(width) * height * image.bytesPerTexel());
    Random random(salt);  // any fixed pattern will do
    for (uint8_t& byte : image.bytes) byte = static_cast<uint8_t>(random.nextU32() >> 24);
    return image;
}

/// The tube runs up +Y from 0 to 2 over `rings` rings of `segments` + 1
/// vertices (the last column repeats the first with u = 1: the seam).
inline character::CharacterAsset makeTestCharacter(int segments = 6, int rings = 4) {
    using namespace character;
    CharacterAsset asset;
    asset.name = "tube";
    const char* names[] = {"root", "spine", "head", "prop"};
    const int32_t parents[] = {-1, 0, 1, 0};
    const glm::vec3 offsets[] = {{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.5f, 0.25f, 0.0f}};
    for (int n = 0; n < 4; ++n) {
        SkeletonNode node;
        node.name = names[n];
        node.parent = parents[n];
        node.rest.translation = offsets[n];
        asset.skeleton.nodes.push_back(node);
    }
    // Joint j sits at height j; its inverse bind undoes that.
    for (uint32_t j = 0; j < 3; ++j) {
        SkinBinding binding;
        binding.node = j;
        binding.inverseBind[3] = glm::vec4(0.0f, -float(j), 0.0f, 1.0f);
        asset.cage.bindings.push_back(binding);
    }

    const float kPi = 3.14159265358979f;
    for (int r = 0; r < rings; ++r) {
        float y = 2.0f * float(r) / float(rings - 1);
        for (int s = 0; s <= segments; ++s) {
            float a = 2.0f * kPi * float(s % segments) / float(segments);
            CageVertex v;
            v.position = {0.3f * std::cos(a), y, 0.3f * std::sin(a)};
            v.normal = glm::normalize(glm::vec3(std::cos(a), 0.0f, std::sin(a)));
            // +u runs around the tube; the bitangent (+v) then points down -Y
            // in this frame, hence w = -1.
            v.tangent = glm::vec4(glm::normalize(glm::vec3(-std::sin(a), 0.0f, std::cos(a))), -1.0f);
            v.uv = {float(s) / float(segments), 1.0f - y / 2.0f};
            // Two joints per vertex, weights exact in binary so they sum to 1.
            uint16_t lower = static_cast<uint16_t>(std::min(int(y), 1));
            float t = std::clamp(y - float(lower), 0.0f, 1.0f);
            float upper = std::round(t * 4.0f) / 4.0f;
            v.joints = {lower, static_cast<uint16_t>(lower + 1), 0, 0};
            v.weights = {1.0f - upper, upper, 0.0f, 0.0f};
            if (upper == 0.0f) v.joints.y = 0;  // no joint repeated with a non-zero weight
            asset.cage.vertices.push_back(v);
        }
    }
    const uint32_t row = static_cast<uint32_t>(segments + 1);
    for (uint32_t r = 0; r + 1 < static_cast<uint32_t>(rings); ++r) {
        for (uint32_t s = 0; s < static_cast<uint32_t>(segments); ++s) {
            uint32_t a = r * row + s, b = a + 1, c = a + row, d = c + 1;
            asset.cage.indices.insert(asset.cage.indices.end(), {a, c, b, b, c, d});
        }
    }

    AnimationClip bend{"bend", {}};
    AnimationChannel spine{1, AnimationPath::Rotation, AnimationInterpolation::Linear, {0.0f, 0.5f, 1.0f}, {}};
    for (float angle : {0.0f, 0.5f, 0.0f}) {
        glm::quat q = glm::angleAxis(angle, glm::vec3(0.0f, 0.0f, 1.0f));
        spine.values.emplace_back(q.x, q.y, q.z, q.w);
    }
    AnimationChannel sway{0, AnimationPath::Translation, AnimationInterpolation::Linear, {0.0f, 0.5f, 1.0f},
                          {{0.0f, 0.0f, 0.0f, 0.0f}, {0.1f, 0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f, 0.0f}}};
    bend.channels = {spine, sway};
    AnimationClip blink{"blink", {}};
    blink.channels.push_back({2, AnimationPath::Scale, AnimationInterpolation::Step, {0.0f, 0.25f},
                              {{1.0f, 1.0f, 1.0f, 0.0f}, {1.0f, 0.5f, 1.0f, 0.0f}}});
    AnimationClip nod{"nod", {}};
    glm::quat q = glm::angleAxis(0.25f, glm::vec3(1.0f, 0.0f, 0.0f));
    nod.channels.push_back({2, AnimationPath::Rotation, AnimationInterpolation::CubicSpline, {0.0f, 2.0f},
                            {{0, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, {q.x, q.y, q.z, q.w}, {0, 0, 0, 0}}});
    asset.clips = {bend, blink, nod};

    asset.baseColor = makeTestImage(8, 8, TextureFormat::Rgba8, 1);
    asset.normalMap = makeTestImage(8, 8, TextureFormat::Rgba8, 2);
    asset.displacement = DisplacementMap{makeTestImage(16, 8, TextureFormat::R16, 3), 0.0123f, -0.0051f};
    return asset;
}

} // namespace tessera::test
