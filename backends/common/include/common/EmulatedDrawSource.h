#pragma once
/// @file EmulatedDrawSource.h
/// What a backend's factor passes hand the emulated tessellator's draw
/// (EmulatedTerrainBackend for terrain, EmulatedSubdivPass for subdivision
/// domains): one record per superprimitive (its levels) and five
/// tessellator commands per record (indirect draws of pattern pieces,
/// TessPattern.h).
///
/// Contract for the buffers:
///  - records: an RGBA32F texel buffer of 2 * capacity texels. Texel r holds
///    record r's four outer levels (Vulkan quad order, clamped to the draw's
///    range), texel capacity + r holds (inner u, inner v, float(patch index), 0).
///  - commands: 5 * capacity VkDrawIndirectCommand (16 bytes each), in any
///    order; command c of record r is tsEmuCommand(outer, inner, c, r) from
///    emulated_tess.glsl (firstInstance = r * 5 + c). Unused commands must be
///    all zero (they draw nothing).
///  - commandCount: how many commands from the start of `commands` the draw
///    issues; 0 means all 5 * capacity. A backend whose commands are record
///    by record and that knows an upper bound on the records it wrote
///    (streamout: the visible patches) passes that bound, so the draw does
///    not walk a whole terrain's worth of empty commands.

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tessera::backends {

struct EmulatedDrawSource {
    VkBufferView records = VK_NULL_HANDLE;
    uint32_t capacity = 0;
    VkBuffer commands = VK_NULL_HANDLE;
    VkDeviceSize commandsOffset = 0;
    uint32_t commandCount = 0;
};

} // namespace tessera::backends
