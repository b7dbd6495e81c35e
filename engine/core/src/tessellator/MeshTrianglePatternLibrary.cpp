#include "tessera/tessellator/MeshTrianglePatternLibrary.h"

#include "MeshPieceStitcher.h"

#include <algorithm>
#include <cassert>

namespace tessera::tessellator {

const MeshTrianglePatternLibrary& MeshTrianglePatternLibrary::uniformFractionalOdd() {
    static const MeshTrianglePatternLibrary library;
    return library;
}

MeshTrianglePatternLibrary::MeshTrianglePatternLibrary() {
    using Rows = detail::MeshPieceStitcher::Rows;
    detail::MeshPieceStitcher pieces(mKeys, mTriangles);
    const auto oddSpacing = detail::MeshPieceStitcher::oddSpacing;
    mKeys.resize(TS_MESH_TRI_KEY_COUNT);
    // Transition strips: an outer edge's n points to the first ring's row,
    // which takes the inner spacing's points 1 .. n - 2. At one uniform
    // level the edge and the inner spacing have the same point count.
    for (uint32_t k = 0; k < TS_MESH_TRI_TRANSITION_KEYS; ++k) {
        const uint32_t points = 2 * (k + 2);
        pieces.add(k, points, points - 2, [&](detail::RowStitcher& s, Rows a, Rows b) {
            s.transition(a, oddSpacing(points), b, oddSpacing(points));
        });
    }
    // One side of a ring pair: a trapezoid, diagonals mirrored, as
    // TrianglePattern stitches every ring after the first.
    for (uint32_t k = 0; k < TS_MESH_TRI_RING_KEYS; ++k) {
        const uint32_t outside = 2 * (k + 2);
        pieces.add(TS_MESH_TRI_KEY_RING + k, outside, outside - 2, [](detail::RowStitcher& s, Rows a, Rows b) {
            s.regular(a, b, true, detail::RowStitcher::Diagonals::Mirrored);
        });
    }
    // The centre (or, at level 1, the whole patch): one triangle over the
    // first points of edges 0, 1 and 2.
    pieces.add(TS_MESH_TRI_KEY_CENTRE, 3, 0, [](detail::RowStitcher& s, Rows a, Rows) { s.triangle(a[0], a[1], a[2]); });
    mGroups = buildGroups(TS_MESH_TRI_GROUP_MAX_TRIANGLES);
    mCrowdGroups = buildGroups(TS_MESH_MAX_TRIANGLES);
}

std::vector<glm::uvec4> MeshTrianglePatternLibrary::buildGroups(uint32_t maxTriangles) const {
    struct Group {
        std::vector<glm::uvec4> chains;
        uint32_t points = 0, triangles = 0;
    };
    std::vector<glm::uvec4> classes(TS_MESH_TRI_CLASSES);
    std::vector<std::vector<Group>> groupsOf(TS_MESH_TRI_CLASSES);
    for (uint32_t c = 0; c < TS_MESH_TRI_CLASSES; ++c) {
        // A level whose patch has 2 * (c + 1) points an edge.
        const shader::TsMeshTrianglePatch p = shader::tsMeshTrianglePatch(c == 0 ? 1.0f : float(2 * c + 1));
        std::vector<Group>& groups = groupsOf[c];
        groups.emplace_back();
        uint32_t patchPoints = 0, patchTriangles = 0;
        // Adds `points` and `triangles` to the open group, first opening a
        // new one (and so a new chain) when they would not fit.
        auto fits = [&](uint32_t points, uint32_t triangles) {
            const Group& g = groups.back();
            return g.points + points <= TS_MESH_MAX_VERTICES && g.triangles + triangles <= maxTriangles;
        };
        for (uint32_t e = 0; e < 3 && p.rings > 1; ++e)
            for (uint32_t q = 0; q + 1 < p.rings; ++q) {
                const glm::uvec4 entry = mKeys[shader::tsMeshTrianglePieceKey(p, 3 * q + e)].entry;
                Group* g = &groups.back();
                const bool extends = !g->chains.empty() && g->chains.back().x == e && g->chains.back().z + 1 == q;
                // Extending a chain adds only the piece's inside row.
                const uint32_t points = extends ? entry.w : entry.z + entry.w;
                if (!extends || !fits(points, entry.y)) {
                    if (!fits(entry.z + entry.w, entry.y)) groups.emplace_back();
                    g = &groups.back();
                    g->chains.push_back({e, q, q, 0});
                    g->points += entry.z + entry.w;
                } else {
                    g->chains.back().z = q;
                    g->points += entry.w;
                }
                g->triangles += entry.y;
            }
        if (!fits(3, 1)) groups.emplace_back();
        groups.back().chains.push_back({TS_MESH_TRI_CHAIN_CENTRE, 0, 0, 0});
        groups.back().points += 3;
        groups.back().triangles += 1;
        for (const Group& g : groups) {
            patchPoints += g.points;
            patchTriangles += g.triangles;
        }
        const auto groupsPerPatch = static_cast<uint32_t>(groups.size());
        const uint32_t patchesPerGroup =
            groupsPerPatch > 1 ? 1
                               : std::min(TS_MESH_MAX_VERTICES / patchPoints, maxTriangles / patchTriangles);
        classes[c] = {0, groupsPerPatch, patchesPerGroup, 0};
    }
    // Lay out: classes, every class's groups, then every chain.
    uint32_t groupCount = 0;
    for (const auto& groups : groupsOf) groupCount += static_cast<uint32_t>(groups.size());
    std::vector<glm::uvec4> table = classes;
    uint32_t nextChain = TS_MESH_TRI_CLASSES + groupCount;
    std::vector<glm::uvec4> chains;
    for (uint32_t c = 0; c < TS_MESH_TRI_CLASSES; ++c) {
        table[c].x = static_cast<uint32_t>(table.size());
        for (const Group& g : groupsOf[c]) {
            table.push_back({nextChain, static_cast<uint32_t>(g.chains.size()), g.points, g.triangles});
            nextChain += static_cast<uint32_t>(g.chains.size());
            chains.insert(chains.end(), g.chains.begin(), g.chains.end());
        }
    }
    table.insert(table.end(), chains.begin(), chains.end());
    return table;
}

} // namespace tessera::tessellator
