// String forms of the contract's enums, shared by the CLI, reports and logs.
#include "tessera/backend/BackendCapabilities.h"
#include "tessera/backend/TerrainDesc.h"

namespace tessera::backend {

const char* toString(TessellationPath path) {
    switch (path) {
    case TessellationPath::None: return "none";
    case TessellationPath::Emulated: return "emulated";
    case TessellationPath::Hardware: return "hardware";
    }
    return "?";
}

const char* toString(TerrainMode mode) {
    switch (mode) {
    case TerrainMode::LowRes: return "lowres";
    case TerrainMode::Continuous: return "continuous";
    case TerrainMode::Adaptive: return "adaptive";
    }
    return "?";
}

} // namespace tessera::backend
