// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// Breaks no rule: the GPU tests drive the Vulkan layer and backends/common.
#include "GpuTerrain.h"
#include "tessera/gpu/Device.h"

#include <vulkan/vulkan.h>
