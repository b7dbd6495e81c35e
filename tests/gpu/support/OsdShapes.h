#pragma once
/// @file OsdShapes.h
/// Test support: OpenSubdiv's regression shapes in ../shared/testdata
/// (TESSERA_TESTDATA_DIR), every .obj sorted by name.

#include <algorithm>
#include <filesystem>
#include <vector>

namespace tessera::test {

inline std::vector<std::filesystem::path> osdShapeFiles() {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path dir = std::filesystem::path(TESSERA_TESTDATA_DIR) / "osd_shapes";
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".obj") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace tessera::test
