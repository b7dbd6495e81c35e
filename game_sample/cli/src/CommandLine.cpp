#include "tessera/demo/CommandLine.h"

#include "tessera/demo/DemoFlags.h"
#include "tessera/demo/FlagValues.h"

#include "tessera/cli/CameraPoseText.h"
#include "tessera/cli/FeatureMaskText.h"
#include "tessera/cli/Validators.h"
#include "tessera/lod/LodPolicy.h"

namespace tessera::demo {

using namespace tessera::runtime;

namespace {

constexpr const char* kDescription =
    "Renders the crowd on tessellated terrain (or the flythrough, the characters, the subdivision surfaces, a "
    "benchmark). Headless (offscreen) by default, on the best Vulkan device (a GPU, else lavapipe).";

/// The flags whose values are lists (tessera/cli/NumberList.h's rules), or
/// files, into Options.
Status interpretLists(const CLI::App& app, const DemoFlagText& t, Options& o) {
    auto given = [&](const char* flag) { return app.count(flag) > 0; };
    for (const auto& model : t.models) (isObjFile(model) ? o.surfaces : o.models).push_back(model);
    for (const auto& text : t.splats) {
        auto splat = parseSplat(text);
        if (!splat) return splat.error();
        o.splats.push_back(splat.value());
    }
    if (given("--agents")) {
        auto counts = parseAgents(t.agents);
        if (!counts) return counts.error();
        o.agents = counts.value();
    }
    if (given("--clear-color")) {
        auto color = parseColor(t.clearColor);
        if (!color) return color.error();
        o.clearColor = color.value();
    }
    if (given("--sun")) {
        auto sun = parseSun(t.sun);
        if (!sun) return sun.error();
        o.sunDirection = sun.value();
    }
    if (given("--camera")) {
        auto pose = cli::parseCameraPose(t.camera);
        if (!pose) return pose.error();
        o.camera = pose.value();
    }
    if (given("--subdiv-level")) {
        auto sweep = parseSweep("--subdiv-level", t.subdivLevel, 1.0f, 64.0f);
        if (!sweep) return sweep.error();
        o.subdiv.level = sweep.value().first;
        o.subdiv.levelEnd = sweep.value().second;
    }
    if (given("--orbit-distance")) {
        auto sweep = parseSweep("--orbit-distance", t.orbitDistance, 0.25f, 10000.0f);
        if (!sweep) return sweep.error();
        o.orbitDistance = sweep.value().first;
        o.orbitDistanceEnd = sweep.value().second;
    }
    return {};
}

/// Turns the flags read as text into Options, each with its own message.
Status interpret(const cli::CommandLine& line, const DemoFlagText& t, Options& o) {
    const CLI::App& app = line.app();
    auto given = [&](const char* flag) { return app.count(flag) > 0; };
    if (Status lists = interpretLists(app, t, o); !lists) return lists;
    if (given("--character-path"))
        o.characterPath = t.characterPath == "single-pass" ? backend::CharacterPath::SinglePass
                                                           : backend::CharacterPath::TwoPass;
    if (given("--normals")) o.subdiv.normals = t.normals == "accurate" ? 1u : 0u;
    if (given("--subdiv-view")) {
        const char* const views[] = {"shaded", "patches", "levels", "mips"};
        for (uint32_t v = 0; v < 4; ++v)
            if (t.subdivView == views[v]) o.subdiv.view = v;
    }
    if (given("--look")) {
        o.look = t.look == "plain" ? backend::Look::Plain : backend::Look::Full;
        o.benchBothLooks = t.look == "both";
    }
    if (given("--terrain-shading"))
        o.terrainShading = t.terrainShading == "forward"    ? backend::TerrainShading::Forward
                           : t.terrainShading == "deferred" ? backend::TerrainShading::Deferred
                                                            : backend::TerrainShading::Auto;
    if (given("--shadows"))
        o.shadows = t.shadows == "blob"       ? backend::Shadows::Blob
                    : t.shadows == "cascaded" ? backend::Shadows::Cascaded
                    : t.shadows == "none"     ? backend::Shadows::None
                                              : backend::Shadows::Auto;
    if (given("--sculpt")) o.subdiv.sculpt = t.sculpt == "raise" ? 1 : -1;
    if (given("--terrain-mode")) o.terrainMode = terrain::parseTerrainMode(t.terrainMode);
    if (given("--tess-metric")) o.tessellation.metric = *terrain::parseTessMetric(t.tessMetric);
    if (given("--character-level")) o.characterLevel = t.characterLevel;
    if (given("--subdiv-pixels")) o.subdiv.pixels = t.subdivPixels;
    if (given("--subdiv-budget")) o.subdiv.budget = t.subdivBudget;
    if (given("--lod-near")) o.lodNear = t.lodNear;
    if (given("--lod-far")) o.lodFar = t.lodFar;
    if (given("--lod-impostor")) o.lodImpostor = t.lodImpostor;
    if (given("--lod-budget")) {
        if (t.lodBudget == 0)
            return fail("--lod-budget 0: a budget of zero tessellated triangles draws nothing tessellated; give at "
                        "least one cage's worth (e.g. 10000)");
        o.lodBudget = t.lodBudget;
    }
    if (given("--lod-near-max")) o.lodNearMax = t.lodNearMax;
    if (given("--lod-middle-max")) o.lodMiddleMax = t.lodMiddleMax;
    if (given("--lod-far-max")) o.lodFarMax = t.lodFarMax;
    if (given("--lod-fade")) o.lodFade = t.lodFade;
    if (given("--lod-edge")) o.lodEdge = t.lodEdge;
    if (given("--lod-far-triangles")) o.lodFarTriangles = t.lodFarTriangles;
    if (given("--lod-middle-triangles")) o.lodMiddleTriangles = t.lodMiddleTriangles;
    if (given("--lod-far-caster-triangles")) o.lodFarCasterTriangles = t.lodFarCasterTriangles;
    if (given("--renderdoc")) o.renderdocFrame = t.renderdocFrame;
    if (given("--device-memory-cap")) o.deviceMemoryCap = t.deviceMemoryCap << 20;
    if (given("--hide-features")) {
        auto mask = cli::parseFeatureMask(t.hideFeatures);
        if (!mask) return fail("--hide-features: ", mask.error().message);
        o.hiddenFeatures = mask.value();
    }
    return {};
}

} // namespace

std::string helpText() {
    cli::CommandLine line("tessera-demo", kDescription);
    Options options;
    DemoFlagText text;
    declareDemoFlags(line, options, text);
    return line.help();
}

Result<Options> parseCommandLine(const std::vector<std::string>& args) {
    cli::CommandLine line("tessera-demo", kDescription);
    Options o;
    DemoFlagText t;
    declareDemoFlags(line, o, t);
    auto parsed = line.parse(args);
    if (!parsed) return parsed.error();
    if (!parsed.value()) {
        o.help = true;
        return o;
    }
    if (Status ok = interpret(line, t, o); !ok) return ok.error();
    const bool crowdDrawGiven = line.app().count("--crowd-draw") > 0;
    const bool sceneGiven = line.app().count("--scene") > 0, meteorsGiven = line.app().count("--meteors") > 0;
    if (o.backend == "all" && o.bench.empty())
        return fail("--backend all compares the backends in --bench terrain, characters or crowd; pick one backend "
                    "for the demo");
    const float lodNear = o.lodNear.value_or(lod::LodPolicy{}.nearPixels);
    const float lodFar = o.lodFar.value_or(lod::LodPolicy{}.farPixels);
    if (lodFar > lodNear)
        return fail("--lod-far ", cli::formatNumber(lodFar), " is above --lod-near ", cli::formatNumber(lodNear),
                    ": the far threshold must be the smaller");
    if (o.lodImpostor && *o.lodImpostor > lodFar)
        return fail("--lod-impostor ", cli::formatNumber(*o.lodImpostor), " is above --lod-far ", cli::formatNumber(lodFar),
                    ": the impostor threshold must be the smaller");
    if ((!o.models.empty() || !o.surfaces.empty()) && !sceneGiven) o.scene = "characters";
    const bool crowdFlags = !o.agents.empty() || crowdDrawGiven;
    if (crowdFlags && !sceneGiven && o.bench.empty()) o.scene = "crowd";
    // With no scene asked for, the showcase: the crowd on the adaptive
    // terrain under a meteor shower, seen from a flight over it.
    if (!sceneGiven && o.models.empty() && o.surfaces.empty() && o.bench.empty()) o.scene = "crowd";
    if (o.scene == "crowd" && o.bench.empty() && !meteorsGiven) o.meteors = kCrowdSceneMeteors;
    const bool crowdBench = o.bench == "crowd" || o.bench == "crowd-sim";
    if (crowdFlags && o.scene != "crowd" && !crowdBench)
        return fail(!o.agents.empty() ? "--agents" : "--crowd-draw",
                    " is for --scene crowd, --bench crowd or --bench crowd-sim");
    if (o.agents.size() > 1 && !crowdBench)
        return fail("--agents takes one count in the crowd scene (a list is for --bench crowd and crowd-sim), got ",
                    std::to_string(o.agents.size()));
    if (!o.models.empty() && o.scene != "characters" && o.scene != "crowd")
        return fail("--model places models in the characters or crowd scene; drop --scene ", o.scene);
    if (!o.surfaces.empty() && o.scene != "characters")
        return fail("--model ", o.surfaces.front(), ": a .obj surface stands in the characters scene; drop --scene ",
                    o.scene);
    if (o.characterSurface != "planar" && (o.models.empty() || o.scene != "characters"))
        return fail("--character-surface ", o.characterSurface,
                    " draws the --model .glb files of the characters scene as Catmull-Clark surfaces; give "
                    "--model FILE.glb (with FILE.cctiles beside it)");
    if (o.bench == "terrain" && o.scene != "terrain")
        return fail("--bench terrain measures the terrain; drop --scene ", o.scene);
    if (o.benchBothLooks && o.bench != "terrain")
        return fail("--look both measures the two looks side by side in --bench terrain; give plain or full here");
    if (o.window && !o.record.empty()) return fail("--record writes headless frames; drop --window");
    if (o.window && !o.screenshot.empty() && o.frames == 0)
        return fail("--screenshot with --window needs --frames N to know which frame to capture");
    return o;
}

} // namespace tessera::demo
