#include "tessera/character/Pose.h"

#include "tessera/character/AnimationSampler.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::character {

Pose::Pose(const Skeleton& skeleton) : mSkeleton(&skeleton) {
    assert(skeleton.isParentFirst());
    mLocals.resize(skeleton.nodes.size());
    mGlobals.resize(skeleton.nodes.size(), glm::mat4(1.0f));
    reset();
    computeGlobals();
}

void Pose::reset() {
    for (size_t i = 0; i < mLocals.size(); ++i) mLocals[i] = mSkeleton->nodes[i].rest;
}

void Pose::apply(const AnimationClip& clip, float seconds, bool loop) {
    const float duration = clip.duration();
    float t = 0.0f;
    if (duration > 0.0f && std::isfinite(seconds)) {
        if (loop) {
            t = std::fmod(seconds, duration);
            if (t < 0.0f) t += duration;
        } else {
            t = std::clamp(seconds, 0.0f, duration);
        }
    }
    for (const AnimationChannel& channel : clip.channels) {
        if (channel.node >= mLocals.size() || !isChannelSampleable(channel)) continue;
        const glm::vec4 v = sampleChannel(channel, t);
        NodeTransform& local = mLocals[channel.node];
        switch (channel.path) {
        case AnimationPath::Translation:
            local.translation = glm::vec3(v);
            break;
        case AnimationPath::Rotation:
            local.rotation = glm::quat(v.w, v.x, v.y, v.z);
            break;
        case AnimationPath::Scale:
            local.scale = glm::vec3(v);
            break;
        }
    }
}

void Pose::computeGlobals() {
    for (size_t i = 0; i < mLocals.size(); ++i) {
        const int32_t parent = mSkeleton->nodes[i].parent;
        const glm::mat4 local = mLocals[i].matrix();
        mGlobals[i] = parent < 0 ? local : mGlobals[static_cast<size_t>(parent)] * local;
    }
}

void Pose::palette(const CageMesh& cage, std::vector<glm::mat4>& out) const {
    out.resize(cage.bindings.size());
    for (size_t i = 0; i < cage.bindings.size(); ++i) {
        const SkinBinding& binding = cage.bindings[i];
        assert(binding.node < mGlobals.size());
        out[i] = mGlobals[binding.node] * binding.inverseBind;
    }
}

} // namespace tessera::character
