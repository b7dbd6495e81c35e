#pragma once
/// @file CageTiles.h
/// A character's displacement tiles on disk: the `.cctiles` file the
/// creature generator writes beside each `.glb` (content/characters/
/// froblin_<seed>.cctiles) so that the same creature can be drawn as a
/// Catmull-Clark surface with the second paper's tile displacement
/// (docs/SUBDIV.md, "The Froblin as a Catmull-Clark surface").
///
/// Why a sidecar file and not a glTF extension in the .glb: the .glb stays
/// byte-for-byte what the planar pipeline and the glTF validator check (a
/// private extension would have to be declared, and be ignored by every
/// other tool anyway); the tiles are read only when a Catmull-Clark surface
/// is asked for; and the file is versioned on its own, so a change of tile
/// layout never touches the glTF exporter. The price is that the two files
/// must stay together: the header records the cage it was baked for
/// (vertex and triangle counts of the .glb's cage, the welded control
/// vertex count and a hash of the welded topology) and the demo refuses a
/// file that does not match.
///
/// Layout (little-endian, no padding):
///
/// | offset | bytes | field |
/// | --- | --- | --- |
/// | 0 | 8 | magic "TSCCTILE" |
/// | 8 | 4 | version (kCageTilesVersion) |
/// | 12 | 4 | cage vertices (the .glb's, seam copies included) |
/// | 16 | 4 | cage triangles |
/// | 20 | 4 | control vertices (welded, TriangleCage.h) |
/// | 24 | 8 | topology hash (WeldedCage::topologyHash) |
/// | 32 | 4 | tile count T (ptex faces) |
/// | 36 | 4 | scale (float) |
/// | 40 | 4 | bias (float) |
/// | 44 | T | log2 size k of each tile (1 .. 12) |
/// | 44 + T | 2 * sum(4^k) | level-0 coefficients, uint16, tile after tile, row after row (DisplacementTiles::allCoefficients' layout): q / 65535 * scale + bias |
/// | end - 8 | 8 | FNV-1a 64 of every byte before it |
///
/// 16-bit coefficients, as the planar displacement map's 16-bit texels:
/// half the bytes of floats, and a step of scale / 65535 (about 1.5
/// micrometres on a Froblin) far below anything a tessellation shows.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace tessera::subdiv {

struct WeldedCage;

inline constexpr uint32_t kCageTilesVersion = 1;

/// The file's contents.
struct CageTiles {
    uint32_t cageVertices = 0;
    uint32_t cageTriangles = 0;
    uint32_t controlVertices = 0;
    uint64_t topologyHash = 0;
    std::vector<uint8_t> log2Sizes; ///< per tile (ptex face)
    float scale = 0.0f;             ///< coefficient = q / 65535 * scale + bias
    float bias = 0.0f;
    std::vector<uint16_t> quantized; ///< sum over tiles of 4^k

    /// The coefficients as floats (DisplacementTiles::assign's input).
    std::vector<float> coefficients() const;
    /// sum over tiles of 4^k: the coefficient count log2Sizes implies.
    uint64_t coefficientCount() const;
};

/// Quantizes `coefficients` (tile after tile, as log2Sizes lay them out) to
/// 16 bits over their range; the cage fields are left for the caller.
CageTiles quantizeCageTiles(std::span<const uint8_t> log2Sizes, std::span<const float> coefficients);

/// The file's bytes.
std::vector<uint8_t> encodeCageTiles(const CageTiles& tiles);
/// Parses and validates file bytes; `name` labels every error. Errors, one
/// line each: shorter than the header ("truncated"), wrong magic, another
/// version, no tiles, a tile size outside 1 .. 12, a non-finite or negative
/// scale or a non-finite bias, a size other than the header implies
/// (truncated, or bytes after the end), a checksum mismatch (corrupted).
Result<CageTiles> decodeCageTiles(std::span<const uint8_t> bytes, const std::string& name);

/// Writes the file; an error names it when it cannot be written.
Status writeCageTiles(const std::filesystem::path& file, const CageTiles& tiles);
/// Reads and decodes the file; a missing or unreadable file is an error
/// naming it.
Result<CageTiles> readCageTiles(const std::filesystem::path& file);

/// Whether `tiles` was baked for this cage: the .glb's cage vertex and
/// triangle counts, the welded control vertex count, the topology hash and
/// `tileCount` tiles (PtexTopology::tileCount). Errors name `name`, the
/// field, and both values.
Status checkCageTiles(const CageTiles& tiles, const WeldedCage& cage, uint32_t cageVertices, uint32_t tileCount,
                      const std::string& name);

} // namespace tessera::subdiv
