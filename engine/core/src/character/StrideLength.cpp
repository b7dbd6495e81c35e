#include "tessera/character/StrideLength.h"

#include "tessera/character/Pose.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace tessera::character {

namespace {

// A foot is in stance while it is within this fraction of its vertical range
// above its lowest point.
constexpr float kStanceFraction = 0.15f;
// Fewest stance samples per foot (the lowest ones, if the band holds fewer).
constexpr size_t kMinStanceSamples = 3;
// A foot walks when it lifts by this fraction of its leg length...
constexpr float kMinLiftFraction = 0.01f;
// ... and sweeps this fraction of it horizontally relative to the hips.
constexpr float kMinSweepFraction = 0.05f;
// Leaf-joint feet lie in this fraction of the skeleton's height above its
// lowest joint.
constexpr float kFootBandFraction = 0.25f;
// Two feet stand at least this fraction of the skeleton's size apart.
constexpr float kMinFootSeparation = 0.02f;
constexpr uint32_t kMinSamples = 8;

bool hasFootName(const std::string& name) {
    std::string lower(name.size(), '\0');
    std::transform(name.begin(), name.end(), lower.begin(),
                   [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
    return lower.find("foot") != std::string::npos || lower.find("ankle") != std::string::npos ||
           lower.find("toe") != std::string::npos;
}

glm::vec3 position(const glm::mat4& m) {
    return glm::vec3(m[3]);
}

// Everything about the rest pose that foot selection needs.
struct RestSkeleton {
    std::vector<glm::vec3> positions; // world positions of every node at rest
    std::vector<uint32_t> depth;      // number of ancestors
    std::vector<bool> joint;          // in the skin (or every node without one)
    std::vector<bool> leaf;           // a joint with no joint below it
    float lowest = 0.0f, height = 0.0f, size = 0.0f;
};

RestSkeleton describeRest(const CharacterAsset& asset) {
    const Skeleton& skeleton = asset.skeleton;
    const size_t n = skeleton.nodes.size();
    RestSkeleton rest;
    Pose pose(skeleton);
    rest.positions.resize(n);
    for (size_t i = 0; i < n; ++i) rest.positions[i] = position(pose.globals()[i]);
    rest.depth.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        const int32_t parent = skeleton.nodes[i].parent;
        if (parent >= 0) rest.depth[i] = rest.depth[static_cast<size_t>(parent)] + 1;
    }
    rest.joint.assign(n, asset.cage.bindings.empty());
    for (const SkinBinding& binding : asset.cage.bindings)
        if (binding.node < n) rest.joint[binding.node] = true;
    // A node has a joint below it when a child is a joint or has one below it.
    std::vector<bool> jointBelow(n, false);
    for (size_t i = n; i-- > 0;) {
        const int32_t parent = skeleton.nodes[i].parent;
        if (parent >= 0 && (rest.joint[i] || jointBelow[i])) jointBelow[static_cast<size_t>(parent)] = true;
    }
    rest.leaf.resize(n);
    for (size_t i = 0; i < n; ++i) rest.leaf[i] = rest.joint[i] && !jointBelow[i];

    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    bool anyJoint = false;
    for (size_t i = 0; i < n; ++i) {
        if (!rest.joint[i]) continue;
        anyJoint = true;
        lo = glm::min(lo, rest.positions[i]);
        hi = glm::max(hi, rest.positions[i]);
    }
    if (anyJoint) {
        rest.lowest = lo.y;
        rest.height = hi.y - lo.y;
        rest.size = glm::length(hi - lo);
    }
    return rest;
}

std::vector<int32_t> ancestry(const Skeleton& skeleton, uint32_t node) {
    std::vector<int32_t> chain;
    for (int32_t i = static_cast<int32_t>(node); i >= 0; i = skeleton.nodes[static_cast<size_t>(i)].parent)
        chain.push_back(i);
    return chain; // node first, root last
}

// The nearest common ancestor (or self) of two nodes, or -1 when they are in
// different trees.
int32_t commonAncestor(const Skeleton& skeleton, uint32_t a, uint32_t b) {
    const std::vector<int32_t> above = ancestry(skeleton, b);
    for (int32_t x : ancestry(skeleton, a))
        if (std::find(above.begin(), above.end(), x) != above.end()) return x;
    return -1;
}

// Two feet from `candidates`: the first is the best by `better`; its partner
// is on another limb, the candidate whose common ancestor with the first is
// nearest the root (another leg rather than another toe of the same foot),
// then the best by `better`. Neither may be above the other in the
// hierarchy, and they must stand apart. Only the first when none qualifies.
template <class Better>
std::vector<uint32_t> footPair(const RestSkeleton& rest, const Skeleton& skeleton,
                               const std::vector<uint32_t>& candidates, Better better) {
    if (candidates.empty()) return {};
    const uint32_t first = *std::min_element(candidates.begin(), candidates.end(), better);
    const float apart = kMinFootSeparation * rest.size;
    int64_t partner = -1;
    uint32_t partnerJoin = 0;
    for (uint32_t c : candidates) {
        const int32_t join = commonAncestor(skeleton, first, c);
        if (join == static_cast<int32_t>(first) || join == static_cast<int32_t>(c)) continue;
        if (glm::length(rest.positions[c] - rest.positions[first]) < apart) continue;
        const uint32_t joinDepth = join < 0 ? 0 : rest.depth[static_cast<size_t>(join)];
        if (partner < 0 || joinDepth < partnerJoin ||
            (joinDepth == partnerJoin && better(c, static_cast<uint32_t>(partner)))) {
            partner = c;
            partnerJoin = joinDepth;
        }
    }
    if (partner < 0) return {first};
    std::vector<uint32_t> feet{first, static_cast<uint32_t>(partner)};
    std::sort(feet.begin(), feet.end());
    return feet;
}

std::vector<uint32_t> chooseFeet(const RestSkeleton& rest, const Skeleton& skeleton) {
    const auto n = static_cast<uint32_t>(skeleton.nodes.size());
    if (!(rest.size > 0.0f)) return {};
    auto lower = [&](uint32_t a, uint32_t b) { return rest.positions[a].y < rest.positions[b].y; };

    // Named feet, nearest the root first (an ankle before its toe).
    std::vector<uint32_t> named;
    for (uint32_t i = 0; i < n; ++i)
        if (rest.joint[i] && hasFootName(skeleton.nodes[i].name)) named.push_back(i);
    const std::vector<uint32_t> namedFeet = footPair(rest, skeleton, named, [&](uint32_t a, uint32_t b) {
        return rest.depth[a] != rest.depth[b] ? rest.depth[a] < rest.depth[b] : lower(a, b);
    });
    if (namedFeet.size() == 2) return namedFeet;

    // The lowest leaf joints, near the ground (so that one foot is not paired
    // with a hand).
    const float band = rest.lowest + kFootBandFraction * rest.height;
    std::vector<uint32_t> leaves;
    for (uint32_t i = 0; i < n; ++i)
        if (rest.leaf[i] && rest.positions[i].y <= band) leaves.push_back(i);
    const std::vector<uint32_t> leafFeet = footPair(rest, skeleton, leaves, lower);
    if (leafFeet.size() == 2) return leafFeet;

    // One named foot (a one-legged or half-named rig) is better than none,
    // if it hangs from something to measure it against.
    if (namedFeet.size() == 1 && skeleton.nodes[namedFeet[0]].parent >= 0) return namedFeet;
    return {};
}

// The hips: the feet's nearest common ancestor (a single foot's parent), or
// -1 when they share none.
int32_t hipsOf(const Skeleton& skeleton, const std::vector<uint32_t>& feet) {
    if (feet.size() == 1) return skeleton.nodes[feet[0]].parent;
    return commonAncestor(skeleton, feet[0], feet[1]);
}

// The rest-pose bone lengths from `foot` up to `hips` (to the root when -1).
float legLength(const RestSkeleton& rest, const Skeleton& skeleton, uint32_t foot, int32_t hips) {
    float length = 0.0f;
    for (int32_t i = static_cast<int32_t>(foot); i >= 0 && i != hips;) {
        const int32_t parent = skeleton.nodes[static_cast<size_t>(i)].parent;
        if (parent < 0) break;
        length += glm::length(rest.positions[static_cast<size_t>(i)] - rest.positions[static_cast<size_t>(parent)]);
        i = parent;
    }
    return length;
}

float median(std::vector<float> values) {
    if (values.empty()) return 0.0f;
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
    float m = values[mid];
    if (values.size() % 2 == 0)
        m = 0.5f * (m + *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid)));
    return m;
}

