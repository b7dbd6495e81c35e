#pragma once
// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// Breaks no rule: backends use the GPU layer and Vulkan.
#include "tessera/gpu/Image.h"

#include <vulkan/vulkan.h>
