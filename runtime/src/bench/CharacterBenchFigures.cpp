#include "bench/CharacterBenchFigures.h"

#include "tessera/tessellator/Tessellator.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace tessera::runtime {
namespace {

/// The non-negative number at `key` of `report`, truncated to a whole one;
/// none when it is missing or not such a number.
std::optional<uint64_t> countAt(const nlohmann::json& report, const char* key) {
    const auto it = report.find(key);
    if (it == report.end() || !it->is_number()) return std::nullopt;
    if (it->is_number_unsigned()) return it->get<uint64_t>();
    const double n = it->get<double>();
    if (!std::isfinite(n) || n < 0.0) return std::nullopt;
    return static_cast<uint64_t>(n);
}

/// The text at `key` of `report`; empty when it is missing or not text.
std::string textAt(const nlohmann::json& report, const char* key) {
    const auto it = report.find(key);
    return it != report.end() && it->is_string() ? it->get<std::string>() : std::string();
}

uint64_t imageBytes(const character::TextureImage& image) {
    return uint64_t(image.width) * image.height * image.bytesPerTexel();
}

} // namespace

uint64_t trianglesPerCageTriangle(float level) {
    tessellator::TessFactors factors;
    factors.outer = {level, level, level, level};
    factors.inner = {level, level};
    return tessellator::Tessellator::countTriangles(tessellator::Domain::Triangle,
                                                    tessellator::Partitioning::FractionalOdd, factors);
}

float paperAmplificationLevel(float maxLevel) {
    const double target = kPaperTessellatedTriangles / kPaperCageTriangles;
    float best = 1.0f;
    double bestError = 1e30;
    const int steps = static_cast<int>(std::lround(double(maxLevel) * 100.0));
    for (int i = 100; i <= steps; ++i) {
        const float level = float(i) / 100.0f;
        const double error = std::abs(std::log(double(trianglesPerCageTriangle(level)) / target));
        // <= keeps the highest level of a run of equal counts.
        if (error <= bestError) best = level, bestError = error;
    }
    return best;
}

std::optional<SculptReport> readSculptReport(const std::filesystem::path& assetFile) {
    std::filesystem::path path = assetFile;
    path.replace_extension(".json");
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    // Without exceptions: a report that is not JSON is no report.
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
    if (!json.is_object()) return std::nullopt;
    const auto triangles = countAt(json, "sculpt_triangles");
    const auto vertices = countAt(json, "sculpt_vertices");
    const auto dense = countAt(json, "dense_mesh_bytes");
    if (!triangles || !vertices || !dense) return std::nullopt;
    SculptReport report;
    report.file = path.filename().string();
    report.sculptTriangles = *triangles;
    report.sculptVertices = *vertices;
    report.denseMeshBytes = *dense;
    report.denseMeshFormula = textAt(json, "dense_mesh_formula");
    return report;
}

CharacterAssetFigures assetFigures(const CrowdAsset& crowdAsset, float sharedLevel, float paperLevel,
                                   float tableLevel) {
    const character::CharacterAsset& asset = crowdAsset.asset;
    CharacterAssetFigures f;
    f.name = std::filesystem::path(crowdAsset.file).filename().string();
    f.cageVertices = static_cast<uint32_t>(asset.cage.vertices.size());
    f.cageTriangles = asset.cage.triangleCount();
    f.trianglesPerCageTriangle = trianglesPerCageTriangle(sharedLevel);
    f.tessellatedTriangles = f.trianglesPerCageTriangle * f.cageTriangles;
    f.paperLevelTriangles = trianglesPerCageTriangle(paperLevel) * f.cageTriangles;

    f.cageBytes = f.cageVertices * kCageVertexBytes + f.cageTriangles * kTriangleIndexBytes;
    f.compressedCageBytes = f.cageVertices * kCompressedVertexBytes;
    if (asset.displacement && !asset.displacement->image.empty()) {
        f.displacementWidth = asset.displacement->image.width;
        f.displacementHeight = asset.displacement->image.height;
        f.displacementBytes = imageBytes(asset.displacement->image);
    }
    if (asset.normalMap) f.normalMapBytes = imageBytes(*asset.normalMap);
    f.denseTriangles = trianglesPerCageTriangle(tableLevel) * f.cageTriangles;
    // A closed triangle mesh has about half as many vertices as triangles
    // (Euler: V - E + F = 2 with E = 3F/2); each would carry the cage
    // vertex's attributes to be skinned the same way.
    f.denseVertices = f.denseTriangles / 2;
    f.denseBytes = f.denseVertices * kCageVertexBytes + f.denseTriangles * kTriangleIndexBytes;
    f.sculpt = readSculptReport(crowdAsset.file);

    f.error =
        character::measureAnimatedCompressionError(asset, crowdAsset.box, character::uvBounds(asset.cage.vertices));
    return f;
}

} // namespace tessera::runtime
