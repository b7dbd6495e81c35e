#include "characters/CharacterCrowd.h"

#include "world/ContentLocator.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace tessera::runtime {
namespace {

constexpr float kOrbitDistance = 5.0f;      // metres, unless --orbit-distance
constexpr float kOrbitHeight = 1.6f;        // camera height above the site
constexpr float kLookHeight = 0.6f;         // the camera aims this high above the site

// The flattest spot (smallest height change over a character-sized
// neighbourhood) on a grid over the terrain's middle: crowds on a cliff face
// would be hidden by the ground.
glm::vec3 findSite(const terrain::Terrain& terrain) {
    const glm::vec2 size = terrain.field().worldSize();
    constexpr int kSteps = 32;
    constexpr float kReach = 12.0f;
    float bestSlope = 1e30f;
    glm::vec2 best = size * 0.5f;
    for (int j = 0; j <= kSteps; ++j)
        for (int i = 0; i <= kSteps; ++i) {
            const glm::vec2 p = size * (0.3f + 0.4f * glm::vec2(float(i), float(j)) / float(kSteps));
            const float h = terrain.heightAt(p.x, p.y);
            float slope = 0.0f;
            for (glm::vec2 d : {glm::vec2(kReach, 0), glm::vec2(-kReach, 0), glm::vec2(0, kReach), glm::vec2(0, -kReach)})
                slope = std::max(slope, std::abs(terrain.heightAt(p.x + d.x, p.y + d.y) - h));
            if (slope < bestSlope) bestSlope = slope, best = p;
        }
    return {best.x, terrain.heightAt(best.x, best.y), best.y};
}

} // namespace

Result<std::unique_ptr<CharacterCrowd>> CharacterCrowd::load(const Options& options, const terrain::Terrain& terrain,
                                                             const terrain::DrawnSurface& ground) {
    std::unique_ptr<CharacterCrowd> crowd(new CharacterCrowd());
    crowd->mTerrain = &terrain;
    crowd->mGround = &ground;
    crowd->mSite = findSite(terrain);
    crowd->mOrbit = {crowd->mSite, options.orbitDistance.value_or(kOrbitDistance), kOrbitHeight, kLookHeight};
    crowd->mOrbitFixed = options.orbitDistance.has_value();
    crowd->mOnlyModels = options.crowd == 0;

    const uint32_t froblins = std::min(options.crowd, CharacterAssets::kFroblinSeeds);
    if (Status ok = crowd->mAssets.addFroblins(options.contentDir, froblins); !ok) return ok.error();
    // CesiumMan is Khronos sample data the build copies from ../shared/testdata
    // when it is there; the scene goes on without it otherwise.
    uint32_t cesium = 0;
    if (options.crowd > 0) {
        if (auto file = locateContent(options.contentDir, "characters/CesiumMan/CesiumMan.gltf")) {
            if (Status ok = crowd->mAssets.add(file.value().string()); !ok) return ok.error();
            cesium = 1;
        } else {
            log::info("CesiumMan not in the content directory (the build copies it from ../shared/testdata); "
                      "the characters scene goes on without it");
        }
    }
    const uint32_t firstModel = uint32_t(crowd->mAssets.size());
    for (const std::string& model : options.models)
        if (Status ok = crowd->mAssets.add(model); !ok) return ok.error();
    crowd->populate(options, froblins, cesium, firstModel);
    // The same path as the crowd scene: every member an instance of an
    // instanced crowd (clips baked, culled and binned on the GPU), unless
    // the single-pass path is asked for (the instanced near tier is
    // two-pass) or more creatures are mixed than one crowd holds.
    if (options.characterPath == backend::CharacterPath::TwoPass &&
        crowd->mAssets.size() <= TS_CROWD_MAX_CHARACTERS && !crowd->mMembers.empty()) {
        auto instanced = InstancedCrowd::create(crowd->mAssets);
        if (!instanced) return instanced.error();
        crowd->mInstanced = std::move(instanced.value());
    }
    return crowd;
}

