#pragma once
/// @file CrowdRenderBenchmark.h
/// `tessera-demo --bench crowd` (`./tessera bench crowd`): the instanced
/// crowd's cost per crowd size and backend, against the terrain alone.

#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"

namespace tessera::runtime {

/// For each --agents size (default 1000, 10000, 65000) and each backend
/// (--backend all: hulldomain, r2vb, streamout; a name; else the device's
/// best), the crowd scene (the simulated crowd drawn instanced, culled and
/// binned on the GPU) from one fixed camera over the crowd (the crowd
/// scene's orbit view of the first size), and the terrain alone from the
/// same camera: --warmup frames (default 10), then --frames measured frames
/// (default 30), at 1920x1080 unless --width or --height is given. Writes
/// the JSON to --out or stdout, the table to stdout (stderr when the JSON
/// goes to stdout), and a Chrome trace per row (--out-dir, or with
/// --backend all next to --out).
Status runCrowdRenderBenchmark(const Options& options);

} // namespace tessera::runtime
