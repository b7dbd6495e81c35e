#pragma once
/// @file Options.h
/// Everything a run of the runtime is told: backend and device, the scene
/// (terrain, characters, crowd, subdivision surfaces), level of detail,
/// outputs and benchmarks. Plain data with working defaults: a game fills in
/// what it needs; tessera-demo fills it from its command line (each field
/// names its flag, documented in `tessera-demo --help`). A value whose
/// default depends on the mode (the benchmarks', the backend's) is a
/// std::optional: unset, the mode decides; set, it is the caller's choice.

#include "tessera/backend/CharacterDesc.h"
#include "tessera/device/FeatureMask.h"
#include "tessera/backend/FrameInfo.h"
#include "tessera/core/Result.h"
#include "tessera/scene/CameraPose.h"
#include "tessera/terrain/CraterSplat.h"
#include "tessera/terrain/TessellationSettings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::runtime {

class Reporter;

/// How --model .obj files (Catmull-Clark surfaces with analytic
/// displacement, docs/SUBDIV.md) are drawn.
struct SubdivOptions {
    uint32_t normals = 0;               ///< --normals approximate (0) | accurate (1): TS_SUBDIV_NORMALS_*
    std::optional<float> level;         ///< --subdiv-level L: one level everywhere (measurements)
    std::optional<float> levelEnd;      ///< --subdiv-level A:B: the level swept from A to B over the run
    std::optional<float> pixels;        ///< --subdiv-pixels PX: target pixels per tessellated segment
    uint32_t view = 0;                  ///< --subdiv-view shaded|patches|levels|mips: TS_SUBDIV_VIEW_*
    bool mips = true;                   ///< --no-mips: sample the finest displacement level everywhere
    std::optional<uint64_t> budget;     ///< --subdiv-budget T: tessellated triangles per frame, all surfaces
    float amplitude = 0.02f;            ///< --subdiv-amplitude A: procedural displacement, fraction of the diagonal
    bool animate = true;                ///< --subdiv-still: the cages keep their rest pose
    int sculpt = 0;                     ///< --sculpt raise|lower: +1 / -1, a scripted stroke, one dab a frame
};

/// The terrain's tessellation as the caller asks for it (the first paper's
/// Table 2 modes; the mode itself is Options::terrainMode). What is left
/// unset takes the metric's or the backend's default; a level set above
/// what the backend draws is an error, a default one is clamped to it (as
/// D3D10-era hardware clamps to 14.99).
struct TessellationOptions {
    /// --tess-metric: the adaptive mode's metric; unset: screen (--bench
    /// terrain: every metric).
    std::optional<terrain::TessMetric> metric;
    /// --tess-target: pixels per edge (screen, silhouette) or of error
    /// (detail); unset: the metric's default (terrain::defaultTargetPixels).
    std::optional<float> targetPixels;
    /// --tess-distance: the distance metric's metres where the level reaches 1.
    float farDistance = terrain::TessellationSettings{}.farDistance;
    /// --tess-level: the continuous mode's level; unset: 15.
    std::optional<float> continuousLevel;
    /// --tess-max: the adaptive mode's largest level; unset: the backend's maximum.
    std::optional<float> maxLevel;

    /// The settings asked for, before a backend checks and clamps them (its
    /// mode still the default).
    terrain::TessellationSettings settings() const;
};

/// Meteor impacts over a crowd-scene run when --meteors is not given.
inline constexpr uint32_t kCrowdSceneMeteors = 4;
/// The frame size when the options give none.
inline constexpr uint32_t kDefaultWidth = 1280, kDefaultHeight = 720;

