#pragma once
/// @file RenderSession.h
/// One backend on one device drawing one terrain into an offscreen target or
/// a window: what the flythrough and the benchmark share.

#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/CharacterAssets.h"
#include "tessera/runtime/Options.h"
#include "tessera/runtime/SubdivModels.h"
#include "tessera/lod/LodPolicy.h"
#include "tessera/gpu/FrameScheduler.h"
#include "tessera/gpu/RenderDoc.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/gpu/Swapchain.h"
#include "tessera/core/ImageFile.h"
#include "tessera/scene/Camera.h"
#include "tessera/terrain/Terrain.h"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tessera::runtime {

class Reporter;

class RenderSession {
public:
    /// Selects the backend and device from `options`, opens the target (and
    /// window with --window), initialises the backend and uploads `terrain`,
    /// which must outlive the session.
    static Result<std::unique_ptr<RenderSession>> create(const Options& options, terrain::Terrain& terrain);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    const backend::BackendCapabilities& capabilities() const { return mSelected->capabilities; }
    std::string deviceName() const;
    std::string driverName() const;
    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }
    bool windowed() const { return mSwapchain != nullptr; }

    /// The tessellation the options ask for, checked against this backend:
    /// the default mode, and a clear error for a mode or level it cannot draw.
    Result<terrain::TessellationSettings> resolveTessellation(const Options& options) const;

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
    void setTerrainVisible(bool visible) { mTerrainVisible = visible; }
    /// How the next frames are shaded (Options::look at creation); the
    /// terrain benchmark switches it to measure both looks in one run.
    void setLook(backend::Look look) { mLook = look; }
    backend::Look look() const { return mLook; }

    /// Replaces the backend with backend `name` on the same device, window
    /// and target, without restarting: every GPU object of the old backend is
    /// destroyed and the terrain is uploaded again, as it is now, craters
    /// included. The caller uploads its characters, crowd and surfaces again
    /// (SceneRun::switchBackend does). On failure the old backend is restored
    /// and the error names the backend and the reason.
    /// With `terrain`, the session draws that terrain from now on (a world
    /// loaded anew, which must outlive the session).
    Status switchBackend(const Options& options, const std::string& name, terrain::Terrain* terrain = nullptr);
    /// Called with each frame's context after the backend's passes and before
    /// presentation or readback: the window's overlay records itself here.
    void setOverlayRecorder(std::function<void(gpu::FrameContext&)> recorder) { mOverlay = std::move(recorder); }
    /// Captures the next frame through RenderDoc when it was loaded
    /// (--renderdoc); otherwise an error saying why not.
    Status requestCapture();
    /// The device frames render on (null for the null backend).
    gpu::Device* device() const { return mSelected->device.get(); }
    /// The window of a --window session; null headless.
    GLFWwindow* window() const { return mSwapchain ? mSwapchain->window() : nullptr; }
    /// Whether a backend switched away from stays initialised (pipelines,
    /// its own resources; none of the scene's) so that switching back costs
    /// only the scene's upload. On by default; off, every switch shuts the
    /// old backend down and initialises the new one from nothing.
    void setParkBackends(bool park) { mParkBackends = park; }
    /// Counts the backends initialised in this session: a switch that
    /// changes it re-created the scene's GPU objects (even one that failed
    /// and restored the old backend).
    uint64_t generation() const { return mGeneration; }
    /// Device memory the session's device holds now (0 without a device).
    uint64_t deviceBytes() const { return mSelected->device ? mSelected->device->allocatedBytes() : 0; }
    /// The most device memory the session's device has held (0 without a device).
    uint64_t peakDeviceBytes() const { return mSelected->device ? mSelected->device->peakAllocatedBytes() : 0; }
    /// Device allocations made so far (0 without a device): with
    /// Options::failAllocation, what the exhaustion tests count through.
    uint64_t deviceAllocations() const { return mSelected->device ? mSelected->device->allocationCount() : 0; }
    /// Caps the device memory from now on (Options::deviceMemoryCap at
    /// creation); an allocation past it throws OutOfDeviceMemory. 0: no cap.
    void setDeviceMemoryCap(uint64_t bytes) {
        if (mSelected->device) mSelected->device->setMemoryCap(bytes);
    }
    /// The characters' shadows the next frames draw on the terrain
    /// (FrameInfo::shadowCasters, shadowRegion); `casters` must stay valid
    /// until renderFrame has been called.
    void setShadowCasters(std::span<const glm::vec4> casters, const glm::vec3& region) {
        mShadowCasters = casters;
        mShadowRegion = region;
    }
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
    backend::FrameReport lastFrameReport() const { return mSelected->backend->lastFrameReport(); }
    /// Patches that survived culling in the last frame.
    uint32_t lastPatchCount() const { return static_cast<uint32_t>(mVisible.size()); }
    /// The GPU copy of the height map (blocking).
    Result<std::vector<uint16_t>> readHeights();
    /// The RenderDoc capture written by Options::renderdocFrame, once that
    /// frame has been rendered; empty otherwise.
    const std::filesystem::path& captureFile() const { return mCaptureFile; }

private:
    RenderSession() = default;
    /// Initialises the selected backend on the device (unless it already is:
    /// a parked one) and uploads the terrain.
    Status initializeBackend(bool alreadyInitialized);
    enum class Release { Shutdown, Park, Keep };
    /// Destroys every handle the backend holds; then shuts it down, parks it
    /// for a switch back (when setParkBackends allows) or keeps it selected.
    void releaseBackend(Release release);

    struct ParkedBackend {
        backend::BackendPtr backend;
        backend::BackendCapabilities capabilities;
    };

    terrain::Terrain* mTerrain = nullptr;
    const Reporter* mReporter = nullptr; ///< the options' (reporterFor)
    std::unique_ptr<SelectedBackend> mSelected;
    std::unique_ptr<gpu::Swapchain> mSwapchain;
    std::unique_ptr<gpu::RenderTarget> mTarget;
    std::unique_ptr<gpu::FrameScheduler> mScheduler;
    std::unique_ptr<gpu::RenderDoc> mRenderDoc; ///< with --renderdoc, when RenderDoc is there
    std::optional<uint32_t> mCaptureFrame;
    std::filesystem::path mCaptureFile;
    backend::TerrainHandle mTerrainHandle;
    std::vector<backend::CharacterHandle> mCharacters;
    backend::CrowdHandle mCrowd;
    std::vector<backend::SubdivHandle> mSubdivs;
    bool mTerrainVisible = true;
    backend::Look mLook = backend::Look::Full;
    backend::TerrainShading mTerrainShading = backend::TerrainShading::Auto;
    glm::vec3 mSunDirection{0.4f, 0.8f, 0.3f};
    uint32_t mWidth = 0;
    uint32_t mHeight = 0;
    std::vector<uint32_t> mVisible;
    std::function<void(gpu::FrameContext&)> mOverlay;
    uint32_t mFrameIndex = 0;
    std::vector<Rgba8Image> mDetailTextures; ///< the terrain's, uploaded by each backend
    std::span<const glm::vec4> mShadowCasters;
    glm::vec3 mShadowRegion{0.0f};
    uint64_t mGeneration = 0;
    bool mParkBackends = true;
    std::map<std::string, ParkedBackend> mParked; ///< after mSelected: destroyed before the device
};

} // namespace tessera::runtime
