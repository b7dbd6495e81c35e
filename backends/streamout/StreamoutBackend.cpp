// streamout: the D3D10-style backend. Transform feedback, instancing,
// geometry-shader culling and LOD binning, and draw-auto
// (vkCmdDrawIndirectByteCountEXT), in front of the emulated tessellator.
#include "BasicTerrainBackend.h"
#include "tessera/backend/PluginApi.h"

namespace tessera::backends {
namespace {

class StreamoutBackend final : public BasicTerrainBackend {
public:
    backend::BackendCapabilities capabilities(const backend::DeviceFeatures* device) override {
        backend::BackendCapabilities caps;
        caps.name = "streamout";
        caps.description = "D3D10-style: transform feedback, geometry-shader culling, draw-auto, emulated tessellator";
        caps.tessellation = backend::TessellationPath::Emulated;
        caps.usesTransformFeedback = true;
        caps.usesGeometryShaders = true;
        caps.maxTessFactor = 14.99f;
        checkRequirements(device, caps);
        return caps;
    }
};

backend::Backend* create() { return new StreamoutBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"streamout", &tessera::backends::create, &tessera::backends::destroy});
}
