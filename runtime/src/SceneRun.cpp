#include "tessera/runtime/SceneRun.h"

#include "LodSettings.h"
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
    auto loaded = World::load(options, frames);
    if (!loaded) return loaded.error();
    run->mWorld = std::move(loaded.value());
    auto created = RenderSession::create(options, run->mWorld->terrain());
    if (!created) return created.error();
    run->mSession = std::move(created.value());
    RenderSession& session = *run->mSession;
    auto settings = session.resolveTessellation(options);
    if (!settings) return settings.error();
    run->mSettings = settings.value();
    log::info(std::string("terrain mode ") + terrain::toString(run->mSettings.mode) +
              (run->mSettings.mode == terrain::TerrainMode::Adaptive
                   ? std::string(", metric ") + terrain::toString(run->mSettings.metric)
                   : std::string()));
    session.setTerrainVisible(options.terrain);
    auto policy = lodPolicyFor(options, session.deviceClass());
    if (!policy) return policy.error();
    run->mLodPolicy = policy.value();

    CharacterPopulation* characters = run->mWorld->characters();
    if (characters) {
        if (options.characterLevel && *options.characterLevel > session.maxCharacterLevel())
            return fail("--character-level ", formatNumber(*options.characterLevel), ": backend ",
                        session.capabilities().name, " tessellates up to level ",
                        formatNumber(session.maxCharacterLevel()));
        if (Status ok = session.createCharacters(characters->assets()); !ok) return ok.error();
        // The crowd scene draws as one instanced crowd where the backend
        // culls and bins crowds on the GPU, through the character path
        // elsewhere.
        InstancedCrowd* instanced = characters->instancedCrowd();
        if (instanced && session.capabilities().crowd) {
            const uint32_t capacity = std::max(characters->instanceCapacity(), 1u);
            if (Status ok = session.createCrowd(instanced->desc(characters->assets(), capacity, run->mLodPolicy)); !ok)
                return ok.error();
            characters->useInstancedCrowd();
            run->mInstanced = instanced;
        }
    }
    if (SubdivModels* surfaces = run->mWorld->surfaces()) {
        if (options.subdiv.level && *options.subdiv.level > session.capabilities().maxTessFactor)
            return fail("--subdiv-level ", formatNumber(*options.subdiv.level), ": backend ",
                        session.capabilities().name, " tessellates up to level ",
                        formatNumber(session.capabilities().maxTessFactor));
        if (Status ok = session.createSubdivs(*surfaces); !ok) return ok.error();
    }
    if (SubdivCharacters* subdivCharacters = run->mWorld->subdivCharacters()) {
        if (!session.capabilities().subdiv)
            return fail("--character-surface ", options.characterSurface, ": backend ", session.capabilities().name,
                        " does not draw Catmull-Clark surfaces (BackendCapabilities::subdiv); use --backend "
                        "hulldomain, or --character-surface planar");
        if (Status ok = session.createSubdivs(*subdivCharacters); !ok) return ok.error();
    }
    if (const SimulatedCrowd* simulated = run->mWorld->simulatedCrowd())
        std::printf("%s\n",
                    simulated->drawingMode(session.capabilities().name, session.capabilities().requiresGpu).c_str());
    return run;
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
    backend::CharacterDrawInfo draw;
    backend::CrowdDrawInfo crowdDraw;
    CharacterPopulation* characters = mWorld->characters();
    if (characters) {
        characters->update(frame * World::kSecondsPerFrame, mCamera,
                           {session.height(), session.maxCharacterLevel(), mOptions.characterLevel, mLodPolicy});
        draw = {characters->items(), mOptions.characterPath, mOptions.displacement, mOptions.lodColors};
        if (mInstanced) crowdDraw = mInstanced->drawInfo(mOptions.displacement, mOptions.lodColors);
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
    session.renderFrame(frame, mCamera, mSettings, mOptions.clearColor, mOptions.wireframe, readback,
                        characters ? &draw : nullptr, mInstanced ? &crowdDraw : nullptr, surfaceDraws);
}

} // namespace tessera::runtime
