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
#include "tessera/scene/Camera.h"
#include "tessera/terrain/Terrain.h"

#include <filesystem>
#include <memory>
#include <optional>
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

    terrain::Terrain* mTerrain = nullptr;
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
    glm::vec3 mSunDirection{0.4f, 0.8f, 0.3f};
    uint32_t mWidth = 0;
    uint32_t mHeight = 0;
    std::vector<uint32_t> mVisible;
};

} // namespace tessera::runtime
