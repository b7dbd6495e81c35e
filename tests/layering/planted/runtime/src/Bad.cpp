// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// The runtime may use the GPU layer, but not Vulkan's own header.
#include "tessera/gpu/Device.h"
#include <vulkan/vulkan.h>
// The runtime does not link the command-line library: a game fills its
// options from its own code.
#include "tessera/cli/CommandLine.h"
