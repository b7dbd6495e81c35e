#pragma once
/// @file RenderSessionImpl.h
/// What a RenderSession holds, private to the runtime: the selected backend
/// with its instance and device, the window's swapchain, the offscreen
/// target, the frame scheduler, RenderDoc, and the scene's handles on the
/// backend. Games see only RenderSession.h, which includes none of it.

#include "tessera/runtime/RenderSession.h"

#include "session/SelectedBackend.h"
#include "tessera/core/ImageFile.h"
#include "tessera/gpu/FrameScheduler.h"
#include "tessera/gpu/RenderDoc.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/gpu/Swapchain.h"

#include <functional>
#include <map>
#include <optional>

namespace tessera::runtime {

class Reporter;

struct RenderSession::Impl {
    enum class Release { Shutdown, Park, Keep };
    struct ParkedBackend {
        backend::BackendPtr backend;
        backend::BackendCapabilities capabilities;
    };

    /// The window's swapchain (when `windowed`), the offscreen target and the
    /// frame scheduler on the selected device; none without one.
    Status openTarget(bool windowed);
    /// Initialises the selected backend on the device (unless it already is:
    /// a parked one) and uploads the terrain.
    Status initializeBackend(bool alreadyInitialized);
    /// Destroys every handle the backend holds; then shuts it down, parks it
    /// for a switch back (when setParkBackends allows) or keeps it selected.
    void releaseBackend(Release release);
    /// After a failed switch: `previous` (parked or made anew) draws on.
    void restoreBackend(const Options& options, const std::string& previous);
    /// The frame's description for the backend: the camera, size, look and
    /// the characters' shadows.
    backend::FrameInfo frameInfo(uint32_t frameIndex, const scene::Camera& camera, const glm::vec3& clearColor,
                                 bool wireframe) const;
    /// Ends a RenderDoc capture of the frame just submitted.
    void endCapture(uint32_t frameIndex);

    terrain::Terrain* terrain = nullptr;
    const Reporter* reporter = nullptr; ///< the options' (reporterFor)
    std::unique_ptr<SelectedBackend> selected;
    std::unique_ptr<gpu::Swapchain> swapchain;
    std::unique_ptr<gpu::RenderTarget> target;
    std::unique_ptr<gpu::FrameScheduler> scheduler;
    std::unique_ptr<gpu::RenderDoc> renderDoc; ///< with Options::renderdocFrame, when RenderDoc is there
    std::optional<uint32_t> captureFrame;
    std::filesystem::path captureFile;
    backend::TerrainHandle terrainHandle;
    std::vector<backend::CharacterHandle> characters;
    backend::CrowdHandle crowd;
    std::vector<backend::SubdivHandle> subdivs;
    bool terrainVisible = true;
    backend::Look look = backend::Look::Full;
    backend::TerrainShading terrainShading = backend::TerrainShading::Auto;
    backend::Shadows shadows = backend::Shadows::Auto;
    std::vector<scene::ShadowCascade> shadowCascades; ///< this frame's, fitted in renderFrame
    glm::vec3 sunDirection{0.4f, 0.8f, 0.3f};
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint32_t> visible;
    std::function<void(gpu::FrameContext&)> overlay;
    uint32_t frameIndex = 0;
    std::vector<Rgba8Image> detailTextures; ///< the terrain's, uploaded by each backend
    std::span<const glm::vec4> shadowCasters;
    glm::vec3 shadowRegion{0.0f};
    uint64_t generation = 0;
    bool parkBackends = true;
    std::map<std::string, ParkedBackend> parked; ///< after `selected`: destroyed before the device
};

} // namespace tessera::runtime
