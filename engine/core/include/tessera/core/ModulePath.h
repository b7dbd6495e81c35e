#pragma once
/// @file ModulePath.h
/// Where Tessera's own shared libraries are on disk, so that plugins and
/// content are found relative to the library that needs them, wherever the
/// game's executable lives (the build tree, an install prefix, a game's
/// own folder).

#include <filesystem>

namespace tessera {

/// The directory of the shared library (or executable) that contains
/// `address`, a function or object defined in it; empty if the loader
/// cannot say.
std::filesystem::path moduleDirectory(const void* address);

} // namespace tessera
