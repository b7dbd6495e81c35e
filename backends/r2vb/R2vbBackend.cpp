// r2vb: the D3D9-style backend. Data goes round only through render targets
// read back as vertex streams (R2VB), with an emulated fixed-function
// tessellator in front of an evaluation vertex shader. It uses no compute,
// storage writes, geometry or tessellation stages.
#include "BasicTerrainBackend.h"
#include "tessera/backend/PluginApi.h"

namespace tessera::backends {
namespace {

class R2vbBackend final : public BasicTerrainBackend {
public:
    backend::BackendCapabilities capabilities(const backend::DeviceFeatures* device) override {
        backend::BackendCapabilities caps;
        caps.name = "r2vb";
        caps.description = "D3D9-style: render-to-vertex-buffer multipass, emulated tessellator";
        caps.tessellation = backend::TessellationPath::Emulated;
        caps.maxTessFactor = 14.99f;
        checkRequirements(device, caps);
        return caps;
    }
};

backend::Backend* create() { return new R2vbBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"r2vb", &tessera::backends::create, &tessera::backends::destroy});
}
