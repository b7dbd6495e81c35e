#pragma once
/// @file BfrReference.h
/// The CPU reference a SubdivSurface's patches are checked against:
/// OpenSubdiv's Bfr (base face representation) evaluating each base face
/// on its own, over the surface's own TopologyRefiner, at the same
/// approximation levels as the surface's adaptive refinement.

#include "tessera/subdiv/LimitPoint.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include <glm/glm.hpp>

namespace tessera::subdiv {

class SubdivSurface;

/// Bfr evaluation of a SubdivSurface's base faces, in each face's own
/// parameterization (FaceParameterization explains its relation to Far's
/// ptex faces), with the surface's current base positions.
///
/// Bfr approximates irregular regions with Gregory patches after
/// SubdivSettings::smoothIsolationLevel (smooth features) and
/// isolationLevel (sharp features) levels, as the surface's Gregory end
/// caps do, so the two agree to round-off; with B-spline end caps they
/// differ near extraordinary vertices by the end caps' approximation.
///
/// Reads the surface's state (its refiner and current base positions): keep
/// the surface alive while this exists (moving the surface is fine). Not
/// thread-safe (Bfr's factory caches patches).
class BfrReference {
public:
    explicit BfrReference(const SubdivSurface& surface);
    BfrReference(BfrReference&&) noexcept;
    BfrReference& operator=(BfrReference&&) noexcept;
    ~BfrReference();

    /// False for holes and faces Bfr gives no limit surface (e.g. faces on
    /// a boundary with BoundaryInterpolation::None).
    bool hasLimitSurface(uint32_t face) const;
    /// False where OpenSubdiv 3.5's Bfr is known to fail: a face with two or
    /// more valence-2 interior corner vertices, where its irregular patch
    /// builder can share a wrong cached patch between faces or write out of
    /// bounds (fixed upstream in OpenSubdiv PR 1353, after Debian 12's
    /// 3.5); on catmark_val2_interior it is 6e-2 of the diagonal off and
    /// crashes with caching off. A conservative rule (it also skips a face
    /// Bfr gets right) that never lets the bug run. Implies
    /// hasLimitSurface().
    bool canEvaluate(uint32_t face) const;
    /// Position and derivatives (with respect to the face's (u, v)) at one
    /// location; nothing without a limit surface or where !canEvaluate.
    std::optional<LimitPoint> evaluate(uint32_t face, glm::dvec2 uv) const;
    /// The same at many locations of one face, preparing the face once.
    /// Returns false (leaving `out` alone) where !canEvaluate.
    bool evaluate(uint32_t face, std::span<const glm::dvec2> uvs, std::span<LimitPoint> out) const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace tessera::subdiv
