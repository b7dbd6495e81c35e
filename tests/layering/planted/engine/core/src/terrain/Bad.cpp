// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
#include "tessera/terrain/Terrain.h"

#include <vulkan/vulkan.h>
