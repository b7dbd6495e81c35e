// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// It breaks no rule: the include below is commented out, and the scene's
// own headers are fine.
// #include <vulkan/vulkan.h>
#include "tessera/scene/SceneGraph.h"
