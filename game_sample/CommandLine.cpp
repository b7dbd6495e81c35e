#include "CommandLine.h"

#include "tessera/shaders/CrowdLod.h"

#include "tessera/crowd/Crowd.h"
#include "tessera/lod/LodPolicy.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace tessera::demo {

using namespace tessera::runtime;

namespace {

/// A Catmull-Clark control mesh (.obj, any case), not a glTF model.
bool isObjFile(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".obj";
}

Result<uint32_t> parseCount(const std::string& flag, const std::string& text, uint32_t min, uint32_t max) {
    uint32_t value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max)
        return fail(flag, " expects a whole number from ", std::to_string(min), " to ", std::to_string(max), ", got \"",
                    text, "\"");
    return value;
}

// --agents: one count, or a comma list of counts for --bench crowd and crowd-sim.
Result<std::vector<uint32_t>> parseAgents(const std::string& text) {
    const Error bad = fail("--agents expects a whole number of agents from 1 to ",
                           std::to_string(crowd::Crowd::kMaxAgents), " (a comma list with --bench crowd or crowd-sim), got \"",
                           text, "\"");
    std::vector<uint32_t> counts;
    std::stringstream stream(text);
    std::string part;
    while (std::getline(stream, part, ',')) {
        uint64_t value = 0;
        auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (ec != std::errc() || end != part.data() + part.size() || value < 1 || value > crowd::Crowd::kMaxAgents)
            return bad;
        counts.push_back(uint32_t(value));
    }
    if (counts.empty() || text.back() == ',') return bad;
    return counts;
}

Result<glm::vec3> parseColor(const std::string& text) {
    glm::vec3 color{};
    std::stringstream stream(text);
    std::string part;
    int n = 0;
    while (std::getline(stream, part, ',')) {
        char* end = nullptr;
        const float v = std::strtof(part.c_str(), &end);
        if (n >= 3 || part.empty() || *end != '\0' || !std::isfinite(v) || v < 0.0f || v > 1.0f)
            return fail("--clear-color expects r,g,b with each in [0,1], got \"", text, "\"");
        color[n++] = v;
    }
    if (n != 3) return fail("--clear-color expects r,g,b with each in [0,1], got \"", text, "\"");
    return color;
}

Result<float> parseNumber(const std::string& flag, const std::string& text, float min, float max) {
    char* end = nullptr;
    const float v = std::strtof(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || v < min || v > max)
        return fail(flag, " expects a number from ", formatNumber(min), " to ", formatNumber(max), ", got \"", text, "\"");
    return v;
}

Result<terrain::CraterSplat> parseSplat(const std::string& text) {
    std::vector<float> values;
    std::stringstream stream(text);
    std::string part;
    bool numbers = true;
    while (std::getline(stream, part, ',')) {
        char* end = nullptr;
        const float v = std::strtof(part.c_str(), &end);
        numbers = numbers && !part.empty() && *end == '\0' && std::isfinite(v);
        values.push_back(v);
    }
    const bool shaped = numbers && (values.size() == 3 || values.size() == 4);
    if (!shaped || values[2] <= 0.0f || (values.size() == 4 && values[3] < 0.0f))
        return fail("--splat expects x,z,radius[,depth] in metres with radius > 0 and depth >= 0, got \"", text, "\"");
    terrain::CraterSplat splat;
    splat.center = {values[0], values[1]};
    splat.radius = values[2];
    splat.profile.depth = values.size() == 4 ? values[3] : 0.22f * values[2];
    splat.profile.rimHeight = 0.06f * values[2];
    return splat;
}

} // namespace

