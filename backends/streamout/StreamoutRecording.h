#pragma once
/// @file StreamoutRecording.h
/// The attachment-less rendering scope streamout's transform-feedback
/// passes need (barriers and descriptor writes: CommandHelpers.h).

#include "CommandHelpers.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tessera::backends::streamout {

/// Opens rendering with no attachments and sets a 1x1 viewport: transform
/// feedback only exists inside rendering, and these passes rasterise nothing.
void beginStreamOut(VkCommandBuffer cmd);
void endStreamOut(VkCommandBuffer cmd);

} // namespace tessera::backends::streamout
