#pragma once
/// @file Outputs.h
/// What a demo run writes at the end: screenshot, trace, benchmark and the
/// height-map copies, each with an error naming the file when it fails.

#include "tessera/runtime/Options.h"
#include "tessera/runtime/RenderSession.h"

#include <cstdint>
#include <vector>

namespace tessera::runtime {

/// Writes every output `options` asks for. `frames` counts the frames
/// rendered, warm-up included.
Status writeOutputs(const Options& options, RenderSession& session, const terrain::Terrain& terrain,
                    const std::vector<uint8_t>& pixels, uint32_t frames);

} // namespace tessera::runtime
