#pragma once
// GltfError: the exception the loader's checks throw. It never leaves the
// library: loadCharacter catches it and returns Error{"file: message"}. The
// checks are deep and numerous; unwinding keeps each of them one line.

#include <stdexcept>
#include <string>

namespace tessera::assets {

class GltfError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Throws GltfError{"<pointer>: <problem>"} (pointer is a JSON pointer, "" for the file itself).
[[noreturn]] inline void raise(const std::string& pointer, const std::string& problem) {
    throw GltfError(pointer.empty() ? problem : pointer + ": " + problem);
}

} // namespace tessera::assets
