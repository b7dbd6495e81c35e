// String forms of the contract's enums, shared by the CLI, reports and logs.
#include "tessera/backend/BackendCapabilities.h"
#include "tessera/backend/CharacterDesc.h"

namespace tessera::backend {

const char* toString(TessellationPath path) {
    switch (path) {
    case TessellationPath::None: return "none";
    case TessellationPath::Emulated: return "emulated";
    case TessellationPath::Hardware: return "hardware";
    case TessellationPath::Mesh: return "mesh";
    }
    return "?";
}

const char* toString(CharacterPath path) {
    switch (path) {
    case CharacterPath::TwoPass: return "two-pass";
    case CharacterPath::SinglePass: return "single-pass";
    }
    return "?";
}

} // namespace tessera::backend