// One foot's track over the samples.
struct FootTrack {
    std::vector<float> height;       // world y
    std::vector<glm::vec2> relative; // horizontal (x, z) position relative to the hips
    std::vector<glm::vec2> velocity; // its time derivative
    std::vector<size_t> stance;      // the low samples (stance once moving backward)
    bool walks = false;
};

} // namespace

StrideMeasure measureStride(const CharacterAsset& asset, size_t clipIndex, uint32_t samples) {
    StrideMeasure result;
    const Skeleton& skeleton = asset.skeleton;
    if (skeleton.nodes.empty() || !skeleton.isParentFirst()) return result;

    const RestSkeleton rest = describeRest(asset);
    result.feet = chooseFeet(rest, skeleton);
    if (result.feet.empty() || clipIndex >= asset.clips.size()) return result;
    const AnimationClip& clip = asset.clips[clipIndex];
    const float duration = clip.duration();
    if (!(duration > 0.0f) || !std::isfinite(duration)) return result;

    const int32_t hips = hipsOf(skeleton, result.feet);
    const uint32_t n = std::max(samples, kMinSamples);
    const float dt = duration / static_cast<float>(n);

    // Pose every sample once; keep the feet's and the hips' world positions.
    std::vector<FootTrack> tracks(result.feet.size());
    Pose pose(skeleton);
    for (uint32_t s = 0; s <= n; ++s) {
        pose.reset();
        pose.apply(clip, duration * static_cast<float>(s) / static_cast<float>(n), false);
        pose.computeGlobals();
        const glm::vec3 hipsAt = hips >= 0 ? position(pose.globals()[static_cast<size_t>(hips)]) : glm::vec3(0.0f);
        for (size_t f = 0; f < result.feet.size(); ++f) {
            const glm::vec3 foot = position(pose.globals()[result.feet[f]]);
            tracks[f].height.push_back(foot.y);
            tracks[f].relative.emplace_back(foot.x - hipsAt.x, foot.z - hipsAt.z);
        }
    }

    // Velocities, stance, and whether each foot walks at all.
    glm::vec2 lowVelocitySum(0.0f);
    for (size_t f = 0; f < tracks.size(); ++f) {
        FootTrack& t = tracks[f];
        t.velocity.resize(n + 1);
        for (uint32_t s = 0; s <= n; ++s) {
            const uint32_t a = s == 0 ? 0 : s - 1, b = s == n ? n : s + 1;
            t.velocity[s] = (t.relative[b] - t.relative[a]) / (dt * static_cast<float>(b - a));
        }
        const auto [lo, hi] = std::minmax_element(t.height.begin(), t.height.end());
        const float lift = *hi - *lo;
        glm::vec2 rlo = t.relative[0], rhi = t.relative[0];
        for (const glm::vec2& r : t.relative) {
            rlo = glm::min(rlo, r);
            rhi = glm::max(rhi, r);
        }
        const float sweep = glm::length(rhi - rlo);
        const float leg = legLength(rest, skeleton, result.feet[f], hips);
        const float scale = leg > 0.0f ? leg : rest.size;
        t.walks = lift >= kMinLiftFraction * scale && sweep >= kMinSweepFraction * scale;
        if (!t.walks) continue;

        // The last sample repeats the first in a looping clip; leave it out
        // of the stance so that pose does not count twice.
        std::vector<size_t> order(n);
        for (size_t s = 0; s < n; ++s) order[s] = s;
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return t.height[a] < t.height[b]; });
        const float limit = *lo + kStanceFraction * lift;
        for (size_t k = 0; k < order.size(); ++k)
            if (t.height[order[k]] <= limit || k < kMinStanceSamples) t.stance.push_back(order[k]);
        for (size_t s : t.stance) lowVelocitySum += t.velocity[s];
    }

    // Forward is where the low feet are not going.
    const float sumLength = glm::length(lowVelocitySum);
    if (!(sumLength > 0.0f) || !std::isfinite(sumLength)) return result;
    const glm::vec2 forward = -lowVelocitySum / sumLength;

    float speedSum = 0.0f;
    size_t walkingFeet = 0;
    for (const FootTrack& t : tracks) {
        if (!t.walks) continue;
        // A planted foot moves backward relative to the hips: a low sample
        // moving forward is the end of a swing (or a foot that slides
        // anyway), not stance.
        std::vector<float> backward;
        backward.reserve(t.stance.size());
        for (size_t s : t.stance) {
            const float speed = -glm::dot(t.velocity[s], forward);
            if (speed > 0.0f) backward.push_back(speed);
        }
        if (backward.empty()) continue;
        speedSum += median(std::move(backward));
        ++walkingFeet;
    }
    const float speed = walkingFeet ? speedSum / static_cast<float>(walkingFeet) : 0.0f;
    if (!(speed > 0.0f) || !std::isfinite(speed)) return result;
    result.naturalSpeed = speed;
    result.strideLength = speed * duration;
    return result;
}

} // namespace tessera::character