const char* helpText() {
    return R"(usage: tessera-demo [options]

Renders a scripted flythrough over tessellated terrain. Headless (offscreen)
by default, on the best Vulkan device (a GPU, else lavapipe).

Backend and device:
  --backend NAME        r2vb | streamout | hulldomain | null (default: the
                        most capable backend the device can run); with
                        --bench terrain, characters, crowd or subdiv also "all": every GPU
                        backend side by side
  --list-backends       list backends and their capabilities on the device
  --device NAME|INDEX   pick a Vulkan device by index or name substring
  --list-devices        list Vulkan devices
  --plugin-dir DIR      also search DIR for backend plugins (repeatable)
  --validation          enable the Khronos validation layer; print and count
                        every message, fail at exit if there were any

Scene:
  --scene NAME          crowd (the default: the crowd simulation, --agents
                        agents wandering between four goals under a meteor
                        shower, every one drawn as an instanced crowd culled
                        and sorted into LOD tiers on the GPU, seen from a
                        flight over it) | terrain (the flythrough over the
                        terrain alone) | characters (a few tessellated,
                        displaced, animated creatures and CesiumMan walking
                        on the terrain; the default when --model is given)
  --model FILE          place a .gltf or .glb file in the characters scene,
                        playing its first animation, or (--scene crowd) mix
                        it into the crowd with the generated creatures; a
                        crowd's models need a skin and a walk clip; or a
                        .obj control mesh (OpenSubdiv's tags read) drawn as
                        a Catmull-Clark surface with a procedural analytic
                        displacement, in the characters scene (repeatable)
  --crowd N             generated creatures in the characters scene, with
                        CesiumMan (default 6; 0: only the --model files,
                        centred where the crowd would stand)
  --orbit-distance M    radius of the camera's circle around the characters
                        (default 5 metres); in the crowd scene, circle the
                        crowd's spawn at M metres instead of flying over it;
                        A:B dollies from A to B metres over the run
  --agents N            agents in the crowd scene (default 2000; refused
                        when more than the machine's memory holds); with
                        --bench crowd or crowd-sim a comma list of crowd
                        sizes (default 1000,10000,65000)
  --crowd-draw K        on a backend without instanced crowds, how many
                        agents the crowd scene draws, the nearest in view,
                        one character draw each (default 48)
  --threads N           the crowd simulation's threads (default 0: every
                        hardware thread)
  --no-displacement     draw characters without their displacement maps
  --no-terrain          draw the characters alone on the clear colour
  --character-path P    two-pass (skin the cage once into 128-bit vertices,
                        then tessellate; default) | single-pass (skin every
                        tessellated vertex)
  --character-level L   characters' tessellation level, 1 to the backend's
                        maximum (default: from each character's size on
                        screen); every character in view is then
                        tessellated at L, with no LOD budget unless the
                        --lod-* flags give one
  --lod-near PX         LOD thresholds: characters at least PX pixels tall
  --lod-far PX          on screen are tessellated (default 192), below the
                        far one drawn with the simplest mesh (default 64),
                        the cage in between
  --lod-budget T        at most T tessellated triangles a frame (default:
                        24000000 on a GPU, 100000 on lavapipe)
  --lod-near-max N      at most N tessellated characters a frame (default:
                        256 on a GPU, 4 on lavapipe)
  --lod-middle-max N    at most N characters drawn as their untessellated
                        cage a frame (the rest take the far mesh)
  --lod-fade N          frames a tier change cross-fades over (dithered;
                        default 8, 0: switch at once, at most 63)
  --lod-edge PX         tessellate near characters to edges of about PX
                        pixels (default 2 on a GPU, 3 on lavapipe)
  --lod-far-triangles N the far tier's mesh simplified to at most N
                        triangles (default 120 on a GPU, 64 on lavapipe;
                        the content's far mesh has about 280)
  --lod-colors          tint characters by LOD tier: near green, middle
                        yellow, far red
  --crowd-tiers FILE    write the last frame's crowd agents per LOD tier,
                        as the backend binned them and as the CPU
                        reference did (JSON; the crowd scene)
  --heightmap FILE      8- or 16-bit grayscale PNG height map (default: the
                        generated content/terrain/height.png)
  --content DIR         content directory
  --seed N              camera path, meteor and crowd spawn seed (default 1)
  --camera x,y,z,yaw,pitch  fixed view (degrees) instead of the flythrough
  --wireframe           draw wireframe
  --meteors N           a meteor shower of N impacts during the flythrough
                        (the crowd scene: 4 unless given; 0 for none),
                        deterministic by --seed; craters deform the terrain
                        (in the crowd scene they land among the agents)
  --splat x,z,r[,depth] stamp a crater (metres) before the first frame
                        (repeatable; depth defaults to 0.22 r)

Terrain tessellation (the first paper's Table 2 modes):
  --terrain-mode M      lowres | continuous | adaptive (default: adaptive
                        where the backend draws it, else lowres)
  --tess-metric M       adaptive metric: screen (edge length in pixels),
                        distance, silhouette, detail (height-map error in
                        pixels); default screen
  --tess-target PX      pixels per edge (screen, silhouette) or of error
                        (detail); default 16, or 2 for detail
  --tess-distance M     distance metric: metres where the level reaches 1
                        (default 4000)
  --tess-level L        continuous mode's level, 1 to the backend's maximum
                        (default 15)
  --tess-max L          largest adaptive level (default: the backend's
                        maximum, 64 hardware, 14.99 emulated)

Subdivision surfaces (--model FILE.obj; the second paper, docs/SUBDIV.md):
  --normals N           accurate (with the Weingarten term) | approximate
                        (without; the default)
  --subdiv-pixels PX    screen-space level of detail: pixels per
                        tessellated segment (default 6)
  --subdiv-level L      one level everywhere instead (1 to the backend's
                        maximum), for measurements; A:B sweeps it from A
                        to B over the run's frames
  --subdiv-budget T     tessellated triangles per frame, all surfaces
                        (default: 150000 on lavapipe, 4000000 on a GPU);
                        levels scale down to fit
  --no-mips             sample the finest displacement mip everywhere
                        instead of the level of detail's (section 6)
  --subdiv-view V       shaded | patches (regular patches green to blue by
                        depth, end caps red) | levels | mips
  --subdiv-amplitude A  procedural displacement, fraction of the shape's
                        diagonal (default 0.02; 0: the base surface)
  --sculpt raise|lower  a scripted brush stroke around each surface, one
                        dab a frame: the touched tiles, their mips and
                        overlaps are rederived and re-uploaded
  --subdiv-still        keep the control cages in their rest pose (they
                        sway by default)
  --character-surface S planar (default) | catmull-clark | both: draw each
                        --model .glb as the first paper's planar cage, as
                        a Catmull-Clark surface with the tile displacement
                        baked beside it (FILE.cctiles, made by
                        tessera-creaturegen for the generated Froblins), or
                        both side by side; the Catmull-Clark ones need a
                        backend that draws subdivision surfaces (hulldomain)

Output:
  --width N --height N  render size (default 1280x720)
  --clear-color r,g,b   background colour, components in [0,1]
  --frames N            frames to render after the warm-up (default 60
                        headless; until closed with --window)
  --window              open a window (GLFW) instead of rendering headless
  --screenshot FILE     write the last frame as PNG
  --record DIR          write every frame as DIR/frame_NNNN.png (headless;
                        waits for each frame)
  --capture FILE        write a Chrome trace (Perfetto, chrome://tracing)
  --benchmark FILE      write per-pass min/median/max GPU ms as JSON
  --warmup N            frames run first and left out of --benchmark (default 0;
                        with --bench crowd-sim: unmeasured steps, default 60)
  --dump-heights PREFIX after the last frame write the GPU and CPU copies of
                        the height map as PREFIX.gpu.png and PREFIX.cpu.png
  --bench terrain       run the Table 2 benchmark: a far and a close-up view,
                        every mode (adaptive with every metric unless
                        --tess-metric is given) on every device and backend.
                        With --backend all: hulldomain, r2vb and streamout in
                        one run at the emulated tessellator's maximum level
                        (--tess-max 14.99), a Chrome trace per backend and a
                        side-by-side table (GPU ms per pass, triangles,
                        shader invocations, intermediate memory, ratios to
                        hulldomain)
  --bench characters    run the characters benchmark: the crowd (--crowd,
                        --model) posed at one time from one camera, drawn
                        two-pass and single-pass on every backend (or
                        --backend NAME; all: hulldomain, r2vb, streamout) at
                        min(--character-level, 14.99), and also at
                        --character-level where the backend reaches it
                        (default 32; hulldomain only); reports GPU ms of the
                        character passes, amplification, Table 1 bytes and
                        the compressed vertex's error
  --bench crowd-sim     run the crowd simulation benchmark (no GPU): on the
                        generated terrain, for each --agents size, the time
                        to create the crowd, then --warmup steps (default
                        60) and --steps measured steps (default 300) with a
                        crater among the agents every 3 simulated seconds;
                        reports ms per step (total, fields, avoidance,
                        integration: median, mean, max), memory per agent,
                        overlaps, arrivals, stuck and fleeing agents, field
                        tiles solved, threads (--threads) and the CPU
  --bench crowd         run the crowd rendering benchmark at 1920x1080 (or
                        --width/--height): for each --agents size (default
                        1000,10000,65000) the simulated crowd on the terrain
                        from one camera over it, and the terrain alone from
                        the same camera, on every backend (--backend all) or
                        one; --warmup frames (default 10) then --frames
                        measured frames (default 30); reports GPU ms per
                        pass (cull and bin, skin, each tier's draw), GPU and
                        CPU frame ms, simulation ms, instances and
                        triangles per tier, GPU memory per agent and the
                        ratios to hulldomain and to the terrain alone
  --bench subdiv        the second paper's section 7: every --model .obj
                        surface on each backend (or --backend all), the base
                        surface, displaced, displaced with the level of
                        detail and with the Weingarten term, at the shared
                        level 14.99 (and --subdiv-level where a backend goes
                        higher); GPU ms of the subdivision passes, ratios to
                        the base surface, triangles, tile memory against a
                        dense mesh and atlas maps
  --steps N             --bench crowd-sim's measured steps
  --out FILE            where --bench writes its JSON (default: stdout)
  --out-dir DIR         where --bench writes its per-backend traces,
                        bench-<backend>.json, bench-characters-<backend>.json
                        for characters (--backend all: default next to
                        --out, else the current directory)
  --help                this text
)";
}

Result<Options> parseCommandLine(const std::vector<std::string>& args) {
    Options o;
    bool crowdDrawGiven = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& flag = args[i];
        auto value = [&]() -> Result<std::string> {
            if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0) return fail(flag, " needs a value");
            return args[++i];
        };
#define TESSERA_TAKE(var)                        \
    auto var##Value = value();                   \
    if (!var##Value) return var##Value.error();  \
    const std::string& var = var##Value.value()
#define TESSERA_TAKE_NUMBER(field, min, max)                        \
    {                                                               \
        TESSERA_TAKE(text);                                         \
        auto n = parseNumber(flag, text, min, max);                 \
        if (!n) return n.error();                                   \
        o.field = n.value();                                        \
    }
#define TESSERA_TAKE_COUNT(field, min, max)                         \
    {                                                               \
        TESSERA_TAKE(text);                                         \
        auto n = parseCount(flag, text, min, max);                  \
        if (!n) return n.error();                                   \
        o.field = n.value();                                        \
    }
        if (flag == "--help" || flag == "-h") o.help = true;
        else if (flag == "--list-backends") o.listBackends = true;
        else if (flag == "--list-devices") o.listDevices = true;
        else if (flag == "--validation") o.validation = true;
        else if (flag == "--window") o.window = true;
        else if (flag == "--wireframe") o.wireframe = true;
        else if (flag == "--no-displacement") o.displacement = false;
        else if (flag == "--no-terrain") o.terrain = false;
        else if (flag == "--model") {
            TESSERA_TAKE(v);
            (isObjFile(v) ? o.surfaces : o.models).push_back(v);
        }
        else if (flag == "--character-surface") {
            TESSERA_TAKE(v);
            if (v != "planar" && v != "catmull-clark" && v != "both")
                return fail("--character-surface expects planar, catmull-clark or both, got \"", v, "\"");
            o.characterSurface = v;
        }
        else if (flag == "--normals") {
            TESSERA_TAKE(v);
            if (v == "approximate") o.subdiv.normals = 0;
            else if (v == "accurate") o.subdiv.normals = 1;
            else return fail("--normals expects accurate or approximate, got \"", v, "\"");
        }
        else if (flag == "--subdiv-view") {
            TESSERA_TAKE(v);
            const char* const views[] = {"shaded", "patches", "levels", "mips"};
            auto it = std::find(std::begin(views), std::end(views), v);
            if (it == std::end(views))
                return fail("--subdiv-view expects shaded, patches, levels or mips, got \"", v, "\"");
            o.subdiv.view = uint32_t(it - std::begin(views));
        }
        else if (flag == "--subdiv-level") {
            // L, or A:B for a sweep from A to B over the run's frames.
            TESSERA_TAKE(text);
            const size_t colon = text.find(':');
            auto n = parseNumber(flag, text.substr(0, colon), 1.0f, 64.0f);
            if (!n) return n.error();
            o.subdiv.level = n.value();
            if (colon != std::string::npos) {
                auto end = parseNumber(flag, text.substr(colon + 1), 1.0f, 64.0f);
                if (!end) return end.error();
                o.subdiv.levelEnd = end.value();
            }
        }
        else if (flag == "--subdiv-pixels") {
            TESSERA_TAKE(text);
            auto n = parseNumber(flag, text, 0.5f, 1000.0f);
            if (!n) return n.error();
            o.subdiv.pixels = n.value();
        }
        else if (flag == "--subdiv-amplitude") {
            TESSERA_TAKE(text);
            auto n = parseNumber(flag, text, 0.0f, 0.25f);
            if (!n) return n.error();
            o.subdiv.amplitude = n.value();
        }
        else if (flag == "--subdiv-budget") {
            TESSERA_TAKE(text);
            auto n = parseCount(flag, text, 1000, 1000000000);
            if (!n) return n.error();
            o.subdiv.budget = n.value();
        }
        else if (flag == "--no-mips") o.subdiv.mips = false;
        else if (flag == "--subdiv-still") o.subdiv.animate = false;
        else if (flag == "--sculpt") {
            TESSERA_TAKE(v);
            if (v == "raise") o.subdiv.sculpt = 1;
            else if (v == "lower") o.subdiv.sculpt = -1;
            else return fail("--sculpt expects raise or lower, got \"", v, "\"");
        }
        else if (flag == "--scene") {
            TESSERA_TAKE(v);
            if (v != "terrain" && v != "characters" && v != "crowd")
                return fail("--scene expects terrain, characters or crowd, got \"", v, "\"");
            o.scene = v;
            o.sceneGiven = true;
        } else if (flag == "--character-path") {
            TESSERA_TAKE(v);
            if (v == "two-pass") o.characterPath = backend::CharacterPath::TwoPass;
            else if (v == "single-pass") o.characterPath = backend::CharacterPath::SinglePass;
            else return fail("--character-path expects two-pass or single-pass, got \"", v, "\"");
        }
        else if (flag == "--character-level") {
            TESSERA_TAKE(text);
            auto n = parseNumber(flag, text, 1.0f, 64.0f);
            if (!n) return n.error();
            o.characterLevel = n.value();
        }
        else if (flag == "--lod-colors") o.lodColors = true;
        else if (flag == "--lod-near" || flag == "--lod-far") {
            TESSERA_TAKE(text);
            auto n = parseNumber(flag, text, 0.5f, 100000.0f);
            if (!n) return n.error();
            (flag == "--lod-near" ? o.lodNear : o.lodFar) = n.value();
        }
        else if (flag == "--lod-budget") {
            TESSERA_TAKE(text);
            auto n = parseCount(flag, text, 0, UINT32_MAX);
            if (!n) return n.error();
            if (n.value() == 0)
                return fail("--lod-budget 0: a budget of zero tessellated triangles draws nothing tessellated; give at "
                            "least one cage's worth (e.g. 10000)");
            o.lodBudget = n.value();
        }
        else if (flag == "--lod-middle-max") {
            TESSERA_TAKE(text);
            auto n = parseCount(flag, text, 0, 10000000);
            if (!n) return n.error();
            o.lodMiddleMax = n.value();
        }
        else if (flag == "--lod-fade") {
            TESSERA_TAKE(text);
            auto n = parseCount(flag, text, 0, TS_LOD_MAX_FADE_FRAMES);
            if (!n) return n.error();
            o.lodFade = n.value();
        }
        else if (flag == "--lod-edge") {
            TESSERA_TAKE(text);
            auto n = parseNumber(flag, text, 0.25f, 64.0f);
            if (!n) return n.error();
            o.lodEdge = n.value();
        }
        else if (flag == "--lod-far-triangles") {
            TESSERA_TAKE(text);
            auto n = parseCount(flag, text, 4, 100000);
            if (!n) return n.error();
            o.lodFarTriangles = n.value();
        }
        else if (flag == "--lod-near-max") {
            TESSERA_TAKE(text);
            auto n = parseCount(flag, text, 0, 100000);
            if (!n) return n.error();
            o.lodNearMax = n.value();
        }
        else if (flag == "--crowd") TESSERA_TAKE_COUNT(crowd, 0, 256)
        else if (flag == "--orbit-distance") {
            // M, or A:B for a dolly from A to B metres over the run.
            TESSERA_TAKE(text);
            const size_t colon = text.find(':');
            auto n = parseNumber(flag, text.substr(0, colon), 0.25f, 10000.0f);
            if (!n) return n.error();
            o.orbitDistance = n.value();
            if (colon != std::string::npos) {
                auto end = parseNumber(flag, text.substr(colon + 1), 0.25f, 10000.0f);
                if (!end) return end.error();
                o.orbitDistanceEnd = end.value();
            }
        }
        else if (flag == "--agents") {
            TESSERA_TAKE(v);
            auto counts = parseAgents(v);
            if (!counts) return counts.error();
            o.agents = counts.value();
        }
        else if (flag == "--crowd-draw") {
            TESSERA_TAKE_COUNT(crowdDraw, 0, 4096)
            crowdDrawGiven = true;
        }
        else if (flag == "--threads") TESSERA_TAKE_COUNT(threads, 0, 1024)
        else if (flag == "--steps") TESSERA_TAKE_COUNT(steps, 1, 10000000)
        else if (flag == "--backend") { TESSERA_TAKE(v); o.backend = v; }
        else if (flag == "--device") { TESSERA_TAKE(v); o.device = v; }
        else if (flag == "--plugin-dir") { TESSERA_TAKE(v); o.pluginDirs.push_back(v); }
        else if (flag == "--content") { TESSERA_TAKE(v); o.contentDir = v; }
        else if (flag == "--heightmap") { TESSERA_TAKE(v); o.heightmap = v; }
        else if (flag == "--screenshot") { TESSERA_TAKE(v); o.screenshot = v; }
        else if (flag == "--capture") { TESSERA_TAKE(v); o.capture = v; }
        else if (flag == "--benchmark") { TESSERA_TAKE(v); o.benchmark = v; }
        else if (flag == "--dump-heights") { TESSERA_TAKE(v); o.dumpHeights = v; }
        else if (flag == "--crowd-tiers") { TESSERA_TAKE(v); o.crowdTiers = v; }
        else if (flag == "--record") { TESSERA_TAKE(v); o.record = v; }
        else if (flag == "--out") { TESSERA_TAKE(v); o.benchOut = v; }
        else if (flag == "--out-dir") { TESSERA_TAKE(v); o.benchOutDir = v; }
        else if (flag == "--bench") {
            TESSERA_TAKE(v);
            if (v != "terrain" && v != "characters" && v != "crowd" && v != "crowd-sim" && v != "subdiv")
                return fail("--bench expects \"terrain\", \"characters\", \"crowd\", \"crowd-sim\" or \"subdiv\", got \"",
                            v, "\"");
            o.bench = v;
        } else if (flag == "--terrain-mode") {
            TESSERA_TAKE(v);
            auto mode = terrain::parseTerrainMode(v);
            if (!mode) return fail("--terrain-mode expects lowres, continuous or adaptive, got \"", v, "\"");
            o.terrainMode = *mode;
        } else if (flag == "--tess-metric") {
            TESSERA_TAKE(v);
            auto metric = terrain::parseTessMetric(v);
            if (!metric) return fail("--tess-metric expects screen, distance, silhouette or detail, got \"", v, "\"");
            o.tessellation.metric = *metric;
            o.tessMetricGiven = true;
        }
        else if (flag == "--tess-target") {
            TESSERA_TAKE_NUMBER(tessellation.targetPixels, 0.25f, 1000.0f)
            o.tessTargetGiven = true;
        }
        else if (flag == "--tess-distance") TESSERA_TAKE_NUMBER(tessellation.farDistance, 1.0f, 1.0e6f)
        else if (flag == "--tess-level") {
            TESSERA_TAKE_NUMBER(tessellation.continuousLevel, 1.0f, 64.0f)
            o.tessLevelGiven = true;
        }
        else if (flag == "--tess-max") {
            TESSERA_TAKE_NUMBER(tessellation.maxLevel, 1.0f, 64.0f)
            o.tessMaxGiven = true;
        }
        else if (flag == "--meteors") {
            TESSERA_TAKE_COUNT(meteors, 0, 10000)
            o.meteorsGiven = true;
        }
        else if (flag == "--splat") {
            TESSERA_TAKE(v);
            auto splat = parseSplat(v);
            if (!splat) return splat.error();
            o.splats.push_back(splat.value());
        }
        else if (flag == "--width") {
            TESSERA_TAKE_COUNT(width, 16, 16384)
            o.sizeGiven = true;
        }
        else if (flag == "--height") {
            TESSERA_TAKE_COUNT(height, 16, 16384)
            o.sizeGiven = true;
        }
        else if (flag == "--frames") TESSERA_TAKE_COUNT(frames, 1, 10000000)
        else if (flag == "--warmup") {
            TESSERA_TAKE_COUNT(warmup, 0, 1000000)
            o.warmupGiven = true;
        }
        else if (flag == "--seed") TESSERA_TAKE_COUNT(seed, 0, UINT32_MAX)
        else if (flag == "--clear-color") {
            TESSERA_TAKE(v);
            auto c = parseColor(v);
            if (!c) return c.error();
            o.clearColor = c.value();
        } else if (flag == "--camera") {
            TESSERA_TAKE(v);
            auto pose = scene::parseCameraPose(v);
            if (!pose) return pose.error();
            o.camera = pose.value();
        } else {
            return fail("unknown option \"", flag, "\"; run with --help for the list");
        }
#undef TESSERA_TAKE_NUMBER
#undef TESSERA_TAKE_COUNT
#undef TESSERA_TAKE
    }
    if (o.backend == "all" && o.bench.empty())
        return fail("--backend all compares the backends in --bench terrain, characters or crowd; pick one backend "
                    "for the demo");
    const float lodNear = o.lodNear.value_or(lod::LodPolicy{}.nearPixels);
    const float lodFar = o.lodFar.value_or(lod::LodPolicy{}.farPixels);
    if (lodFar > lodNear)
        return fail("--lod-far ", formatNumber(lodFar), " is above --lod-near ", formatNumber(lodNear),
                    ": the far threshold must be the smaller");
    if ((!o.models.empty() || !o.surfaces.empty()) && !o.sceneGiven) o.scene = "characters";
    const bool crowdFlags = !o.agents.empty() || crowdDrawGiven;
    if (crowdFlags && !o.sceneGiven && o.bench.empty()) o.scene = "crowd";
    // With no scene asked for, the showcase: the crowd on the adaptive
    // terrain under a meteor shower, seen from a flight over it.
    if (!o.sceneGiven && o.models.empty() && o.surfaces.empty() && o.bench.empty()) o.scene = "crowd";
    if (o.scene == "crowd" && o.bench.empty() && !o.meteorsGiven) o.meteors = kCrowdSceneMeteors;
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
    if (!o.tessTargetGiven) o.tessellation.targetPixels = terrain::defaultTargetPixels(o.tessellation.metric);
    if (o.window && !o.record.empty()) return fail("--record writes headless frames; drop --window");
    if (o.window && !o.screenshot.empty() && o.frames == 0)
        return fail("--screenshot with --window needs --frames N to know which frame to capture");
    return o;
}

} // namespace tessera::demo
