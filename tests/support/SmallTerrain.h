#pragma once
/// @file SmallTerrain.h
/// A 513 x 513 crop (2 km) of the middle of the build's content terrain, at
/// its spacing: the same kind of ground with a sixteenth of the cells, so a
/// scene on it loads (its crowd's fields above all) in a fraction of the
/// time. Shared by the render tests (through CrowdDemo.h) and the runtime
/// tests (SceneOptions.h).

#include "tessera/terrain/HeightMapIO.h"

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace tessera::test {

/// Writes `samples` (size x size) as a 16-bit height map PNG at `out`
/// through a per-process partial file and a rename, so tests running in
/// parallel never read half a file. Returns `out`, or "" with `error` set.
inline std::string writeHeightMapAtomically(const std::filesystem::path& out, uint32_t size,
                                            const std::vector<uint16_t>& samples, std::string& error) {
    std::filesystem::create_directories(out.parent_path());
    const std::filesystem::path partial = out.string() + "." + std::to_string(::getpid()) + ".partial";
    auto written = terrain::saveHeightMapPng16(partial, size, size, samples);
    if (!written.ok()) {
        error = written.error().message;
        return {};
    }
    std::error_code ec;
    std::filesystem::rename(partial, out, ec);
    if (ec) {
        error = "cannot rename " + partial.string() + ": " + ec.message();
        return {};
    }
    return out.string();
}


/// Writes the crop of `contentDir`/terrain/height.png into `outDir` once and
/// returns its path; empty, with `error` set, when it cannot. Tests run in
/// parallel: each writes its own partial file and renames it into place, so
/// a reader never sees half a file and two writers never mix their bytes.
inline std::string smallTerrainCrop(const std::filesystem::path& contentDir, const std::filesystem::path& outDir,
                                    std::string& error) {
    constexpr uint32_t kSize = 513;
    const std::filesystem::path out = outDir / "height_513.png";
    if (std::filesystem::exists(out)) return out.string();
    auto field = terrain::loadHeightMapPng(contentDir / "terrain" / "height.png");
    if (!field.ok()) {
        error = field.error().message;
        return {};
    }
    const terrain::HeightField& h = field.value();
    const uint32_t x0 = (h.width() - kSize) / 2, z0 = (h.height() - kSize) / 2;
    std::vector<uint16_t> samples;
    samples.reserve(size_t(kSize) * kSize);
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) samples.push_back(h.samples()[size_t(z0 + j) * h.width() + x0 + i]);
    return writeHeightMapAtomically(out, kSize, samples, error);
}

} // namespace tessera::test
