#pragma once
/// @file FuzzInputFile.h
/// The loaders take paths (a glTF names its neighbours relative to itself),
/// so each input is written to one scratch file per process, reused.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace tessera::fuzz {

/// Writes `data` to this process's scratch file with `extension` and returns its path.
inline std::filesystem::path writeInput(const uint8_t* data, size_t size, const std::string& extension) {
    static const std::filesystem::path dir = std::filesystem::temp_directory_path();
    const std::filesystem::path path = dir / ("tessera-fuzz-" + std::to_string(getpid()) + extension);
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                  static_cast<std::streamsize>(size));
    return path;
}

} // namespace tessera::fuzz
