#include "UvAtlas.h"

#include "UvChartGrid.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <deque>
#include <map>
#include <numeric>

namespace tessera::creature {

namespace {

const std::array<glm::vec3, 6> kAxes = {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                        glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)};

// Below this facing a triangle would project too thin to texture well.
constexpr float kMinFacing = 0.3f;
// A triangle of another class may join a chart whose axis it faces this much.
constexpr float kJoinFacing = 0.6f;

struct Chart {
    std::vector<uint32_t> triangles;
    std::vector<glm::vec2> corners;  ///< three per triangle, in metres
    glm::vec2 size{0.0f};
    glm::vec2 offset{0.0f};  ///< where the chart's box lands in the atlas (UV)
};

// Triangle neighbours across each edge (UINT32_MAX where none).
std::vector<std::array<uint32_t, 3>> triangleNeighbours(const IndexedMesh& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> edges;
    uint32_t n = mesh.triangleCount();
    for (uint32_t t = 0; t < n; ++t)
        for (uint32_t k = 0; k < 3; ++k) edges[{mesh.indices[t * 3 + k], mesh.indices[t * 3 + (k + 1) % 3]}] = t;
    std::vector<std::array<uint32_t, 3>> result(n);
    for (uint32_t t = 0; t < n; ++t) {
        for (uint32_t k = 0; k < 3; ++k) {
            auto it = edges.find({mesh.indices[t * 3 + (k + 1) % 3], mesh.indices[t * 3 + k]});
            result[t][k] = it == edges.end() ? UINT32_MAX : it->second;
        }
    }
    return result;
}

std::vector<uint32_t> classifyTriangles(const IndexedMesh& mesh, const std::vector<std::array<uint32_t, 3>>& adj,
                                        std::vector<glm::vec3>& normals) {
    uint32_t n = mesh.triangleCount();
    std::vector<uint32_t> cls(n);
    normals.resize(n);
    for (uint32_t t = 0; t < n; ++t) {
        const glm::vec3 &a = mesh.positions[mesh.indices[t * 3]], &b = mesh.positions[mesh.indices[t * 3 + 1]],
                        &c = mesh.positions[mesh.indices[t * 3 + 2]];
        glm::vec3 nrm = glm::cross(b - a, c - a);
        float len = glm::length(nrm);
        normals[t] = len > 0.0f ? nrm / len : glm::vec3(0, 1, 0);
        uint32_t best = 0;
        for (uint32_t k = 1; k < 6; ++k)
            if (glm::dot(normals[t], kAxes[k]) > glm::dot(normals[t], kAxes[best])) best = k;
        cls[t] = best;
    }
    // Smooth the labels so fewer, larger charts form: a triangle joins the
    // class of two or more of its neighbours if it still faces that axis.
    for (int pass = 0; pass < 4; ++pass) {
        std::vector<uint32_t> next = cls;
        for (uint32_t t = 0; t < n; ++t) {
            for (uint32_t k = 0; k < 3; ++k) {
                uint32_t a = adj[t][k], b = adj[t][(k + 1) % 3];
                if (a == UINT32_MAX || b == UINT32_MAX || cls[a] != cls[b] || cls[a] == cls[t]) continue;
                if (glm::dot(normals[t], kAxes[cls[a]]) > kMinFacing) next[t] = cls[a];
            }
        }
        cls = std::move(next);
    }
    return cls;
}

// Turns the chart to the angle (of 16 tried) with the smallest bounding box
// and moves its corner to the origin.
void fitChart(Chart& chart) {
    float bestArea = 1e30f, bestAngle = 0.0f;
    for (int i = 0; i < 16; ++i) {
        float angle = static_cast<float>(i) * (3.14159265f * 0.5f / 16.0f);
        float cs = std::cos(angle), sn = std::sin(angle);
        glm::vec2 lo(1e30f), hi(-1e30f);
        for (const glm::vec2& p : chart.corners) {
            glm::vec2 q(cs * p.x - sn * p.y, sn * p.x + cs * p.y);
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
        float area = (hi.x - lo.x) * (hi.y - lo.y);
        if (area < bestArea - 1e-12f) {
            bestArea = area;
            bestAngle = angle;
        }
    }
    float cs = std::cos(bestAngle), sn = std::sin(bestAngle);
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (glm::vec2& p : chart.corners) {
        p = glm::vec2(cs * p.x - sn * p.y, sn * p.x + cs * p.y);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    for (glm::vec2& p : chart.corners) p -= lo;
    chart.size = hi - lo;
}

// Shelf packing at `scale` UV units per metre; false if it overflows.
bool packCharts(std::vector<Chart>& charts, const std::vector<uint32_t>& order, float scale, float gutter) {
    float x = gutter, y = gutter, shelf = 0.0f;
    for (uint32_t c : order) {
        glm::vec2 size = charts[c].size * scale;
        if (x + size.x + gutter > 1.0f) {
            x = gutter;
            y += shelf + gutter;
            shelf = 0.0f;
        }
        if (x + size.x + gutter > 1.0f || y + size.y + gutter > 1.0f) return false;
        charts[c].offset = glm::vec2(x, y);
        x += size.x + gutter;
        shelf = std::max(shelf, size.y);
    }
    return true;
}

} // namespace

UvAtlas buildUvAtlas(const IndexedMesh& mesh, float gutter) {
    auto adj = triangleNeighbours(mesh);
    std::vector<glm::vec3> normals;
    std::vector<uint32_t> cls = classifyTriangles(mesh, adj, normals);

    // Charts grow breadth-first over neighbours of the same class, skipping
    // any triangle whose flattened image would overlap the chart so far
    // (a surface can curl back over itself while facing one axis); a
    // skipped triangle seeds a later chart.
    uint32_t n = mesh.triangleCount();
    std::vector<uint32_t> chartOf(n, UINT32_MAX), rejectedBy(n, UINT32_MAX);
    std::vector<Chart> charts;
    for (uint32_t seed = 0; seed < n; ++seed) {
        if (chartOf[seed] != UINT32_MAX) continue;
        uint32_t id = static_cast<uint32_t>(charts.size());
        charts.emplace_back();
        // Basis with e1 x e2 = axis: triangles facing the axis stay
        // counter-clockwise in (u, v).
        glm::vec3 axis = kAxes[cls[seed]];
        glm::vec3 e1 = std::abs(axis.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::normalize(glm::cross(glm::vec3(0, 1, 0), axis));
        glm::vec3 e2 = glm::cross(axis, e1);
        auto flatten = [&](uint32_t t) {
            UvChartGrid::Triangle tri;
            for (uint32_t k = 0; k < 3; ++k) {
                const glm::vec3& p = mesh.positions[mesh.indices[t * 3 + k]];
                tri[k] = glm::vec2(glm::dot(p, e1), glm::dot(p, e2));
            }
            return tri;
        };
        UvChartGrid grid(0.04f);
        grid.add(flatten(seed));
        chartOf[seed] = id;
        std::deque<uint32_t> queue{seed};
        while (!queue.empty()) {
            uint32_t t = queue.front();
            queue.pop_front();
            charts[id].triangles.push_back(t);
            for (uint32_t nb : adj[t]) {
                if (nb == UINT32_MAX || chartOf[nb] != UINT32_MAX || rejectedBy[nb] == id) continue;
                // Neighbours of another class join too while they still face
                // this axis well: fewer, larger charts waste less gutter.
                if (cls[nb] != cls[seed] && glm::dot(normals[nb], axis) < kJoinFacing) continue;
                UvChartGrid::Triangle tri = flatten(nb);
                if (grid.overlaps(tri)) {
                    rejectedBy[nb] = id;
                    continue;
                }
                grid.add(tri);
                chartOf[nb] = id;
                queue.push_back(nb);
            }
        }
        std::sort(charts[id].triangles.begin(), charts[id].triangles.end());
        for (uint32_t t : charts[id].triangles) {
            UvChartGrid::Triangle tri = flatten(t);
            charts[id].corners.insert(charts[id].corners.end(), tri.begin(), tri.end());
        }
        fitChart(charts[id]);
    }

    // Tallest first packs shelves tightly; ties keep chart order.
    std::vector<uint32_t> order(charts.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return charts[a].size.y > charts[b].size.y; });
    float lo = 0.0f, hi = 1.0f;
    while (packCharts(charts, order, hi, gutter)) hi *= 2.0f;
    for (int i = 0; i < 40; ++i) {
        float mid = 0.5f * (lo + hi);
        (packCharts(charts, order, mid, gutter) ? lo : hi) = mid;
    }
    bool packed = packCharts(charts, order, lo, gutter);
    (void)packed;
    assert(packed);

    UvAtlas atlas;
    atlas.chartCount = static_cast<uint32_t>(charts.size());
    atlas.indices.resize(mesh.indices.size());
    for (const Chart& chart : charts) {
        std::map<uint32_t, uint32_t> local;  // welded vertex -> split vertex of this chart
        for (size_t i = 0; i < chart.triangles.size(); ++i) {
            uint32_t t = chart.triangles[i];
            for (uint32_t k = 0; k < 3; ++k) {
                uint32_t v = mesh.indices[t * 3 + k];
                auto [it, inserted] = local.try_emplace(v, static_cast<uint32_t>(atlas.source.size()));
                if (inserted) {
                    atlas.source.push_back(v);
                    glm::vec2 uv = chart.offset + chart.corners[i * 3 + k] * lo;
                    atlas.uvs.push_back(glm::clamp(uv, glm::vec2(0.0f), glm::vec2(1.0f)));
                }
                atlas.indices[t * 3 + k] = it->second;
            }
        }
    }
    return atlas;
}

} // namespace tessera::creature
