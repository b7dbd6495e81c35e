#pragma once
// DracoDecoder: KHR_draco_mesh_compression primitives decoded in place. Each
// compressed primitive gets new buffers holding uint32 indices and float
// attributes (normalized integers already mapped by Draco), and its accessors
// point at them. Done here rather than by tinygltf's TINYGLTF_ENABLE_DRACO
// path, which dereferences a null attribute for an unknown Draco id, ignores
// decode failures and sets strides from Draco's storage type rather than the
// type it writes.

#include "GltfTinyGltf.h"

namespace tessera::assets {

/// Throws GltfError naming the primitive when its Draco data is invalid.
void decodeDracoPrimitives(tinygltf::Model& model);

} // namespace tessera::assets
