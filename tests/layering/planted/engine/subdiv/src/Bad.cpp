// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// The subdivision library knows nothing of the host above it.
#include "tessera/runtime/Options.h"
#include "tessera/scene/Aabb.h"
