#include "tessera/demo/DemoFlags.h"

#include "tessera/cli/Validators.h"
#include "tessera/shaders/CrowdLod.h"

#include <cstdint>

namespace tessera::demo {

void declareDemoFlags(cli::CommandLine& line, runtime::Options& o, DemoFlagText& t) {
    CLI::App& app = line.app();
    auto group = [&](const char* name) { app.option_defaults()->group(name); };
    auto flag = [&](const char* name, bool& into, const char* desc) { app.add_flag(name, into, desc); };
    auto text = [&](const char* name, std::string& into, const char* type, const char* desc) {
        return app.add_option(name, into, desc)->type_name(type)->allow_extra_args(false);
    };
    auto repeated = [&](const char* name, std::vector<std::string>& into, const char* type, const char* desc) {
        app.add_option(name, into, desc)
            ->type_name(type)
            ->expected(1)
            ->allow_extra_args(false)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    };
    auto count = [&](const char* name, auto& into, uint64_t lo, uint64_t hi, const char* type, const char* desc) {
        app.add_option(name, into, desc)->type_name(type)->allow_extra_args(false)->check(cli::count(lo, hi));
    };
    auto number = [&](const char* name, auto& into, double lo, double hi, const char* type, const char* desc) {
        app.add_option(name, into, desc)->type_name(type)->allow_extra_args(false)->check(cli::number(lo, hi));
    };
    auto choice = [&](const char* name, std::string& into, std::vector<std::string> choices, const char* type,
                      const char* desc) { text(name, into, type, desc)->check(cli::oneOf(std::move(choices))); };

    group("Backend and device");
    text("--backend", o.backend, "NAME",
         "r2vb | streamout | hulldomain | meshshader | null (default: hulldomain on a GPU, streamout on a CPU "
         "rasterizer such as lavapipe, where it is the fastest; else the next the device runs); with "
         "--bench terrain, characters, crowd or subdiv also \"all\": every GPU backend side by side");
    flag("--list-backends", o.listBackends, "list backends and their capabilities on the device");
    text("--device", o.device, "NAME|INDEX", "pick a Vulkan device by index or name substring");
    flag("--list-devices", o.listDevices, "list Vulkan devices");
    repeated("--plugin-dir", o.pluginDirs, "DIR", "also search DIR for backend plugins (repeatable)");
    flag("--validation", o.validation,
         "enable the Khronos validation layer; print and count every message, fail at exit if there were any");
    count("--device-memory-cap", t.deviceMemoryCap, 1, 1048576, "MIB",
          "simulate a device with only MIB MiB of memory for Tessera: the allocation that would go past it ends the "
          "run with a message naming it, everything released, exit 1 (docs/RELIABILITY.md)");
    text("--hide-features", t.hideFeatures, "LIST",
         "simulate a device without these features (comma list of tessellation, geometry, transform-feedback, "
         "pipeline-statistics, timestamps, wireframe, vertex-stores, multi-draw-indirect): they are not enabled, "
         "a backend that needs one refuses, naming it, and without --backend the next backend that can runs");

    group("Scene");
    choice("--scene", o.scene, {"terrain", "characters", "crowd"}, "NAME",
           "crowd (the default: the crowd simulation, --agents agents wandering between four goals under a meteor "
           "shower, every one drawn as an instanced crowd culled and sorted into LOD tiers on the GPU, seen from a "
           "flight over it) | terrain (the flythrough over the terrain alone) | characters (a few tessellated, "
           "displaced, animated creatures and CesiumMan walking on the terrain; the default when --model is given)");
    repeated("--model", t.models, "FILE",
             "place a .gltf or .glb file in the characters scene, playing its first animation, or (--scene crowd) "
             "mix it into the crowd with the generated creatures; a crowd's models need a skin and a walk clip; or "
             "a .obj control mesh (OpenSubdiv's tags read) drawn as a Catmull-Clark surface with a procedural "
             "analytic displacement, in the characters scene (repeatable)");
    count("--crowd", o.crowd, 0, 256, "N",
          "generated creatures in the characters scene, with CesiumMan (default 6; 0: only the --model files, "
          "centred where the crowd would stand)");
    text("--orbit-distance", t.orbitDistance, "M",
         "radius of the camera's circle around the characters (default 5 metres); in the crowd scene, circle the "
         "crowd's spawn at M metres instead of flying over it; A:B dollies from A to B metres over the run");
    text("--agents", t.agents, "N",
         "agents in the crowd scene (default 2000; refused when more than the machine's memory holds); with "
         "--bench crowd or crowd-sim a comma list of crowd sizes (default 1000,10000,65000)");
    count("--crowd-draw", o.crowdDraw, 0, 4096, "K",
          "on a backend without instanced crowds, how many agents the crowd scene draws, the nearest in view, one "
          "character draw each (default 48)");
    count("--threads", o.threads, 0, 1024, "N", "the crowd simulation's threads (default 0: every hardware thread)");
    app.add_flag("--no-displacement{false}", o.displacement, "draw characters without their displacement maps");
    app.add_flag("--no-horizon-culling{false}", o.horizonCulling,
                 "draw crowd agents the terrain hides too (culled by default, docs/CROWD.md)");
    app.add_flag("--no-terrain{false}", o.terrain, "draw the characters alone on the clear colour");
    choice("--character-path", t.characterPath, {"two-pass", "single-pass"}, "P",
           "two-pass (skin the cage once into 128-bit vertices, then tessellate; default) | single-pass (skin every "
           "tessellated vertex)");
    number("--character-level", t.characterLevel, 1, 64, "L",
           "characters' tessellation level, 1 to the backend's maximum (default: from each character's size on "
           "screen); every character in view is then tessellated at L, with no LOD budget unless the --lod-* flags "
           "give one");
    number("--lod-near", t.lodNear, 0.5, 100000, "PX",
           "LOD threshold: characters at least PX pixels tall on screen are tessellated (default 192)");
    number("--lod-far", t.lodFar, 0.5, 100000, "PX",
           "characters below PX pixels tall are drawn with the simplest mesh (default 64), the cage in between");
    number("--lod-impostor", t.lodImpostor, 0, 100000, "PX",
           "characters below PX pixels tall are drawn as impostors, cards from their baked views (default 32; 0: only "
           "those beyond the far tier's budget); at most --lod-far");
    count("--lod-budget", t.lodBudget, 0, UINT32_MAX, "T",
          "at most T tessellated triangles a frame (default: 24000000 on a GPU, 100000 on lavapipe)");
    count("--lod-near-max", t.lodNearMax, 0, 100000, "N",
          "at most N tessellated characters a frame (default: 256 on a GPU, 4 on lavapipe)");
    count("--lod-middle-max", t.lodMiddleMax, 0, 10000000, "N",
          "at most N characters drawn in the middle tier a frame, beyond which the smallest take the far "
          "mesh, never one at or above the far threshold (default 16384 on a GPU, 64 on lavapipe)");
    count("--lod-far-max", t.lodFarMax, 0, UINT32_MAX, "N",
          "at most N characters drawn with the far mesh a frame, beyond which the smallest are drawn as impostors "
          "(default: unlimited on a GPU, 3000 on lavapipe)");
    count("--lod-fade", t.lodFade, 0, TS_LOD_MAX_FADE_FRAMES, "N",
          "frames a tier change cross-fades over (dithered; default 8 on a GPU, 4 on lavapipe, 0: switch at once, at most "
          "63)");
    number("--lod-edge", t.lodEdge, 0.25, 64, "PX",
           "tessellate near characters to edges of about PX pixels (default 2 on a GPU, 3 on lavapipe)");
    count("--lod-far-triangles", t.lodFarTriangles, 4, 100000, "N",
          "the far tier's mesh simplified to at most N triangles (default 120 on a GPU, 200 on lavapipe; the "
          "content's far mesh has about 280)");
    count("--lod-middle-triangles", t.lodMiddleTriangles, 0, 1000000, "N",
          "the middle tier draws at most N of the cage's triangles, simplified over its vertices (default 0 on a "
          "GPU: the whole cage; 1000 on lavapipe)");
    count("--lod-far-caster-triangles", t.lodFarCasterTriangles, 0, 100000, "N",
          "with --shadows cascaded, far creatures cast their far mesh simplified to at most N triangles (default "
          "96; 0: the far mesh itself)");
    flag("--lod-colors", o.lodColors, "tint characters by LOD tier: near green, middle yellow, far red");
    text("--crowd-tiers", o.crowdTiers, "FILE",
         "write the last frame's crowd agents per LOD tier, as the backend binned them and as the CPU reference "
         "did (JSON; the crowd scene)");
    text("--heightmap", o.heightmap, "FILE",
         "8- or 16-bit grayscale PNG height map (default: the generated content/terrain/height.png)");
    text("--content", o.contentDir, "DIR", "content directory");
    count("--seed", o.seed, 0, UINT32_MAX, "N", "camera path, meteor and crowd spawn seed (default 1)");
    text("--camera", t.camera, "x,y,z,yaw,pitch", "fixed view (degrees) instead of the flythrough");
    flag("--wireframe", o.wireframe, "draw wireframe");
    choice("--look", t.look, {"plain", "full", "both"}, "L",
           "full (default): analytic sky, aerial-perspective fog, terrain sun shadows, filmic tone mapping | "
           "plain: the flat shading from before, to compare | both (--bench terrain only): every row in both "
           "looks, with the full look's cost (docs/LOOKS.md)");
    choice("--terrain-shading", t.terrainShading, {"auto", "forward", "deferred"}, "S",
           "where the full look shades the terrain: auto (default: deferred where the backend resolves in compute "
           "on a GPU, i.e. hulldomain; forward on r2vb, streamout and lavapipe) | "
           "forward (in its fragments) | deferred (once per pixel after the main pass; docs/LOOKS.md)");
    choice("--shadows", t.shadows, {"auto", "blob", "cascaded", "none"}, "S",
           "the characters' shadows in the full look: auto (default: the backend's cheaper for the device) | "
           "blob (a soft ellipse per character on the terrain, the cheapest) | cascaded (cascaded shadow maps: "
           "characters shadow the terrain and each other, where the backend draws them; docs/LOOKS.md) | none (no "
           "character shadows, to measure what the others cost)");
    text("--sun", t.sun, "az,el",
         "the sun's azimuth (degrees from +X towards +Z) and elevation (1 to 90 degrees); default 36.9,58 "
         "(shadows, sky and fog follow it)");
    count("--meteors", o.meteors, 0, 10000, "N",
          "a meteor shower of N impacts during the flythrough (the crowd scene: 4 unless given; 0 for none), "
          "deterministic by --seed; craters deform the terrain (in the crowd scene they land among the agents)");
    repeated("--splat", t.splats, "x,z,r[,depth]",
             "stamp a crater (metres) before the first frame (repeatable; depth defaults to 0.22 r)");

    group("Terrain tessellation (the first paper's Table 2 modes)");
    choice("--terrain-mode", t.terrainMode, {"lowres", "continuous", "adaptive"}, "M",
           "lowres | continuous | adaptive (default: adaptive where the backend draws it, else lowres)");
    choice("--tess-metric", t.tessMetric, {"screen", "distance", "silhouette", "detail"}, "M",
           "adaptive metric: screen (edge length in pixels), distance, silhouette, detail (height-map error in "
           "pixels); default screen");
    number("--tess-target", o.tessellation.targetPixels, 0.25, 1000, "PX",
           "pixels per edge (screen, silhouette) or of error (detail); default 16, or 2 for detail");
    number("--tess-distance", o.tessellation.farDistance, 1, 1.0e6, "M",
           "distance metric: metres where the level reaches 1 (default 4000)");
    number("--tess-level", o.tessellation.continuousLevel, 1, 64, "L",
           "continuous mode's level, 1 to the backend's maximum (default 15)");
    number("--tess-max", o.tessellation.maxLevel, 1, 64, "L",
           "largest adaptive level (default: the backend's maximum, 64 hardware, 14.99 emulated)");

    group("Subdivision surfaces (--model FILE.obj; the second paper, docs/SUBDIV.md)");
    choice("--normals", t.normals, {"accurate", "approximate"}, "N",
           "accurate (with the Weingarten term) | approximate (without; the default)");
    number("--subdiv-pixels", t.subdivPixels, 0.5, 1000, "PX",
           "screen-space level of detail: pixels per tessellated segment (default 6)");
    text("--subdiv-level", t.subdivLevel, "L",
         "one level everywhere instead (1 to the backend's maximum), for measurements; A:B sweeps it from A to B "
         "over the run's frames");
    count("--subdiv-budget", t.subdivBudget, 1000, 1000000000, "T",
          "tessellated triangles per frame, all surfaces (default: 150000 on lavapipe, 4000000 on a GPU); levels "
          "scale down to fit");
    app.add_flag("--no-mips{false}", o.subdiv.mips,
                 "sample the finest displacement mip everywhere instead of the level of detail's (section 6)");
    choice("--subdiv-view", t.subdivView, {"shaded", "patches", "levels", "mips"}, "V",
           "shaded | patches (regular patches green to blue by depth, end caps red) | levels | mips");
    number("--subdiv-amplitude", o.subdiv.amplitude, 0, 0.25, "A",
           "procedural displacement, fraction of the shape's diagonal (default 0.02; 0: the base surface)");
    choice("--sculpt", t.sculpt, {"raise", "lower"}, "raise|lower",
           "a scripted brush stroke around each surface, one dab a frame: the touched tiles, their mips and "
           "overlaps are rederived and re-uploaded");
    app.add_flag("--subdiv-still{false}", o.subdiv.animate,
                 "keep the control cages in their rest pose (they sway by default)");
    choice("--character-surface", o.characterSurface, {"planar", "catmull-clark", "both"}, "S",
           "planar (default) | catmull-clark | both: draw each --model .glb as the first paper's planar cage, as a "
           "Catmull-Clark surface with the tile displacement baked beside it (FILE.cctiles, made by "
           "tessera-creaturegen for the generated Froblins), or both side by side; the Catmull-Clark ones need a "
           "backend that draws subdivision surfaces (hulldomain)");

    group("Output");
    count("--width", o.width, 16, 16384, "N", "render width (default 1280)");
    count("--height", o.height, 16, 16384, "N", "render height (default 720)");
    text("--clear-color", t.clearColor, "r,g,b", "background colour, components in [0,1]");
    count("--frames", o.frames, 1, 10000000, "N",
          "frames to render after the warm-up (default 60 headless; until closed with --window)");
    flag("--window", o.window,
         "open a window (GLFW) instead of rendering headless, with an overlay of statistics and controls: F1 "
         "overlay, Tab free camera (WASD/QE, right mouse to look, Shift fast), 1-3 backends, F2 wireframe, F3 LOD "
         "colours, M meteor, F12 screenshot, F11 RenderDoc capture (with --renderdoc), Esc quit");
    app.add_flag_function("--overlay", [&o](std::int64_t) { o.overlay = true; },
                          "draw the overlay headless too (into screenshots; its GPU pass in --benchmark)");
    app.add_flag_function("--no-overlay", [&o](std::int64_t) { o.overlay = false; },
                          "with --window: no overlay (the scene alone)");
    text("--screenshot", o.screenshot, "FILE", "write the last frame as PNG");
    text("--record", o.record, "DIR", "write every frame as DIR/frame_NNNN.png (headless; waits for each frame)");
    text("--capture", o.capture, "FILE", "write a Chrome trace (Perfetto, chrome://tracing)");
    text("--benchmark", o.benchmark, "FILE", "write per-pass min/median/max GPU ms as JSON");
    count("--warmup", o.warmup, 0, 1000000, "N",
          "frames run first and left out of --benchmark (default 0; with --bench crowd-sim: unmeasured steps, "
          "default 60)");
    text("--dump-heights", o.dumpHeights, "PREFIX",
         "after the last frame write the GPU and CPU copies of the height map as PREFIX.gpu.png and "
         "PREFIX.cpu.png");

    count("--renderdoc", t.renderdocFrame, 0, 10000000, "N",
          "capture frame N (from 0, warm-up included) with RenderDoc's in-application API, every pass and object "
          "named; needs Debian's renderdoc package (librenderdoc.so), else a warning and the run goes on");
    text("--renderdoc-file", o.renderdocPath, "PREFIX",
         "where the capture goes: RenderDoc names it PREFIX_capture.rdc (default tessera, in the current directory); the demo prints the path");

    group("Benchmarks");
    choice("--bench", o.bench, {"terrain", "characters", "crowd", "crowd-sim", "subdiv"}, "NAME",
           "terrain: the first paper's Table 2, a far and a close-up view, every mode (adaptive with every metric "
           "unless --tess-metric is given), with --backend all every backend the device runs at the emulated "
           "tessellator's maximum level (14.99), a Chrome trace per backend and a side-by-side table | characters: "
           "the crowd (--crowd, --model) posed at one time, drawn two-pass and single-pass on every backend at "
           "min(--character-level, 14.99) and at --character-level where a backend reaches it (default 32); GPU "
           "ms, amplification, Table 1 bytes and the compressed vertex's error | crowd-sim: the crowd simulation "
           "(no GPU) for each --agents size, --warmup steps (default 60) then --steps measured (default 300); ms "
           "per step, memory per agent, behaviour | crowd: the crowd rendering benchmark at 1920x1080 for each "
           "--agents size (default 1000,10000,65000), --warmup frames (default 10) then --frames (default 30); GPU "
           "ms per pass, frame ms, instances and triangles per tier, memory per agent, ratios | subdiv: the second "
           "paper's section 7 on every --model .obj surface: base surface, displaced, with the level of detail "
           "and with the Weingarten term at level 14.99 (and --subdiv-level where a backend goes higher); GPU ms, "
           "triangles, tile memory against a dense mesh and atlas maps");
    count("--steps", o.steps, 1, 10000000, "N", "--bench crowd-sim's measured steps");
    text("--out", o.benchOut, "FILE", "where --bench writes its JSON (default: stdout)");
    text("--out-dir", o.benchOutDir, "DIR",
         "where --bench writes its per-backend traces, bench-<backend>.json, bench-characters-<backend>.json for "
         "characters (--backend all: default next to --out, else the current directory)");
}

} // namespace tessera::demo
