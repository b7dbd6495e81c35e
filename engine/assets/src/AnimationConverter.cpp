#include "AnimationConverter.h"

#include "GltfError.h"

namespace tessera::assets {

std::vector<character::AnimationClip> convertAnimations(const tinygltf::Model& model, const SkeletonBuild& skeleton) {
    AccessorReader reader(model);
    std::vector<character::AnimationClip> clips;
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& animation = model.animations[a];
        character::AnimationClip clip;
        clip.name = animation.name.empty() ? "animation" + std::to_string(a) : animation.name;
        for (const tinygltf::AnimationChannel& channel : animation.channels) {
            using character::AnimationPath;
            AnimationPath path;
            if (channel.target_path == "translation") path = AnimationPath::Translation;
            else if (channel.target_path == "rotation") path = AnimationPath::Rotation;
            else if (channel.target_path == "scale") path = AnimationPath::Scale;
            else continue;
            auto node = skeleton.nodeToIndex.find(channel.target_node);
            if (node == skeleton.nodeToIndex.end()) continue;  // animates a node outside the scene
            const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
            character::AnimationChannel out;
            out.node = node->second;
            out.path = path;
            out.interpolation = sampler.interpolation == "STEP"          ? character::AnimationInterpolation::Step
                                : sampler.interpolation == "CUBICSPLINE" ? character::AnimationInterpolation::CubicSpline
                                                                         : character::AnimationInterpolation::Linear;
            out.times = reader.readFloats(sampler.input);
            std::vector<float> values = reader.readFloats(sampler.output);
            size_t n = path == AnimationPath::Rotation ? 4 : 3;
            size_t perKey = out.interpolation == character::AnimationInterpolation::CubicSpline ? 3 : 1;
            if (values.size() != out.times.size() * perKey * n)
                raise("/animations/" + std::to_string(a), "sampler output count does not match its input");
            for (size_t v = 0; v + n <= values.size(); v += n)
                out.values.emplace_back(values[v], values[v + 1], values[v + 2], n == 4 ? values[v + 3] : 0.0f);
            clip.channels.push_back(std::move(out));
        }
        clips.push_back(std::move(clip));
    }
    return clips;
}

} // namespace tessera::assets
