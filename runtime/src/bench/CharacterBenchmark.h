#pragma once
/// @file CharacterBenchmark.h
/// `tessera-demo --bench characters`: the first paper's character figures
/// (two-pass compressed against single-pass GPU time, amplification, Table 1,
/// compression error) for our crowd on each backend.

#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"

namespace tessera::runtime {

/// Loads the characters scene's crowd (--crowd generated creatures with
/// CesiumMan, and every --model), poses it at one fixed time and draws it from
/// one fixed camera (the orbit's start, or --camera) on the default device
/// (--device picks another) with each backend (--backend NAME, or all:
/// hulldomain, r2vb and streamout). Every backend draws every character at
/// the shared level, min(--character-level, 14.99), with the two-pass and
/// the single-pass path; a backend that tessellates further also draws at
/// --character-level (default 32). Each row runs --warmup frames (default 3) then --frames
/// (default 10) and reports the median GPU ms of its character passes.
/// Writes the JSON to --out (default stdout), a Chrome trace per backend
/// (bench-characters-<backend>.json; see --out-dir) and the tables to stdout
/// (stderr when the JSON goes to stdout). On lavapipe, levels above 14.99
/// run far slower than below (minutes a frame): pass --character-level 14.99.
Status runCharacterBenchmark(const Options& options);

} // namespace tessera::runtime