struct Options {
    /// Where the run's errors and warnings go, naming settings the host's way
    /// (Reporter.h); null: the log, in the runtime's words. Not owned: it
    /// must outlive every object made from these options.
    const Reporter* reporter = nullptr;
    std::string backend;                ///< empty: best backend the device runs; "all" (--bench only): every GPU backend
    std::string device;                 ///< --device NAME|INDEX
    std::vector<std::string> pluginDirs; ///< --plugin-dir (repeatable)
    std::string contentDir;             ///< --content DIR
    std::string heightmap;              ///< --heightmap FILE (8/16-bit gray PNG)
    bool listBackends = false;
    bool listDevices = false;
    bool help = false;
    bool validation = false;
    /// --device-memory-cap: bytes of device memory the run may allocate (0:
    /// no cap); past it an allocation throws OutOfDeviceMemory as a real
    /// exhaustion would (gpu::Device::setMemoryCap).
    uint64_t deviceMemoryCap = 0;
    /// --hide-features: device features the backends are told the device
    /// lacks (and that are not enabled on it).
    device::FeatureMask hiddenFeatures;
    /// Fault injection for the exhaustion tests (gpu::Device::failAllocation):
    /// the device allocation with this index fails. No flag sets it.
    std::optional<uint64_t> failAllocation;
    bool window = false;
    /// --overlay / --no-overlay: the Dear ImGui overlay of statistics and
    /// controls; unset: with --window only. Headless, --overlay draws it into
    /// the frames (screenshots, and its GPU cost in --benchmark).
    std::optional<bool> overlay;
    bool wireframe = false;
    /// --look plain|full: today's shading or the full look (sky, fog, shadows,
    /// tone mapping; docs/LOOKS.md). The terrain benchmark measures both.
    backend::Look look = backend::Look::Full;
    /// --terrain-shading auto|forward|deferred: where the full look shades the terrain.
    backend::TerrainShading terrainShading = backend::TerrainShading::Auto;
    /// --shadows auto|blob|cascaded|none: the characters' shadows in the full look
    /// (docs/LOOKS.md); cascaded only on a backend that draws them.
    backend::Shadows shadows = backend::Shadows::Auto;
    glm::vec3 sunDirection{0.4f, 0.8f, 0.3f}; ///< --sun: towards the sun (normalised by the backend)
    bool benchBothLooks = false;        ///< --look both: --bench terrain measures every row in both looks
    /// --width, --height; unset: kDefaultWidth x kDefaultHeight (--bench
    /// crowd: 1920x1080 unless either is given).
    std::optional<uint32_t> width, height;
    uint32_t frames = 0;                ///< 0: the mode's default
    /// --warmup: frames run first and left out of measurements; unset: none,
    /// or the benchmark's default (BenchPlan::warmup).
    std::optional<uint32_t> warmup;
    uint32_t seed = 1;
    glm::vec3 clearColor{0.55f, 0.68f, 0.85f};
    std::optional<scene::CameraPose> camera; ///< --camera fixes the view
    std::string screenshot;             ///< PNG of the last frame
    std::string capture;                ///< Chrome trace JSON
    std::string benchmark;              ///< benchmark JSON
    std::string dumpHeights;            ///< --dump-heights PREFIX: PREFIX.gpu.png and PREFIX.cpu.png
    /// --crowd-tiers FILE: the last frame's crowd agents per LOD tier as the
    /// backend binned them and as the CPU reference did (JSON).
    std::string crowdTiers;
    std::string record;                 ///< --record DIR: every frame as DIR/frame_NNNN.png
    /// --renderdoc N: capture frame N (from 0, warm-up frames included)
    /// through RenderDoc's in-application API, when librenderdoc.so is
    /// there; without it a warning and the run goes on.
    std::optional<uint32_t> renderdocFrame;
    std::string renderdocPath = "tessera"; ///< --renderdoc-file PREFIX: RenderDoc names the file from it

    /// --terrain-mode; unset: adaptive where the backend draws it, else lowres.
    std::optional<terrain::TerrainMode> terrainMode;
    /// --tess-metric, --tess-target, --tess-level, --tess-max, --tess-distance.
    TessellationOptions tessellation;
    uint32_t meteors = 0;                         ///< --meteors N (tessera-demo's crowd scene: kCrowdSceneMeteors unless given)
    std::vector<terrain::CraterSplat> splats;     ///< --splat x,z,radius[,depth], before the first frame

