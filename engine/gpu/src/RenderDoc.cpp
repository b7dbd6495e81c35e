#include "tessera/gpu/RenderDoc.h"

#include "tessera/gpu/Instance.h"

#include <renderdoc_app.h>

#include <dlfcn.h>

#include <cstdlib>
#include <vector>

namespace tessera::gpu {

namespace {

// The version every RenderDoc since 1.1 serves; it has all we call.
const RENDERDOC_API_1_1_2& api(const void* table) { return *static_cast<const RENDERDOC_API_1_1_2*>(table); }

constexpr const char* kDefaultLibrary = "librenderdoc.so";

// RenderDoc identifies a Vulkan device by the instance's dispatch table
// pointer (RENDERDOC_DEVICEPOINTER_FROM_VKINSTANCE).
RENDERDOC_DevicePointer devicePointer(const Instance& instance) {
    return RENDERDOC_DEVICEPOINTER_FROM_VKINSTANCE(instance.handle());
}

} // namespace

Result<std::unique_ptr<RenderDoc>> RenderDoc::load(const std::filesystem::path& pathTemplate) {
    const char* overrideLibrary = std::getenv("TESSERA_RENDERDOC_LIBRARY");
    const std::string library = overrideLibrary && *overrideLibrary ? overrideLibrary : kDefaultLibrary;
    // Already loaded when the program was launched from RenderDoc's UI.
    void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_NOLOAD);
    if (!handle) handle = dlopen(library.c_str(), RTLD_NOW);
    if (!handle) {
        const char* why = dlerror();
        return fail("RenderDoc is not available: ", library, " could not be loaded (", why ? why : "not found",
                    "); install Debian's renderdoc package, or launch the program from RenderDoc");
    }
    auto getApi = reinterpret_cast<pRENDERDOC_GetAPI>(dlsym(handle, "RENDERDOC_GetAPI"));
    void* table = nullptr;
    if (!getApi || getApi(eRENDERDOC_API_Version_1_1_2, &table) != 1 || !table) {
        dlclose(handle);
        return fail("RenderDoc is not available: ", library,
                    " has no RENDERDOC_GetAPI for API 1.1.2 (is it RenderDoc's library, version 1.1 or later?)");
    }
    std::unique_ptr<RenderDoc> renderDoc(new RenderDoc());
    renderDoc->mLibrary = handle;
    renderDoc->mApi = table;
    // The layer joins only instances created after this (its manifest's
    // enable_environment); overwrite so a stale 0 does not win.
    setenv("ENABLE_VULKAN_RENDERDOC_CAPTURE", "1", 1);
    api(table).SetCaptureFilePathTemplate(pathTemplate.string().c_str());
    // The overlay would be drawn into a presented window's frames; captures
    // and screenshots should show the scene alone.
    api(table).MaskOverlayBits(eRENDERDOC_Overlay_None, eRENDERDOC_Overlay_None);
    return renderDoc;
}

RenderDoc::~RenderDoc() {
    // RenderDoc does not support being unloaded while its layer may still be
    // in use by the loader; the handle is left open on purpose.
}

void RenderDoc::disableLayer() { setenv("ENABLE_VULKAN_RENDERDOC_CAPTURE", "0", 1); }

std::string RenderDoc::version() const {
    int major = 0, minor = 0, patch = 0;
    api(mApi).GetAPIVersion(&major, &minor, &patch);
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

void RenderDoc::begin(const Instance& instance) { api(mApi).StartFrameCapture(devicePointer(instance), nullptr); }

Result<std::filesystem::path> RenderDoc::end(const Instance& instance) {
    const uint32_t before = api(mApi).GetNumCaptures();
    if (api(mApi).EndFrameCapture(devicePointer(instance), nullptr) != 1 || api(mApi).GetNumCaptures() == before)
        return fail("RenderDoc wrote no capture (its Vulkan layer was not active on this instance; was "
                    "VK_LOADER_LAYERS_DISABLE or DISABLE_VULKAN_RENDERDOC_CAPTURE_1_24 set?)");
    uint32_t length = 0;
    api(mApi).GetCapture(api(mApi).GetNumCaptures() - 1, nullptr, &length, nullptr);
    std::vector<char> file(length + 1, '\0');
    api(mApi).GetCapture(api(mApi).GetNumCaptures() - 1, file.data(), &length, nullptr);
    return std::filesystem::path(file.data());
}

} // namespace tessera::gpu
