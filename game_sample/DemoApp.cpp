#include "DemoApp.h"

#include "BackendSelection.h"
#include "CharacterBenchmark.h"
#include "CrowdBenchmark.h"
#include "DemoOutputs.h"
#include "DemoScene.h"
#include "InstancedCrowd.h"
#include "LodSettings.h"
#include "RenderSession.h"
#include "TerrainBenchmark.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/Instance.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"

#include <algorithm>
#include <cstdio>

namespace tessera::demo {
namespace {

constexpr uint32_t kDefaultHeadlessFrames = 60;

Status runFlythrough(const DemoOptions& options) {
    auto& profiler = profiler::Profiler::global();
    profiler.setEnabled(!options.capture.empty() || !options.benchmark.empty());

    // --warmup frames run first and are discarded from the benchmark; --frames
    // counts the frames after them.
    const uint32_t measured =
        options.frames ? options.frames : (options.window ? UINT32_MAX - options.warmup : kDefaultHeadlessFrames);
    const uint32_t frames = options.warmup + measured;
    auto loaded = DemoScene::load(options, frames);
    if (!loaded) return loaded.error();
    DemoScene& scene = *loaded.value();
    auto created = RenderSession::create(options, scene.terrain());
    if (!created) return created.error();
    RenderSession& session = *created.value();
    auto settings = session.resolveTessellation(options);
    if (!settings) return settings.error();
    log::info(std::string("terrain mode ") + terrain::toString(settings.value().mode) +
              (settings.value().mode == terrain::TerrainMode::Adaptive
                   ? std::string(", metric ") + terrain::toString(settings.value().metric)
                   : std::string()));

    session.setTerrainVisible(options.terrain);
    auto lodPolicyFound = lodPolicyFor(options, session.deviceClass());
    if (!lodPolicyFound) return lodPolicyFound.error();
    const lod::LodPolicy lodPolicy = lodPolicyFound.value();
    CharacterPopulation* characters = scene.characters();
    if (characters) {
        if (options.characterLevel && *options.characterLevel > session.maxCharacterLevel())
            return fail("--character-level ", formatNumber(*options.characterLevel), ": backend ",
                        session.capabilities().name, " tessellates up to level ",
                        formatNumber(session.maxCharacterLevel()));
        if (Status ok = session.createCharacters(characters->assets()); !ok) return ok.error();
    }
    // The crowd scene draws as one instanced crowd where the backend culls
    // and bins crowds on the GPU, through the character path elsewhere.
    InstancedCrowd* instanced = characters ? characters->instancedCrowd() : nullptr;
    if (instanced && !session.capabilities().crowd) instanced = nullptr;
    if (instanced) {
        const SimulatedCrowd* simulated = scene.simulatedCrowd();
        const uint32_t agents = simulated ? simulated->crowd().stats().agents : 0;
        if (Status ok = session.createCrowd(instanced->desc(characters->assets(), std::max(agents, 1u), lodPolicy)); !ok)
            return ok.error();
        characters->useInstancedCrowd();
    }
    if (const SimulatedCrowd* simulated = scene.simulatedCrowd())
        std::printf("%s\n",
                    simulated->drawingMode(session.capabilities().name, session.capabilities().requiresGpu).c_str());

    scene::Camera camera;
    uint32_t rendered = 0;
    for (uint32_t frame = 0; frame < frames; ++frame, ++rendered) {
        if (!session.pollWindow()) break;
        profiler.beginFrame(frame);
        {
            TESSERA_CPU_SCOPE("scene.update");
            scene.update(frame);
            camera.setPose(scene.cameraPose(frame));
            camera.setAspect(float(session.width()) / float(session.height()));
        }
        backend::CharacterDrawInfo draw;
        backend::CrowdDrawInfo crowdDraw;
        if (characters) {
            characters->update(frame * DemoScene::kSecondsPerFrame, camera,
                               {session.height(), session.maxCharacterLevel(), options.characterLevel, lodPolicy});
            draw = {characters->items(), options.characterPath, options.displacement, options.lodColors};
            if (instanced) crowdDraw = instanced->drawInfo(options.displacement, options.lodColors);
        }
        const bool last = frame + 1 == frames;
        session.renderFrame(frame, camera, settings.value(), options.clearColor, options.wireframe,
                            last && !options.screenshot.empty(), characters ? &draw : nullptr,
                            instanced ? &crowdDraw : nullptr);
        profiler.endFrame();
    }
    const std::vector<uint8_t> pixels = session.finish();
    if (!options.crowdTiers.empty()) {
        if (!instanced) return fail("--crowd-tiers: backend ", session.capabilities().name,
                                    " draws no instanced crowd here (it needs --scene crowd)");
        auto tiers = session.readCrowdTiers();
        if (!tiers) return tiers.error();
        if (Status ok = instanced->writeTiers(options.crowdTiers, session.capabilities().name, tiers.value()); !ok)
            return ok.error();
        log::info("wrote " + options.crowdTiers);
    }
    if (options.meteors) log::info(std::to_string(scene.impactsLanded()) + " meteor impacts landed");
    if (const SimulatedCrowd* crowd = scene.simulatedCrowd()) std::printf("%s\n", crowd->summary().c_str());
    return writeOutputs(options, session, scene.terrain(), pixels, rendered);
}

} // namespace

int runDemo(const DemoOptions& options) {
    if (options.listDevices || options.listBackends) {
        Status listed = options.listDevices ? listDevices(options) : listBackends(options);
        if (!listed) {
            log::error(listed.error().message);
            return 1;
        }
        return 0;
    }
    int code = 0;
    {
        Status ran = options.bench.empty()           ? runFlythrough(options)
                     : options.bench == "characters" ? runCharacterBenchmark(options)
                     : options.bench == "crowd-sim"  ? runCrowdBenchmark(options)
                                                     : runTerrainBenchmark(options);
        if (!ran) {
            log::error(ran.error().message);
            code = 1;
        }
    }
    if (options.validation) {
        // Printed after every Vulkan object is gone, so messages from
        // destruction are counted too.
        const uint64_t messages = gpu::Instance::validationMessageCount();
        // On stderr, so stdout stays clean JSON for `--bench terrain` without --out.
        std::fprintf(stderr, "validation messages: %llu\n", static_cast<unsigned long long>(messages));
        if (messages > 0 && code == 0) code = 1;
    }
    return code;
}

} // namespace tessera::demo
