// The OpenSubdiv .obj reader (vertices, faces, crease, corner and hole
// tags) on arbitrary text, and, when it reads, the topology checks that
// stand between it and OpenSubdiv.
#include "tessera/subdiv/ObjShape.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto shape = tessera::subdiv::parseObjShape(text, "fuzz.obj");
    (void)shape;
    return 0;
}
