#pragma once
/// @file DisplacementBaker.h
/// Bakes a scalar displacement map and a tangent-space normal map from a
/// sculpt onto a cage, in the manner of AMD's GPUMeshMapper.

#include "creature/SculptMesh.h"
#include "tessera/character/CageMesh.h"
#include "tessera/character/CharacterAsset.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace tessera::creature {

/// How to bake.
struct BakeOptions {
    uint32_t resolution = 2048;  ///< square displacement map size, 1..2048
    /// Square normal map size, 1..2048; 0 means the displacement's resolution.
    uint32_t normalResolution = 0;
    /// Ray envelope along the cage normal, model-space units (both > 0): rays
    /// search from -inner to +outer around the cage surface and keep the
    /// sculpt hit nearest the cage.
    float outerEnvelope = 0.05f;
    float innerEnvelope = 0.05f;
    /// Texels of gutter dilated around every chart so bilinear and mip
    /// fetches never read empty texels.
    uint32_t gutter = 4;
    /// Worker threads for the ray casts; 0 = the hardware's count. The output
    /// is the same bytes for any count.
    uint32_t threads = 0;
};

/// What happened, for the tool's report and the tests.
struct BakeStats {
    uint64_t texelsCovered = 0;   ///< texels whose centre lies inside some cage triangle's UVs
    uint64_t texelsDilated = 0;   ///< texels outside every triangle that a border fetch reads (baked too)
    uint64_t misses = 0;          ///< baked texels (covered or dilated) whose ray found no sculpt
                                  ///< within the envelope; filled from neighbouring hits
    /// Misses by cage triangle (one entry per triangle): where the envelope
    /// is too tight or the sculpt strays from the cage.
    std::vector<uint32_t> missesPerTriangle;
    uint64_t seamEdges = 0;       ///< cage edges whose two sides lie in different UV places
    uint64_t seamVertices = 0;    ///< extra (vertex, chart) pairs at seam vertices
    uint64_t seamTexelsFixed = 0; ///< texels rewritten so both sides of a seam agree
    /// Largest difference, model-space units, between the two sides' fetches
    /// along any seam, sampling the quantised 16-bit map bilinearly as the
    /// shader does: without and with the seam fix.
    float seamMismatchBefore = 0.0f;
    float seamMismatchAfter = 0.0f;
    float minDisplacement = 0.0f; ///< model-space units, the final map's range (= bias)
    float maxDisplacement = 0.0f; ///< (= bias + scale)
};

/// The baked maps.
///
/// Displacement: a texel's value is `sample * scale + bias` model-space
/// units (sample = R16 / 65535) along the normalised interpolated cage
/// normal; bias = minDisplacement and scale = maxDisplacement -
/// minDisplacement exactly (scale = 0 and every sample 0 for a constant map).
///
/// Normal map frame (the displacement's own frame, as the paper requires):
/// at the texel's cage point, N = normalise(sum b_i * normal_i),
/// T = sum b_i * tangent_i.xyz made orthogonal to N and normalised,
/// B = sign(sum b_i * tangent_i.w) * cross(N, T). The stored vector is the
/// sculpt's smooth normal (area-weighted vertex normals, interpolated at the
/// hit) as (dot(n, T), dot(n, B), dot(n, N)) * 0.5 + 0.5 in RGB, A = 255.
struct BakeResult {
    character::DisplacementMap displacement;  ///< R16, with exact scale and bias
    character::TextureImage normalMap;        ///< Rgba8, tangent space of the cage
    BakeStats stats;
};

/// Progress callback: fraction done in [0, 1], called on the calling thread.
using BakeProgressFn = std::function<void(float fraction)>;

/// Bakes `sculpt` onto `cage` (bind pose). The cage surface is the paper's
/// interpolating planar subdivision: positions interpolate linearly over each
/// triangle and the displacement direction is the normalised interpolated
/// vertex normal, exactly what the renderers evaluate.
///
/// Steps: one ray per texel whose centre lies in a triangle's UVs; texels
/// just outside the charts that a bilinear fetch on a chart border reads
/// are baked too (extrapolated linearly from inside the nearest triangle);
/// misses are filled from neighbouring hits; UV seams are reconciled so both
/// sides fetch the same value (least squares over the texels under the
/// seam); charts get `gutter` texels of padding and the rest of the map the
/// charts' mean; then 16-bit quantisation. The output is the same bytes for
/// any thread count. Fails, with a one-line message, on a resolution
/// outside 1..2048, a non-positive or non-finite envelope, a cage without
/// UVs, with UVs outside [0, 1] (tiled textures cannot hold a unique bake)
/// or with bad indices, or an empty sculpt.
Result<BakeResult> bakeDisplacement(const character::CageMesh& cage, const SculptMesh& sculpt,
                                    const BakeOptions& options, const BakeProgressFn& progress = {});

} // namespace tessera::creature
