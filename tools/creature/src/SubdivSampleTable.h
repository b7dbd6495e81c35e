#pragma once
/// @file SubdivSampleTable.h
/// The Catmull-Clark bake's samples: the sculpt's distance along the unit
/// limit normal at every level-0 texel centre of every tile, cast in
/// parallel up front (convertDisplacement asks for them one by one, on one
/// thread), with misses filled from neighbouring texels.

#include "creature/Bvh.h"
#include "tessera/subdiv/DisplacementTiles.h"
#include "tessera/subdiv/SubdivSurface.h"

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::creature {

/// A limit point and its unit normal (cross(Du, Dv) normalised: the
/// direction the renderer displaces along).
struct LimitFrame {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};
};

/// The frame at ptex (u, v); nothing on a hole or where the normal vanishes.
std::optional<LimitFrame> limitFrame(const subdiv::SubdivSurface& surface, uint32_t ptexFace, glm::dvec2 uv);

/// The signed distance along `frame.normal` to the sculpt hit nearest the
/// point within +-search; nothing on a miss.
std::optional<float> castToSculpt(const Bvh& bvh, const LimitFrame& frame, float search);

class SubdivSampleTable {
public:
    /// Casts every texel centre of `tiles` (level 0) on `threads` threads;
    /// the table does not depend on the count.
    SubdivSampleTable(const subdiv::SubdivSurface& surface, const subdiv::DisplacementTiles& tiles, const Bvh& bvh,
                      float search, uint32_t threads);

    /// D at (ptex face, u, v): the table at a texel centre, else a ray of
    /// its own (convertDisplacement's corner samples), a miss there taking
    /// the nearest texel's value.
    double sample(uint32_t ptexFace, glm::dvec2 uv) const;

    uint64_t misses() const { return mMisses; }
    uint64_t fromNeighbours() const { return mFromNeighbours; }
    uint64_t zero() const { return mZero; }

private:
    /// Fills tile `t`'s misses from hit 4-neighbours, pass after pass (each
    /// pass reads the previous one), then 0 where nothing reaches.
    void fillMisses(uint32_t tile, std::vector<uint8_t>& hit);

    const subdiv::SubdivSurface& mSurface;
    const subdiv::DisplacementTiles& mTiles;
    const Bvh& mBvh;
    float mSearch;
    std::vector<float> mValues; ///< allCoefficients()' layout
    uint64_t mMisses = 0, mFromNeighbours = 0, mZero = 0;
};

} // namespace tessera::creature
