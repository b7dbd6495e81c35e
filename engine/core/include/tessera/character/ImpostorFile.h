#pragma once
/// @file ImpostorFile.h
/// The `.impostor` file: an ImpostorAtlas as the content build writes it
/// beside a character's `.glb` (tools/impostor) and the runtime reads it.
///
/// Little-endian, no padding:
///
/// | bytes | field |
/// | --- | --- |
/// | 8 | magic `TSIMPOST` |
/// | 4 | version (kImpostorFileVersion) |
/// | 4 x 5 | TS_IMPOSTOR_VIEWS, CELL, PHASES, MIPS, BORDER it was baked with |
/// | 4 | size (texels a side of a layer at mip 0) |
/// | 4 | layers |
/// | 4 x 2 | centreY, radius (float) |
/// | | per mip m: every layer's albedo, then every layer's normal (ImpostorAtlas's bytes) |
/// | 8 | FNV-1a 64 of every byte before it |
///
/// A reader refuses a file baked with other constants (the draw would read
/// it with the wrong layout): the content build or a bake at load makes a
/// new one.

#include "tessera/character/ImpostorAtlas.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace tessera::character {

/// The layout version this build writes and reads.
inline constexpr uint32_t kImpostorFileVersion = 1;

/// The file's bytes. Asserts the atlas is complete (every image holds its
/// size's bytes).
std::vector<uint8_t> encodeImpostorAtlas(const ImpostorAtlas& atlas);

/// The atlas in `bytes`; every field, size and the checksum are checked
/// first, so truncated or corrupted input is an error naming `name` (the
/// file) and the problem, never a read out of range.
Result<ImpostorAtlas> decodeImpostorAtlas(std::span<const uint8_t> bytes, const std::string& name);

/// Writes `atlas` to `file`; an error naming it when it cannot.
Status writeImpostorFile(const std::filesystem::path& file, const ImpostorAtlas& atlas);

/// Reads `file` (decodeImpostorAtlas); an error naming it when it cannot.
Result<ImpostorAtlas> readImpostorFile(const std::filesystem::path& file);

} // namespace tessera::character
