#include "tessera/runtime/SceneRun.h"

#include "characters/LodSettings.h"
#include "world/ShadowCasters.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"

#include <algorithm>
#include <cstdio>

namespace tessera::runtime {

namespace {
/// Tessellated triangles per frame for all --model .obj surfaces: a
/// software rasterizer stays interactive (well under a second a frame at
/// 1280x720 on two cores); a GPU takes millions.
constexpr uint64_t kSubdivBudgetCpu = 150000;
constexpr uint64_t kSubdivBudgetGpu = 4000000;
} // namespace

Result<std::unique_ptr<SceneRun>> SceneRun::create(const Options& options, uint32_t frames) {
    std::unique_ptr<SceneRun> run(new SceneRun());
    run->mOptions = options;
    run->mFrames = frames;
    auto loaded = World::load(options, frames);
    if (!loaded) return loaded.error();
    run->mWorld = std::move(loaded.value());
    auto created = RenderSession::create(options, run->mWorld->terrain());
    if (!created) return created.error();
    run->mSession = std::move(created.value());
    if (Status ok = run->attachScene(options); !ok) return ok.error();
    return run;
}

Status SceneRun::attachScene(const Options& options) {
    RenderSession& session = *mSession;
    auto settings = session.resolveTessellation(options);
    if (!settings) return settings.error();
    mSettings = settings.value();
    log::info(std::string("terrain mode ") + terrain::toString(mSettings.mode) +
              (mSettings.mode == terrain::TerrainMode::Adaptive
                   ? std::string(", metric ") + terrain::toString(mSettings.metric)
                   : std::string()));
    session.setTerrainVisible(options.terrain);
    auto policy = lodPolicyFor(options, session.deviceClass());
    if (!policy) return policy.error();
    mLodPolicy = policy.value();

    CharacterPopulation* characters = mWorld->characters();
    if (characters) {
        if (options.characterLevel && *options.characterLevel > session.maxCharacterLevel())
            return failSetting(setting::kCharacterLevel, " ", formatNumber(*options.characterLevel), ": backend ",
                        session.capabilities().name, " tessellates up to level ",
                        formatNumber(session.maxCharacterLevel()));
        if (Status ok = session.createCharacters(characters->assets()); !ok) return ok.error();
        // The crowd scene draws as one instanced crowd where the backend
        // culls and bins crowds on the GPU, through the character path
        // elsewhere.
        InstancedCrowd* instanced = characters->instancedCrowd();
        if (instanced && session.capabilities().crowd) {
            const uint32_t capacity = std::max(characters->instanceCapacity(), 1u);
            if (Status ok = session.createCrowd(instanced->desc(characters->assets(), capacity, mLodPolicy)); !ok)
                return ok.error();
            characters->useInstancedCrowd(true);
            mInstanced = instanced;
        }
    }
    if (SubdivModels* surfaces = mWorld->surfaces()) {
        if (options.subdiv.level && *options.subdiv.level > session.capabilities().maxTessFactor)
            return failSetting(setting::kSubdivLevel, " ", formatNumber(*options.subdiv.level), ": backend ",
                        session.capabilities().name, " tessellates up to level ",
                        formatNumber(session.capabilities().maxTessFactor));
        if (Status ok = session.createSubdivs(*surfaces); !ok) return ok.error();
    }
    if (SubdivCharacters* subdivCharacters = mWorld->subdivCharacters()) {
        if (!session.capabilities().subdiv)
            return failSetting(setting::kCharacterSurface, " ", options.characterSurface, ": backend ",
                               session.capabilities().name,
                               " does not draw Catmull-Clark surfaces (BackendCapabilities::subdiv); use ",
                               reporterFor(options).name(setting::kBackend), " hulldomain, or ",
                               reporterFor(options).name(setting::kCharacterSurface), " planar");
        if (Status ok = session.createSubdivs(*subdivCharacters); !ok) return ok.error();
    }
    if (const SimulatedCrowd* simulated = mWorld->simulatedCrowd())
        std::printf("%s\n",
                    simulated
                        ->drawingMode(session.capabilities().name, session.capabilities().requiresGpu,
                                      reporterFor(options))
                        .c_str());
    return {};
}

Status SceneRun::switchBackend(const std::string& name) {
    const uint64_t before = mSession->generation();
    Status switched = mSession->switchBackend(mOptions, name);
    // Refused before anything was released: the scene draws on as it was.
    if (mSession->generation() == before) return switched;
    // A backend was initialised anew (the new one, or the old one restored):
    // the characters go back to the per-character path until the crowd
    // exists on it again, keeping the simulation's state.
    mInstanced = nullptr;
    if (CharacterPopulation* characters = mWorld->characters()) characters->useInstancedCrowd(false);
    mOptions.backend = mSession->capabilities().name;
    // Levels the user gave for the first backend are clamped to the new one's
    // maximum instead of failing the switch.
    Options relaxed = mOptions;
    const float top = mSession->capabilities().maxTessFactor;
    TessellationOptions& levels = relaxed.tessellation;
    if (levels.maxLevel) levels.maxLevel = std::min(*levels.maxLevel, top);
    if (levels.continuousLevel) levels.continuousLevel = std::min(*levels.continuousLevel, top);
    if (relaxed.characterLevel)
        relaxed.characterLevel = std::min(*relaxed.characterLevel, mSession->maxCharacterLevel());
    if (relaxed.subdiv.level) relaxed.subdiv.level = std::min(*relaxed.subdiv.level, top);
    if (relaxed.terrainMode && !mSession->capabilities().drawsTerrainMode(*relaxed.terrainMode)) relaxed.terrainMode.reset();
    Status attached = attachScene(relaxed);
    return switched ? attached : switched;
}

Status SceneRun::reloadWorld(const Options& options) {
    auto loaded = World::load(options, mFrames);
    if (!loaded) return loaded.error();
    // The old world's characters still hold the backend's handles: it goes
    // only after the session has released them.
    std::unique_ptr<World> old = std::move(mWorld);
    mWorld = std::move(loaded.value());
    const std::string backend = mSession->capabilities().name;
    Options next = options;
    next.backend = backend;
    const uint64_t before = mSession->generation();
    Status switched = mSession->switchBackend(next, backend, &mWorld->terrain());
    if (mSession->generation() == before) {
        // Refused before anything was released: keep drawing the old world.
        mWorld = std::move(old);
        return switched;
    }
    mInstanced = nullptr;
    mOptions = next;
    old.reset();
    Status attached = attachScene(next);
    return switched ? attached : switched;
}

bool SceneRun::step(uint32_t frame, bool readback) {
    if (!mSession->pollWindow()) return false;
    auto& profiler = profiler::Profiler::global();
    profiler.beginFrame(frame);
    renderFrame(frame, readback);
    profiler.endFrame();
    return true;
}

void SceneRun::renderFrame(uint32_t frame, bool readback) {
    RenderSession& session = *mSession;
    {
        TESSERA_CPU_SCOPE("scene.update");
        mWorld->update(frame);
        mCamera.setPose(mWorld->cameraPose(frame));
        mCamera.setAspect(float(session.width()) / float(session.height()));
    }
    {
        // The characters stand on the ground the backend draws this frame.
        TESSERA_CPU_SCOPE("terrain.ground");
        terrain::DrawnSurface& ground = mWorld->ground();
        session.updateGround(ground, mCamera, mSettings);
        // The camera keeps its height over the ground as drawn too: a path
        // laid over the height field would sink with it where coarse levels
        // draw the ground metres above (docs/CROWD.md 6.8), closer to the
        // ground and the creatures on it than on a backend drawing finer.
        // The lifted view draws other levels, so the ground is drawn again.
        const glm::vec3 eye = mCamera.position();
        const float rise = ground.heightAt(eye.x, eye.z) - mWorld->terrain().heightAt(eye.x, eye.z);
        if (rise > 0.0f) {
            mCamera.setPosition(eye + glm::vec3(0.0f, rise, 0.0f));
            session.updateGround(ground, mCamera, mSettings);
        }
    }
    backend::CharacterDrawInfo draw;
    backend::CrowdDrawInfo crowdDraw;
    CharacterPopulation* characters = mWorld->characters();
    if (characters) {
        characters->update(frame * World::kSecondsPerFrame, mCamera,
                           {session.height(), session.maxCharacterLevel(), mOptions.characterLevel, mLodPolicy});
        draw = {characters->items(), mOptions.characterPath, mOptions.displacement, mOptions.lodColors};
        if (mInstanced) {
            crowdDraw = mInstanced->drawInfo(mOptions.displacement, mOptions.lodColors);
            // The agents the terrain hid this frame, by the tier their size
            // would have taken (the CPU reference's; every backend culls the
            // same). The impostors' only where the manager tested them all
            // (--crowd-tiers): otherwise the backends alone cull them.
            static const char* const kHidden[lod::kTierCount] = {"crowd near hidden", "crowd middle hidden",
                                                                 "crowd far hidden", "crowd impostor hidden"};
            auto& profiler = profiler::Profiler::global();
            const lod::LodFrame& lod = mInstanced->lod();
            for (uint32_t t = 0; t < lod::kTierCount; ++t)
                if (t != TS_LOD_IMPOSTOR || lod.untested == 0)
                    profiler.recordCounter({kHidden[t], uint64_t(frame), profiler.nowNs(), double(lod.hidden[t])});
        }
    }
    std::span<const SubdivDraw> surfaceDraws;
    const uint64_t budget = mOptions.subdiv.budget.value_or(
        session.deviceClass() == lod::DeviceClass::Cpu ? kSubdivBudgetCpu : kSubdivBudgetGpu);
    if (SubdivModels* surfaces = mWorld->surfaces()) {
        surfaces->update(frame * World::kSecondsPerFrame, mCamera, session.height(),
                         session.capabilities().maxTessFactor, budget);
        surfaceDraws = surfaces->draws();
    }
    if (SubdivCharacters* subdivCharacters = mWorld->subdivCharacters()) {
        subdivCharacters->update(frame * World::kSecondsPerFrame, mCamera, session.height(),
                                 session.capabilities().maxTessFactor, budget);
        mSubdivDraws.assign(surfaceDraws.begin(), surfaceDraws.end());
        mSubdivDraws.insert(mSubdivDraws.end(), subdivCharacters->draws().begin(), subdivCharacters->draws().end());
        surfaceDraws = mSubdivDraws;
    }
    // The characters' shadows on the terrain: whoever stands in the square
    // of ground ahead of the camera.
    mShadowCasters.clear();
    glm::vec3 region(0.0f);
    if (characters) {
        region = shadowRegionFor(mCamera);
        characters->shadowCasters(region, kMaxShadowCasters, mShadowCasters);
    }
    session.setShadowCasters(mShadowCasters, mShadowCasters.empty() ? glm::vec3(0.0f) : region);
    session.renderFrame(frame, mCamera, mSettings, mOptions.clearColor, mOptions.wireframe, readback,
                        characters ? &draw : nullptr, mInstanced ? &crowdDraw : nullptr, surfaceDraws);
}

} // namespace tessera::runtime
