#pragma once
/// @file DemoOptions.h
/// The demo's command line. Every flag is documented in helpText(); parsing
/// never exits, it returns an error naming the bad flag.

#include "tessera/backend/CharacterDesc.h"
#include "tessera/core/Result.h"
#include "tessera/scene/CameraPose.h"
#include "tessera/terrain/CraterSplat.h"
#include "tessera/terrain/TessellationSettings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::demo {

struct DemoOptions {
    std::string backend;                ///< empty: best backend the device runs; "all" (--bench only): every GPU backend
    std::string device;                 ///< --device NAME|INDEX
    std::vector<std::string> pluginDirs; ///< --plugin-dir (repeatable)
    std::string contentDir;             ///< --content DIR
    std::string heightmap;              ///< --heightmap FILE (8/16-bit gray PNG)
    bool listBackends = false;
    bool listDevices = false;
    bool help = false;
    bool validation = false;
    bool window = false;
    bool wireframe = false;
    uint32_t width = 1280;
    uint32_t height = 720;
    uint32_t frames = 0;                ///< 0: the mode's default
    uint32_t warmup = 0;
    uint32_t seed = 1;
    glm::vec3 clearColor{0.55f, 0.68f, 0.85f};
    std::optional<scene::CameraPose> camera; ///< --camera fixes the view
    std::string screenshot;             ///< PNG of the last frame
    std::string capture;                ///< Chrome trace JSON
    std::string benchmark;              ///< benchmark JSON
    std::string dumpHeights;            ///< --dump-heights PREFIX: PREFIX.gpu.png and PREFIX.cpu.png

    /// --terrain-mode; unset: adaptive where the backend draws it, else lowres.
    std::optional<terrain::TerrainMode> terrainMode;
    /// --tess-metric, --tess-target, --tess-level, --tess-max, --tess-distance
    /// (mode is filled in once the backend is known).
    terrain::TessellationSettings tessellation;
    bool tessMaxGiven = false;
    bool tessLevelGiven = false;
    bool tessTargetGiven = false;
    bool tessMetricGiven = false;
    uint32_t meteors = 0;                         ///< --meteors N
    std::vector<terrain::CraterSplat> splats;     ///< --splat x,z,radius[,depth], before the first frame

    /// --scene terrain|characters. "characters" (the default when --model is
    /// given) walks a crowd of generated creatures, CesiumMan and every
    /// --model on the terrain, with the camera circling them.
    std::string scene = "terrain";
    bool sceneGiven = false;
    std::vector<std::string> models;    ///< --model FILE (repeatable): any .gltf or .glb
    uint32_t crowd = 6;                 ///< --crowd N: generated creatures (0: only the --model files, no CesiumMan)
    float orbitDistance = 5.0f;         ///< --orbit-distance M: the characters scene's camera circle
    bool displacement = true;           ///< --no-displacement draws the bare interpolated cage
    bool terrain = true;                ///< --no-terrain: characters alone on the clear colour (crack tests, captures)
    backend::CharacterPath characterPath = backend::CharacterPath::TwoPass; ///< --character-path
    std::optional<float> characterLevel; ///< --character-level L; unset: from each character's size on screen

    /// --bench terrain (the Table 2 benchmark) or characters (two-pass vs
    /// single-pass, amplification, Table 1, compression error) instead of
    /// the flythrough.
    std::string bench;
    std::string benchOut;               ///< --out FILE (default: stdout)
    /// --out-dir DIR: where --bench writes one Chrome trace per backend
    /// (bench-<backend>.json). With --backend all they are written anyway:
    /// next to --out, else in the current directory.
    std::string benchOutDir;
};

/// Parses argv (without argv[0]).
Result<DemoOptions> parseDemoOptions(const std::vector<std::string>& args);

/// A number as a user writes it on the command line ("14.99", "20"), for
/// messages about flags.
std::string formatNumber(double value);

/// The --help text.
const char* helpText();

} // namespace tessera::demo
