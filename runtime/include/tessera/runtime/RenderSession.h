#pragma once
/// @file RenderSession.h
/// One backend on one device drawing one terrain into an offscreen target or
/// a window: what the flythrough and the benchmark share. The GPU side (the
/// Vulkan instance and device, the window's swapchain, the target, the frame
/// scheduler, RenderDoc) lives behind the session's private implementation,
/// so this header, like every runtime header, compiles without the Vulkan
/// headers; the runtime's own code reaches it through session/SessionGpu.h.

#include "tessera/runtime/CharacterAssets.h"
#include "tessera/runtime/Options.h"
#include "tessera/runtime/SubdivModels.h"
#include "tessera/backend/BackendCapabilities.h"
#include "tessera/backend/CrowdDesc.h"
#include "tessera/backend/FrameReport.h"
#include "tessera/lod/LodPolicy.h"
#include "tessera/scene/Camera.h"
#include "tessera/terrain/DrawnSurface.h"
#include "tessera/terrain/Terrain.h"

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace tessera::runtime {

class RenderSession {
public:
    /// Selects the backend and device from `options`, opens the target (and
    /// window with --window), initialises the backend and uploads `terrain`,
    /// which must outlive the session.
    static Result<std::unique_ptr<RenderSession>> create(const Options& options, terrain::Terrain& terrain);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    const backend::BackendCapabilities& capabilities() const;
    std::string deviceName() const;
    std::string driverName() const;
    uint32_t width() const;
    uint32_t height() const;
    /// Whether the session draws into a window (Options::window).
    bool windowed() const;

    /// The tessellation the options ask for, checked against this backend:
    /// the default mode, and a clear error for a mode or level it cannot draw.
    Result<terrain::TessellationSettings> resolveTessellation(const Options& options) const;
    /// Makes `ground` the terrain this backend draws with `settings` seen by
    /// `camera` on this session's viewport: its levels capped at its highest,
    /// the control mesh where it draws the mode untessellated (as drawTerrain
    /// does); the height field while the terrain is hidden. What characters
    /// stand on (terrain::DrawnSurface).
    void updateGround(terrain::DrawnSurface& ground, const scene::Camera& camera,
                      const terrain::TessellationSettings& settings) const;

    /// Uploads every asset of `assets` to the backend and binds the handles
    /// (destroyed with the session). An asset the backend cannot draw is an
    /// error naming its file.
    Status createCharacters(CharacterAssets& assets);
    /// Makes the instanced crowd on the backend (destroyed with the
    /// session); renderFrame draws it when given its frame. An error naming
    /// the backend when it cannot.
    Status createCrowd(const backend::CrowdDesc& desc);
    /// Uploads every surface of `models` (the .obj shapes, the Catmull-Clark
    /// characters) and binds the handles (destroyed with the session). An
    /// error naming the backend and the surface when the backend cannot draw it.
    Status createSubdivs(SubdivSource& models);
    /// The refined points of surface `handle` as the backend's last frame
    /// used them (blocking).
    Result<backend::SubdivPoints> readSubdivPoints(backend::SubdivHandle handle);
    /// The crowd's tiers as the backend binned them in the last frame
    /// (blocking).
    Result<backend::CrowdTiers> readCrowdTiers();
    /// The device's class, for the LOD budget's defaults (the null
    /// backend counts what a GPU would draw).
    lod::DeviceClass deviceClass() const;
    /// The largest character tessellation level the backend draws.
    float maxCharacterLevel() const { return capabilities().maxTessFactor; }

    /// Whether frames draw the terrain (--no-terrain leaves characters alone
    /// on the clear colour; craters still land on the height map).
    void setTerrainVisible(bool visible);
    /// How the next frames are shaded (Options::look at creation); the
    /// terrain benchmark switches it to measure both looks in one run.
    void setLook(backend::Look look);
    backend::Look look() const;

    /// Replaces the backend with backend `name` on the same device, window
    /// and target, without restarting: every GPU object of the old backend is
    /// destroyed and the terrain is uploaded again, as it is now, craters
    /// included. The caller uploads its characters, crowd and surfaces again
    /// (SceneRun::switchBackend does). On failure the old backend is restored
    /// and the error names the backend and the reason.
    /// With `terrain`, the session draws that terrain from now on (a world
    /// loaded anew, which must outlive the session).
    Status switchBackend(const Options& options, const std::string& name, terrain::Terrain* terrain = nullptr);
    /// Captures the next frame through RenderDoc when it was loaded
    /// (--renderdoc); otherwise an error saying why not.
    Status requestCapture();
    /// Whether a backend switched away from stays initialised (pipelines,
    /// its own resources; none of the scene's) so that switching back costs
    /// only the scene's upload. On by default; off, every switch shuts the
    /// old backend down and initialises the new one from nothing.
    void setParkBackends(bool park);
    /// Counts the backends initialised in this session: a switch that
    /// changes it re-created the scene's GPU objects (even one that failed
    /// and restored the old backend).
    uint64_t generation() const;
    /// Device memory the session's device holds now (0 without a device).
    uint64_t deviceBytes() const;
    /// The most device memory the session's device has held (0 without a device).
    uint64_t peakDeviceBytes() const;
    /// Device allocations made so far (0 without a device): with
    /// Options::failAllocation, what the exhaustion tests count through.
    uint64_t deviceAllocations() const;
    /// Caps the device memory from now on (Options::deviceMemoryCap at
    /// creation); an allocation past it throws OutOfDeviceMemory. 0: no cap.
    void setDeviceMemoryCap(uint64_t bytes);
    /// The characters' shadows the next frames draw on the terrain
    /// (FrameInfo::shadowCasters, shadowRegion); `casters` must stay valid
    /// until renderFrame has been called.
    void setShadowCasters(std::span<const glm::vec4> casters, const glm::vec3& region);
    /// Handles window events; false once the window was closed.
    bool pollWindow();
    /// Records and submits one frame: pending craters into the GPU height
    /// map, culling, the terrain draw, then `characters`, `crowd` (the
    /// crowd createCrowd made) and `surfaces` when given. Reads the image
    /// back when `readback`.
    void renderFrame(uint32_t frameIndex, const scene::Camera& camera, const terrain::TessellationSettings& settings,
                     const glm::vec3& clearColor, bool wireframe, bool readback,
                     const backend::CharacterDrawInfo* characters = nullptr,
                     const backend::CrowdDrawInfo* crowd = nullptr, std::span<const SubdivDraw> surfaces = {});
    /// Waits for the GPU; the last read-back image (RGBA8), empty if none.
    std::vector<uint8_t> finish();
    /// The backend's own account of its last recorded frame (intermediate
    /// buffer bytes, patches, passes).
    backend::FrameReport lastFrameReport() const;
    /// Patches that survived culling in the last frame.
    uint32_t lastPatchCount() const;
    /// The GPU copy of the height map (blocking).
    Result<std::vector<uint16_t>> readHeights();
    /// The RenderDoc capture written by Options::renderdocFrame, once that
    /// frame has been rendered; empty otherwise.
    const std::filesystem::path& captureFile() const;

private:
    friend struct SessionGpu; // the runtime's own way to the GPU side (session/SessionGpu.h)
    struct Impl;

    explicit RenderSession(std::unique_ptr<Impl> impl);

    std::unique_ptr<Impl> mImpl;
};

} // namespace tessera::runtime
