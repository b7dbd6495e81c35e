#pragma once
/// @file ObjShapeTestFiles.h
/// The OpenSubdiv regression shapes the .obj reader tests read, and an
/// independent count of what each file holds (line by line, without the
/// reader's code), to check the reader against.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::test {

inline std::filesystem::path osdShapesDir() {
    return std::filesystem::path(TESSERA_TESTDATA_DIR) / "osd_shapes";
}

/// Every .obj in osd_shapes, sorted by name.
inline std::vector<std::filesystem::path> osdShapeFiles() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(osdShapesDir()))
        if (entry.path().extension() == ".obj") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

inline std::string readObjText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// What a file declares, counted from its lines.
struct ObjLineCounts {
    size_t vertices = 0, uvs = 0, faces = 0, faceCorners = 0;
    size_t facesWithUvs = 0;
    std::map<size_t, size_t> faceSizes; ///< vertices per face -> faces
    size_t creaseEdges = 0, corners = 0;
    std::vector<uint32_t> holes;
    std::optional<int> interpolateBoundary;
    std::vector<std::string> smoothTriangles; ///< the tag's strings, once per tag
};

inline ObjLineCounts countObjLines(const std::string& text) {
    ObjLineCounts counts;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "v")
            ++counts.vertices;
        else if (keyword == "vt")
            ++counts.uvs;
        else if (keyword == "f") {
            ++counts.faces;
            size_t size = 0;
            bool uvs = false;
            for (std::string corner; words >> corner; ++size) {
                const size_t slash = corner.find('/');
                uvs = slash != std::string::npos && slash + 1 < corner.size() && corner[slash + 1] != '/';
            }
            counts.faceCorners += size;
            ++counts.faceSizes[size];
            counts.facesWithUvs += uvs ? 1 : 0;
        } else if (keyword == "t") {
            std::string name, declared;
            words >> name >> declared;
            int ints = 0, floats = 0, strings = 0;
            char slash = 0;
            std::istringstream(declared) >> ints >> slash >> floats >> slash >> strings;
            std::vector<long> intValues(size_t(std::max(ints, 0)));
            for (long& value : intValues) words >> value;
            for (int i = 0; i < floats; ++i) {
                float ignored = 0;
                words >> ignored;
            }
            if (name == "crease") counts.creaseEdges += intValues.size() / 2;
            if (name == "corner") counts.corners += intValues.size();
            if (name == "hole")
                for (long face : intValues) counts.holes.push_back(uint32_t(face));
            if (name == "interpolateboundary") counts.interpolateBoundary = int(intValues.at(0));
            if (name == "smoothtriangles") {
                std::string value;
                words >> value;
                counts.smoothTriangles.push_back(value);
            }
        }
    }
    return counts;
}

} // namespace tessera::test
