// The height-map loader (PNG decode, bit depth and size checks) on
// arbitrary bytes.
#include "FuzzInputFile.h"

#include "tessera/terrain/HeightMapIO.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto path = tessera::fuzz::writeInput(data, size, ".png");
    auto field = tessera::terrain::loadHeightMapPng(path);
    (void)field;
    return 0;
}
