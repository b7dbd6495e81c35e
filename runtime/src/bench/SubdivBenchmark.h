#pragma once
/// @file SubdivBenchmark.h
/// `tessera-demo --bench subdiv`: the second paper's section 7 on our
/// shapes, per backend: GPU ms of the subdivision passes for the base
/// surface alone, displaced (approximate normals), displaced with the
/// screen-space level of detail, and displaced with the Weingarten term;
/// the ratios to the base surface (the paper: +46% and +53% for its two
/// displaced variants); triangles; tile memory against a dense mesh and
/// against texture-atlas maps of the same samples.

#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"

namespace tessera::runtime {

/// Draws every --model FILE.obj (the characters scene, no creatures, the
/// cages still) on each backend (--backend NAME, or all), at one fixed
/// level shared by every backend (min(--subdiv-level, 14.99), default
/// 14.99; backends that tessellate further also at --subdiv-level when it
/// is higher) and once adaptive (--subdiv-pixels), with no triangle budget.
/// Each row runs --warmup frames (default 3) then --frames (default 10)
/// and reports the median GPU ms of the subdivision passes. Writes JSON to
/// --out (default stdout), the table to stdout (stderr when the JSON goes
/// there) and a Chrome trace per backend (bench-subdiv-<backend>.json).
Status runSubdivBenchmark(const Options& options);

} // namespace tessera::runtime
