#include "tessera/subdiv/FaceParameterization.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tessera::subdiv {

FaceParameterization::FaceParameterization(uint32_t faceSize) : mFaceSize(faceSize) {
    assert(faceSize >= 3);
    if (hasSubFaces()) {
        // The smallest square grid holding every sub-face, counted in
        // integers so perfect squares do not depend on sqrt's rounding.
        while (mTilesPerRow * mTilesPerRow < faceSize) ++mTilesPerRow;
    }
}

SubFaceCoord FaceParameterization::toSubFace(glm::dvec2 uv) const {
    if (!hasSubFaces()) return {0, glm::clamp(uv, 0.0, 1.0)};
    // A tile's used square is [0, 0.5]; past 3/4 of a tile a coordinate is
    // taken as the next tile's start (round-off from a neighbour's edge).
    const auto tileOf = [](double x) {
        double tile = std::floor(x);
        return x - tile > 0.75 ? tile + 1.0 : tile;
    };
    const double last = double(mTilesPerRow - 1);
    double col = std::clamp(tileOf(uv.x), 0.0, last);
    double row = std::max(tileOf(uv.y), 0.0);
    uint32_t subFace = uint32_t(row) * mTilesPerRow + uint32_t(col);
    if (subFace >= mFaceSize) { // past the last row's used tiles
        subFace = mFaceSize - 1;
        col = double(subFace % mTilesPerRow);
        row = double(subFace / mTilesPerRow);
    }
    glm::dvec2 st = (uv - glm::dvec2(col, row)) * 2.0;
    return {subFace, glm::clamp(st, 0.0, 1.0)};
}

glm::dvec2 FaceParameterization::fromSubFace(const SubFaceCoord& coord) const {
    if (!hasSubFaces()) return coord.st;
    assert(coord.subFace < mFaceSize);
    return vertexCoord(coord.subFace) + coord.st * 0.5;
}

glm::dvec2 FaceParameterization::vertexCoord(uint32_t k) const {
    assert(k < mFaceSize);
    if (!hasSubFaces()) {
        static constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        return {kCorner[k][0], kCorner[k][1]};
    }
    return {double(k % mTilesPerRow), double(k / mTilesPerRow)};
}

} // namespace tessera::subdiv
