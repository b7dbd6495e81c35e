// hulldomain: the D3D11-style backend. Tessellation control and evaluation
// shaders (factors up to 64) and compute.
#include "BasicTerrainBackend.h"
#include "tessera/backend/PluginApi.h"

namespace tessera::backends {
namespace {

class HulldomainBackend final : public BasicTerrainBackend {
public:
    backend::BackendCapabilities capabilities(const backend::DeviceFeatures* device) override {
        backend::BackendCapabilities caps;
        caps.name = "hulldomain";
        caps.description = "D3D11-style: tessellation control/evaluation shaders and compute";
        caps.tessellation = backend::TessellationPath::Hardware;
        caps.usesCompute = true;
        caps.maxTessFactor = 64.0f;
        checkRequirements(device, caps);
        return caps;
    }
};

backend::Backend* create() { return new HulldomainBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"hulldomain", &tessera::backends::create, &tessera::backends::destroy});
}
