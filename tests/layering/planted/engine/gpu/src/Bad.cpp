// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// The GPU layer stands on the core alone: not on the glTF loader.
#include "tessera/assets/GltfLoader.h"
#include "tessera/core/Result.h"
