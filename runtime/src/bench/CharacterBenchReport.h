#pragma once
/// @file CharacterBenchReport.h
/// The figures of `--bench characters` (the first paper's character
/// sections: two-pass against single-pass GPU time, amplification, Table 1
/// and the compressed vertex's error) and their JSON and table.

#include "tessera/character/CompressionError.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tessera::runtime {

/// One backend drawing the posed crowd with one path at one level.
struct CharacterBenchRow {
    std::string backend;
    std::string device;
    std::string driver;
    std::string path;    ///< "two-pass" | "single-pass"
    double level = 0.0;  ///< every character's tessellation level
    uint32_t frames = 0; ///< measured frames
    /// Per frame, the sum of the path's character passes ("character.skin" +
    /// "character.tessellate", or "character.singlePass"); median, min, max.
    double characterMsMedian = 0.0, characterMsMin = 0.0, characterMsMax = 0.0;
    /// Median of every GPU pass of the frame summed (terrain included).
    double gpuFrameMsMedian = 0.0;
    /// Median GPU ms of each pass, in first-recorded order.
    std::vector<std::pair<std::string, double>> passes;
    /// backend::FrameReport of the last frame.
    uint32_t charactersDrawn = 0;
    uint64_t cageTriangles = 0;
    uint64_t triangles = 0;
    uint64_t intermediateBytes = 0;
    /// Primitives reaching the clipper in the drawing pass of the last
    /// measured frame (pipeline statistics; 0 where the device has none).
    uint64_t clippingInvocations = 0;
    std::string trace; ///< the Chrome trace holding the row's frames, or ""
};

/// The sculpt-based Table 1 figure the creature generator wrote beside a
/// generated asset (content/characters/froblin_<seed>.json).
struct SculptReport {
    std::string file;
    uint64_t sculptTriangles = 0;
    uint64_t sculptVertices = 0;
    uint64_t denseMeshBytes = 0;
    std::string denseMeshFormula;
};

/// What one asset of the crowd costs and loses (no GPU involved).
struct CharacterAssetFigures {
    std::string name; ///< file name without directories
    uint32_t cageVertices = 0;
    uint32_t cageTriangles = 0;
    /// Triangles one cage triangle becomes at the shared level, and the
    /// whole character's tessellated triangles there.
    uint64_t trianglesPerCageTriangle = 0;
    uint64_t tessellatedTriangles = 0;
    /// The same at the level closest to the paper's amplification.
    uint64_t paperLevelTriangles = 0;

    /// Table 1 at the benchmark's highest level (CharacterBenchSummary::tableLevel).
    uint64_t cageBytes = 0;           ///< bind-pose vertices (80 B each) + 32-bit indices
    uint64_t compressedCageBytes = 0; ///< the animated cage, 16 B per vertex per instance
    uint32_t displacementWidth = 0, displacementHeight = 0;
    uint64_t displacementBytes = 0; ///< 16-bit texels, one level (no mips are made)
    uint64_t normalMapBytes = 0;    ///< RGBA8 texels, one level
    uint64_t denseTriangles = 0;    ///< = tessellated triangles at the table level
    uint64_t denseVertices = 0;     ///< triangles / 2, as on a closed mesh
    uint64_t denseBytes = 0;        ///< dense vertices * 80 B + triangles * 12 B
    std::optional<SculptReport> sculpt;

    character::CompressionErrorStats error; ///< over every clip (measureAnimatedCompressionError)
};

struct CharacterBenchSummary {
    uint32_t width = 0, height = 0;
    uint32_t warmupFrames = 0, frames = 0;
    uint32_t crowdMembers = 0;            ///< characters drawn per frame
    double poseSeconds = 0.0;             ///< the animation time every frame is posed at
    double sharedLevel = 0.0;             ///< the level every backend draws
    double tableLevel = 0.0;              ///< the highest level drawn: Table 1's dense mesh
    double paperLevel = 0.0;              ///< the level whose amplification is closest to the paper's
    double paperLevelAmplification = 0.0; ///< triangles per cage triangle there
    std::vector<CharacterBenchRow> rows;
    std::vector<CharacterAssetFigures> assets;
    std::vector<std::string> notes;
};

/// The paper's figures the benchmark sets ours against.
inline constexpr double kPaperCageTriangles = 5200.0;
inline constexpr double kPaperTessellatedTriangles = 1.6e6;
inline constexpr double kPaperTable1CageBytes = 100.0 * 1000.0 + 10.0 * 1000.0 * 1000.0;
inline constexpr double kPaperTable1DenseBytes = 450.0 * 1000.0 * 1000.0;
/// Bytes of one bind-pose cage vertex as the GPU reads it (CharacterVertex)
/// and of one animated, compressed vertex (CompressedVertex.h).
inline constexpr uint64_t kCageVertexBytes = 80;
inline constexpr uint64_t kCompressedVertexBytes = 16;
inline constexpr uint64_t kTriangleIndexBytes = 12;

/// A JSON object: "format": "tessera-bench-characters", "version": 1, the run's
/// settings, "timing" (one object per row, with two_pass_over_single_pass
/// fields on two-pass rows that have a single-pass partner), "amplification",
/// "table1" and "compression_error" (one object per asset) and "notes".
std::string characterBenchJson(const CharacterBenchSummary& summary);

/// The same figures as readable tables, backends side by side.
std::string characterBenchTable(const CharacterBenchSummary& summary);

/// The single-pass row of the same backend, device and level as `twoPass`, or null.
const CharacterBenchRow* singlePassPartner(const std::vector<CharacterBenchRow>& rows,
                                           const CharacterBenchRow& twoPass);

} // namespace tessera::runtime