    /// --scene terrain|characters|crowd. "terrain" is the flythrough over
    /// the terrain alone. "characters" (the default when --model is given)
    /// walks a crowd of generated creatures, CesiumMan and every --model on
    /// the terrain, with the camera circling them. "crowd" (the default
    /// otherwise, outside the benchmarks: the showcase) simulates --agents
    /// agents under a meteor shower and draws them all as an instanced
    /// crowd where the backend culls and bins crowds on the GPU, from a
    /// flight over them (an orbit with --orbit-distance).
    std::string scene = "terrain";
    std::vector<std::string> models;    ///< --model FILE (repeatable): any .gltf or .glb
    std::vector<std::string> surfaces;  ///< --model FILE.obj (repeatable): Catmull-Clark control meshes
    SubdivOptions subdiv;
    /// --character-surface planar|catmull-clark|both: the --model .glb
    /// characters as planar cages, as Catmull-Clark surfaces with their
    /// .cctiles displacement (SubdivCharacters), or both side by side.
    std::string characterSurface = "planar";
    uint32_t crowd = 6;                 ///< --crowd N: generated creatures (0: only the --model files, no CesiumMan)
    /// --orbit-distance M: the camera circle's radius; unset: 5 m in the
    /// characters scene, 30 m in the crowd scene.
    std::optional<float> orbitDistance;
    std::optional<float> orbitDistanceEnd; ///< --orbit-distance A:B: the dolly's end
    bool displacement = true;           ///< --no-displacement draws the bare interpolated cage
    bool horizonCulling = true;         ///< --no-horizon-culling draws crowd agents behind the terrain too
    bool terrain = true;                ///< --no-terrain: characters alone on the clear colour (crack tests, captures)
    backend::CharacterPath characterPath = backend::CharacterPath::TwoPass; ///< --character-path
    std::optional<float> characterLevel; ///< --character-level L; unset: from each character's size on screen
    /// The LOD manager's policy over the device class's defaults
    /// (lod::LodPolicy::forDevice): --lod-near PX, --lod-far PX (thresholds
    /// in projected pixels), --lod-budget T (tessellated triangles per
    /// frame), --lod-near-max N (tessellated instances per frame).
    std::optional<float> lodNear, lodFar;
    std::optional<float> lodImpostor;          ///< --lod-impostor PX: impostors below PX (0: only past the far budget)
    std::optional<uint64_t> lodBudget;
    std::optional<uint32_t> lodNearMax;
    std::optional<uint32_t> lodMiddleMax;      ///< --lod-middle-max N: untessellated cages per frame
    std::optional<uint32_t> lodFarMax;         ///< --lod-far-max N: far meshes per frame (the rest: impostors)
    std::optional<float> lodEdge;              ///< --lod-edge PX: the near tier's tessellated edge in pixels
    std::optional<uint32_t> lodFade;           ///< --lod-fade N: cross-fade frames (0: instant)
    std::optional<uint32_t> lodFarTriangles;   ///< --lod-far-triangles N: the far mesh's triangles at most
    std::optional<uint32_t> lodMiddleTriangles; ///< --lod-middle-triangles N: the middle mesh's (0: the cage)
    /// --lod-far-caster-triangles N: the far tier's shadow casters' (0: the far mesh)
    std::optional<uint32_t> lodFarCasterTriangles;
    bool lodColors = false;             ///< --lod-colors: tint instances by LOD tier

    /// --agents N (the crowd scene's agents; unset: 2000) or, with --bench
    /// crowd or crowd-sim, a comma list of crowd sizes (unset:
    /// 1000,10000,65000). Each from 1 to crowd::Crowd::kMaxAgents.
    std::vector<uint32_t> agents;
    uint32_t crowdDraw = 48;            ///< --crowd-draw K: agents drawn in the crowd scene, the nearest in view
    uint32_t threads = 0;               ///< --threads N: the crowd's threads (0: every hardware thread)
    uint32_t steps = 0;                 ///< --steps N: --bench crowd-sim's measured steps (0: its default)

    /// --bench terrain (the Table 2 benchmark), characters (two-pass vs
    /// single-pass, amplification, Table 1, compression error), crowd (the
    /// instanced crowd's GPU passes, frame times, tiers and memory per crowd
    /// size and backend), crowd-sim (the crowd simulation's step time,
    /// memory and behaviour; no GPU) or subdiv (the subdivision surfaces'
    /// levels, triangles and passes per backend) instead of the flythrough.
    std::string bench;
    std::string benchOut;               ///< --out FILE (default: stdout)
    /// --out-dir DIR: where --bench writes one Chrome trace per backend
    /// (bench-<backend>.json). With --backend all they are written anyway:
    /// next to --out, else in the current directory.
    std::string benchOutDir;
};

/// A number as a user writes it ("14.99", "20"), for messages about
/// settings.
std::string formatNumber(double value);

} // namespace tessera::runtime
