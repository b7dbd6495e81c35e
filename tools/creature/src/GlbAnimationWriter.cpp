#include "GlbAnimationWriter.h"

#include <map>

namespace tessera::creature {

namespace {

using character::AnimationInterpolation;
using character::AnimationPath;
using nlohmann::json;

const char* pathName(AnimationPath path) {
    switch (path) {
    case AnimationPath::Translation: return "translation";
    case AnimationPath::Rotation: return "rotation";
    case AnimationPath::Scale: return "scale";
    }
    return "translation";
}

const char* interpolationName(AnimationInterpolation interpolation) {
    switch (interpolation) {
    case AnimationInterpolation::Step: return "STEP";
    case AnimationInterpolation::Linear: return "LINEAR";
    case AnimationInterpolation::CubicSpline: return "CUBICSPLINE";
    }
    return "LINEAR";
}

uint32_t addOutput(GlbBuilder& glb, const character::AnimationChannel& channel) {
    const bool rotation = channel.path == AnimationPath::Rotation;
    const int components = rotation ? 4 : 3;
    std::vector<float> values;
    values.reserve(channel.values.size() * components);
    for (const glm::vec4& value : channel.values) {
        for (int c = 0; c < components; ++c) values.push_back(value[c]);
    }
    return glb.addAccessor(values, GlbComponent::F32, rotation ? "VEC4" : "VEC3", channel.values.size(),
                           GlbTarget::None);
}

} // namespace

json writeAnimations(GlbBuilder& glb, const std::vector<character::AnimationClip>& clips) {
    json animations = json::array();
    // Walk and idle clips key every joint at the same times; sharing the
    // input accessor keeps the file small. std::map keeps it deterministic.
    std::map<std::vector<float>, uint32_t> inputs;
    for (const character::AnimationClip& clip : clips) {
        if (clip.channels.empty()) continue;
        json samplers = json::array();
        json channels = json::array();
        for (const character::AnimationChannel& channel : clip.channels) {
            auto [it, inserted] = inputs.try_emplace(channel.times, 0u);
            if (inserted) {
                it->second = glb.addAccessor(channel.times, GlbComponent::F32, "SCALAR", channel.times.size(),
                                             GlbTarget::None, json::array({channel.times.front()}),
                                             json::array({channel.times.back()}));
            }
            uint32_t sampler = static_cast<uint32_t>(samplers.size());
            samplers.push_back({{"input", it->second},
                                {"output", addOutput(glb, channel)},
                                {"interpolation", interpolationName(channel.interpolation)}});
            channels.push_back({{"sampler", sampler}, {"target", {{"node", channel.node}, {"path", pathName(channel.path)}}}});
        }
        json animation = {{"samplers", samplers}, {"channels", channels}};
        if (!clip.name.empty()) animation["name"] = clip.name;
        animations.push_back(std::move(animation));
    }
    return animations;
}

} // namespace tessera::creature
