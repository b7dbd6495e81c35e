#pragma once
/// @file CrowdChecks.h
/// The checks every backend runs on a crowd before it touches a device, so
/// that bad input gets the same message on every backend (bgfx's validation
/// catalogue): one line naming what is wrong.

#include "tessera/backend/CrowdDesc.h"
#include "tessera/core/Result.h"

namespace tessera::backend {

/// createCrowd's input: creatures (1 to TS_CROWD_MAX_CHARACTERS, each with a
/// far mesh whose bindings match and a complete impostor atlas with a layer
/// per phase of each of its baked clips), baked clips for every creature,
/// sizes.
Status checkCrowdDesc(const CrowdDesc& desc);

/// Whether one frame's instance may be drawn with a crowd of `characters`
/// creatures, `clips` baked clips and ids below `maxIds`: ids in range, its
/// sphere and scale finite. Backends skip the others rather than read out of
/// bounds (the GPU passes clamp the same way).
bool crowdInstanceValid(const shader::CrowdInstance& instance, uint32_t maxIds, uint32_t characters, uint32_t clips);

} // namespace tessera::backend
