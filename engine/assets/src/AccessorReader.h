#pragma once
// AccessorReader: the elements of a glTF accessor as numbers, with strides,
// matrix column padding, normalized integers and sparse substitution handled,
// every byte range checked against the data actually present.

#include "GltfTinyGltf.h"

#include <string>
#include <vector>

namespace tessera::assets {

class AccessorReader {
public:
    explicit AccessorReader(const tinygltf::Model& model) : mModel(model) {}

    /// count * components values. Normalized integer accessors are mapped to
    /// [0, 1] / [-1, 1] when `normalize`; otherwise the raw component values.
    /// Throws GltfError naming the accessor when its bytes are not all present.
    std::vector<double> read(int accessor, bool normalize = true) const;
    /// The same as floats, for conversion.
    std::vector<float> readFloats(int accessor) const;
    /// Components per element of an accessor.
    uint32_t components(int accessor) const;

private:
    const tinygltf::Model& mModel;
};

} // namespace tessera::assets