void CharacterCrowd::populate(const Options& options, uint32_t froblins, uint32_t cesium, uint32_t firstModel) {
    const glm::vec2 site(mSite.x, mSite.z);
    auto add = [this](uint32_t asset, int clip) -> Member& {
        Member& m = mMembers.emplace_back();
        m.asset = asset;
        m.clip = clip;
        return m;
    };
    // Every third creature idles on the inner ring; the others walk circles
    // of growing radius, alternately clockwise, out of step with each other.
    for (uint32_t i = 0; froblins && i < options.crowd; ++i) {
        const auto& asset = mAssets[i % froblins].asset;
        const bool idle = i % 3 == 2;
        Member& m = add(i % froblins, findClip(asset, idle ? "idle" : "walk"));
        m.clipOffset = 0.37f * float(i);
        m.anchor = site;
        m.angle = 2.39996f * float(i);  // golden angle: spread around the site
        if (idle) {
            m.radius = 0.0f;
            m.anchor = site + 1.2f * glm::vec2(std::cos(m.angle), std::sin(m.angle));
        } else {
            m.radius = 1.6f + 0.55f * float(i);
            m.speed = (i % 2 ? -1.0f : 1.0f) * 0.75f;
        }
    }
    if (cesium) {
        Member& m = add(froblins, findClip(mAssets[froblins].asset, "walk"));
        m.anchor = site;
        m.radius = 2.6f;
        m.speed = 1.1f;
        m.angle = 1.0f;
    }
    // --model files stand in a row, playing their first clip: beside the
    // crowd, or centred on the site when they are alone. Models come in any
    // units (a file authored in centimetres is a hundred times too large in
    // metres): the row is spaced by the largest one's size.
    const uint32_t models = uint32_t(mAssets.size()) - firstModel;
    const bool alone = mMembers.empty();
    float largest = 0.0f;
    for (uint32_t a = firstModel; a < mAssets.size(); ++a)
        largest = std::max(largest, glm::length(glm::vec2(mAssets[a].box.extents().x, mAssets[a].box.extents().z)));
    const float spacing = std::max(1.5f, 2.2f * largest);
    for (uint32_t k = 0; k < models; ++k) {
        const uint32_t a = firstModel + k;
        Member& m = add(a, mAssets[a].asset.clips.empty() ? -1 : 0);
        m.anchor = site + (alone ? glm::vec2(spacing * (float(k) - 0.5f * float(models - 1)), 0.0f)
                                 : glm::vec2(-spacing * float(k + 1), 0.8f));
        m.angle = CameraOrbit::kStart;  // facing where the camera starts
    }
    if (models > 0 && !options.orbitDistance) frameModels(firstModel);
}

void CharacterCrowd::frameModels(uint32_t firstModel) {
    // The sphere around every member from the first model on, and the
    // crowd's usual view: the camera backs off until it all fits, and
    // comes closer for a small model alone.
    scene::Aabb bounds = scene::Aabb::fromMinMax(mSite - glm::vec3(0.5f), mSite + glm::vec3(0.5f, 1.5f, 0.5f));
    const bool alone = mMembers.front().asset >= firstModel;
    if (alone) bounds = {};
    for (const Member& m : mMembers) {
        if (m.asset < firstModel) continue;
        const scene::Aabb& box = mAssets[m.asset].box;
        const glm::vec3 at(m.anchor.x, mSite.y, m.anchor.y);
        const float reach = glm::length(glm::vec2(box.extents().x, box.extents().z)) + glm::length(glm::vec2(box.center().x, box.center().z));
        bounds.expand(scene::Aabb::fromMinMax(at + glm::vec3(-reach, box.min.y, -reach), at + glm::vec3(reach, box.max.y, reach)));
    }
    frameBounds(bounds, alone);
}

void CharacterCrowd::frameAlso(const scene::Aabb& box) {
    if (mOrbitFixed) return;
    scene::Aabb bounds = mFramed;
    const bool alone = mOnlyModels && mMembers.empty();
    if (!alone && bounds.isEmpty())
        bounds = scene::Aabb::fromMinMax(mSite - glm::vec3(0.5f), mSite + glm::vec3(0.5f, 1.5f, 0.5f));
    bounds.expand(box);
    frameBounds(bounds, mOnlyModels);
}

