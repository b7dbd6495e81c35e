// The glTF loader (validators, tinygltf, Draco, accessors, skins, clips) on
// arbitrary bytes: a binary container when the input starts with the GLB
// magic, else JSON. It must return a value or an error, never crash, leak
// or hang.
#include "FuzzInputFile.h"

#include "tessera/assets/GltfLoader.h"

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const auto path = tessera::fuzz::writeInput(data, size, glb ? ".glb" : ".gltf");
    auto loaded = tessera::assets::loadCharacter(path);
    (void)loaded;
    return 0;
}
