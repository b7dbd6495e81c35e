// String forms of the contract's enums, shared by the CLI, reports and logs.
#include "tessera/backend/BackendCapabilities.h"

namespace tessera::backend {

const char* toString(TessellationPath path) {
    switch (path) {
    case TessellationPath::None: return "none";
    case TessellationPath::Emulated: return "emulated";
    case TessellationPath::Hardware: return "hardware";
    }
    return "?";
}

} // namespace tessera::backend