void CharacterCrowd::frameBounds(const scene::Aabb& bounds, bool alone) {
    mFramed = bounds;
    const float radius = glm::length(bounds.extents());
    const float fit = 1.2f * radius / std::sin(0.5f * scene::Camera::kDefaultVerticalFov);
    const float distance = alone ? std::max(fit, 1.0f) : std::max(fit, kOrbitDistance);
    const glm::vec3 centre = bounds.center();
    mOrbit.site = {centre.x, mSite.y, centre.z};
    mOrbit.distance = distance;
    mOrbit.lookHeight = centre.y - mSite.y;
    mOrbit.height = mOrbit.lookHeight + 0.25f * distance;
}

void CharacterCrowd::update(double seconds, const scene::Camera& camera, const CharacterLevels& levels) {
    TESSERA_CPU_SCOPE("characters.animate");
    mPoser.begin(camera, levels);
    if (mInstancedActive) {
        mPoser.finish(mAssets);
        return updateInstances(seconds, camera, levels);
    }
    for (uint32_t id = 0; id < mMembers.size(); ++id) {
        const Member& m = mMembers[id];
        const Placement place = placementAt(m, seconds);
        glm::mat4 world = glm::translate(glm::mat4(1.0f), place.feet);
        world = glm::rotate(world, place.heading, glm::vec3(0, 1, 0));
        mPoser.offer(id, m.asset, world, m.clip, float(seconds) + m.clipOffset);
    }
    mPoser.finish(mAssets);
}

CharacterCrowd::Placement CharacterCrowd::placementAt(const Member& m, double seconds) const {
    glm::vec2 at = m.anchor;
    float heading = m.angle;
    if (m.radius > 0.0f) {
        const float theta = m.angle + m.speed / m.radius * float(seconds);
        at += m.radius * glm::vec2(std::cos(theta), std::sin(theta));
        // Facing along the circle: +Z (glTF's forward) turned onto the tangent.
        const glm::vec2 tangent = (m.speed < 0.0f ? -1.0f : 1.0f) * glm::vec2(-std::sin(theta), std::cos(theta));
        heading = std::atan2(tangent.x, tangent.y);
    }
    // On the ground as drawn this frame, not the height field under it.
    return {glm::vec3(at.x, mGround->heightAt(at.x, at.y), at.y), heading};
}

void CharacterCrowd::updateInstances(double seconds, const scene::Camera& camera, const CharacterLevels& levels) {
    mInstanced->begin(mMembers.size());
    for (uint32_t id = 0; id < mMembers.size(); ++id) {
        const Member& m = mMembers[id];
        const Placement place = placementAt(m, seconds);
        const scene::Aabb& box = mAssets[m.asset].box;
        const glm::vec3 centre = box.center();
        const uint32_t clip = mInstanced->bakedClip(m.asset, m.clip);
        shader::CrowdInstance instance;
        // A sphere holding the animated box at any heading (as the crowd's).
        instance.sphere = glm::vec4(place.feet + glm::vec3(0.0f, centre.y, 0.0f),
                                    glm::length(box.extents()) + glm::length(glm::vec2(centre.x, centre.z)));
        instance.placement = glm::vec4(place.feet, place.heading);
        instance.animation = glm::vec4(mInstanced->phase(clip, float(seconds) + m.clipOffset), 1.0f, 0.0f, 0.0f);
        instance.ids = glm::uvec4(id, m.asset, clip, 0xffffffffu);
        mInstanced->set(id, instance);
    }
    lod::LodPolicy policy = levels.lod;
    policy.fixedLevel = levels.fixedLevel.value_or(0.0f);
    mInstanced->setHorizon(*mTerrain);
    mInstanced->select(lod::LodView::fromCamera(camera, levels.viewportHeight, levels.maxLevel), policy);
}

} // namespace tessera::runtime
