#pragma once
/// @file BackendCapabilities.h
/// What a backend uses and what it can do, for `--list-backends` and for the
/// check that refuses to start a backend on a device that cannot run it.
///
/// Unlike bgfx, Tessera does not require every feature everywhere: a D3D9-style
/// backend has no tessellation stages by design. Capabilities differ per
/// backend, and the host reports them instead of hiding them.

#include "tessera/terrain/TessellationSettings.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::backend {

/// How a backend produces tessellated geometry.
enum class TessellationPath {
    None,     ///< draws control meshes only
    Emulated, ///< fixed-function tessellator emulated in vertex processing (levels 1..14.99)
    Hardware, ///< Vulkan tessellation control and evaluation stages (levels up to 64)
};

const char* toString(TessellationPath path);

struct BackendCapabilities {
    std::string name;          ///< the name given to --backend
    std::string description;   ///< one line for --list-backends
    bool requiresGpu = true;   ///< false only for the null backend
    TessellationPath tessellation = TessellationPath::None;
    bool usesTransformFeedback = false;
    bool usesGeometryShaders = false;
    bool usesCompute = false;
    bool usesMeshShaders = false; ///< task and mesh stages (VK_EXT_mesh_shader)
    float maxTessFactor = 1.0f;
    /// Draws instanced crowds with GPU culling and LOD binning (createCrowd);
    /// hosts draw crowds through drawCharacters where it does not.
    bool crowd = false;
    /// Draws Catmull-Clark surfaces with analytic displacement (createSubdiv).
    bool subdiv = false;
    /// Bit (1 << TerrainMode) for each terrain mode the backend draws.
    uint32_t terrainModes = 1u << uint32_t(terrain::TerrainMode::LowRes);
    /// Empty when the backend can run on the device it was asked about;
    /// otherwise one entry per missing feature, in plain words.
    std::vector<std::string> missing;

    bool supported() const { return missing.empty(); }
    bool drawsTerrainMode(terrain::TerrainMode mode) const { return (terrainModes >> uint32_t(mode)) & 1u; }
};

} // namespace tessera::backend
