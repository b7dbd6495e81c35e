#include "creature/SeamFixer.h"

#include "BakeBilinear.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace tessera::creature {

namespace {

/// Tikhonov damping of the seam solve, relative to bilinear weights (rows
/// have norms of about 0.5 to 1).
constexpr double kDamping = 0.03;

/// Weld ids: vertices with bit-identical positions share one.
std::vector<uint32_t> weldByPosition(const character::CageMesh& cage) {
    std::vector<uint32_t> order(cage.vertices.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    auto key = [&](uint32_t i) {
        const glm::vec3& p = cage.vertices[i].position;
        return std::tuple(p.x, p.y, p.z);
    };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return key(a) < key(b) || (key(a) == key(b) && a < b);
    });
    std::vector<uint32_t> weld(cage.vertices.size());
    uint32_t id = 0;
    for (size_t k = 0; k < order.size(); ++k) {
        if (k > 0 && key(order[k]) != key(order[k - 1])) ++id;
        weld[order[k]] = id;
    }
    return weld;
}

struct EdgeSide {
    uint32_t w0, w1;  ///< welded endpoints, w0 < w1
    uint32_t triangle;
    glm::vec2 uv0, uv1;
    bool operator<(const EdgeSide& o) const {
        return std::tie(w0, w1, triangle) < std::tie(o.w0, o.w1, o.triangle);
    }
};

} // namespace

SeamFixer::SeamFixer(const character::CageMesh& cage, uint32_t size) : mSize(size) {
    const std::vector<uint32_t> weld = weldByPosition(cage);
    std::vector<EdgeSide> sides;
    std::vector<std::tuple<uint32_t, float, float>> corners;
    for (uint32_t t = 0; t < cage.triangleCount(); ++t) {
        for (int e = 0; e < 3; ++e) {
            uint32_t i = cage.indices[3 * t + e], j = cage.indices[3 * t + (e + 1) % 3];
            corners.emplace_back(weld[i], cage.vertices[i].uv.x, cage.vertices[i].uv.y);
            if (weld[i] == weld[j]) continue;
            if (weld[i] > weld[j]) std::swap(i, j);
            sides.push_back({weld[i], weld[j], t, cage.vertices[i].uv, cage.vertices[j].uv});
        }
    }
    std::sort(sides.begin(), sides.end());
    for (size_t k = 0; k < sides.size();) {
        size_t end = k;
        while (end < sides.size() && sides[end].w0 == sides[k].w0 && sides[end].w1 == sides[k].w1) ++end;
        // Only manifold edges (two triangles) have a well-defined other side.
        if (end - k == 2 && (sides[k].uv0 != sides[k + 1].uv0 || sides[k].uv1 != sides[k + 1].uv1)) {
            mEdges.push_back({sides[k].uv0, sides[k].uv1, sides[k + 1].uv0, sides[k + 1].uv1});
        }
        k = end;
    }
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    for (size_t k = 0; k < corners.size();) {
        size_t end = k;
        while (end < corners.size() && std::get<0>(corners[end]) == std::get<0>(corners[k])) ++end;
        glm::vec2 first{std::get<1>(corners[k]), std::get<2>(corners[k])};
        for (size_t m = k + 1; m < end; ++m) {
            mVertexPairs.push_back({first, {std::get<1>(corners[m]), std::get<2>(corners[m])}});
        }
        k = end;
    }
}

std::vector<SeamFixer::SeamPair> SeamFixer::pairs(float perTexel) const {
    std::vector<SeamPair> out = mVertexPairs;
    const float scale = static_cast<float>(mSize);
    for (const SeamEdge& e : mEdges) {
        float texels = std::max(glm::length(e.a1 - e.a0), glm::length(e.b1 - e.b0)) * scale;
        int steps = std::max(1, static_cast<int>(std::ceil(texels * perTexel)));
        // Interior parameters only: the endpoints are seam vertices, paired above.
        for (int k = 1; k < steps; ++k) {
            float s = static_cast<float>(k) / static_cast<float>(steps);
            out.push_back({e.a0 + s * (e.a1 - e.a0), e.b0 + s * (e.b1 - e.b0)});
        }
    }
    return out;
}

std::vector<float> SeamFixer::mismatches(const std::vector<float>& map, float perTexel) const {
    std::vector<float> out;
    for (const SeamPair& p : pairs(perTexel)) {
        out.push_back(std::fabs(sampleBilinear(map, mSize, p.a) - sampleBilinear(map, mSize, p.b)));
    }
    return out;
}

float SeamFixer::maxMismatch(const std::vector<float>& map, float perTexel) const {
    std::vector<float> all = mismatches(map, perTexel);
    return all.empty() ? 0.0f : *std::max_element(all.begin(), all.end());
}

uint64_t SeamFixer::fix(std::vector<float>& map, std::vector<uint8_t>& fixed, float perTexel,
                        uint32_t iterations, float tolerance) const {
    // Rows of A in  A * delta = -A * map : fetchA - fetchB per pair, over a
    // compact numbering of the texels the pairs touch (shared texels merged).
    struct Row {
        uint32_t column[8];
        float coeff[8];
        int count = 0;
    };
    std::vector<Row> rows;
    std::vector<int32_t> columnOf(map.size(), -1);
    std::vector<uint32_t> texelOf;
    for (const SeamPair& p : pairs(perTexel)) {
        BilinearTaps a = bilinearTaps(p.a, mSize), b = bilinearTaps(p.b, mSize);
        Row row;
        auto add = [&](uint32_t texel, float c) {
            if (c == 0.0f) return;
            if (columnOf[texel] < 0) {
                columnOf[texel] = static_cast<int32_t>(texelOf.size());
                texelOf.push_back(texel);
            }
            uint32_t column = static_cast<uint32_t>(columnOf[texel]);
            for (int k = 0; k < row.count; ++k) {
                if (row.column[k] == column) {
                    row.coeff[k] += c;
                    return;
                }
            }
            row.column[row.count] = column;
            row.coeff[row.count++] = c;
        };
        for (int k = 0; k < 4; ++k) add(a.index[k], a.weight[k]);
        for (int k = 0; k < 4; ++k) add(b.index[k], -b.weight[k]);
        rows.push_back(row);
    }
    const size_t n = texelOf.size();
    auto multiply = [&](const std::vector<double>& x, std::vector<double>& out) {
        for (size_t r = 0; r < rows.size(); ++r) {
            double sum = 0.0;
            for (int k = 0; k < rows[r].count; ++k) sum += rows[r].coeff[k] * x[rows[r].column[k]];
            out[r] = sum;
        }
    };
    auto multiplyTransposed = [&](const std::vector<double>& y, std::vector<double>& out) {
        std::fill(out.begin(), out.end(), 0.0);
        for (size_t r = 0; r < rows.size(); ++r) {
            for (int k = 0; k < rows[r].count; ++k) out[rows[r].column[k]] += rows[r].coeff[k] * y[r];
        }
    };
    auto maxAbs = [](const std::vector<double>& v) {
        double m = 0.0;
        for (double e : v) m = std::max(m, std::fabs(e));
        return m;
    };

    // Damped CGLS from delta = 0: minimises |A delta - b|^2 + d^2 |delta|^2,
    // so texels move only as much as the seams require. The damping matters:
    // pairs that cannot all agree exactly (two piecewise-bilinear fetches
    // along one edge rarely can) otherwise let texels seen with tiny weights
    // (chart corners) swing far from the surface to shave off the last bit
    // of mismatch.
    std::vector<double> x0(n), delta(n, 0.0), s(n), p(n), residual(rows.size()), q(rows.size());
    for (size_t c = 0; c < n; ++c) x0[c] = map[texelOf[c]];
    multiply(x0, residual);
    for (double& e : residual) e = -e;
    multiplyTransposed(residual, s);
    p = s;
    double gamma = 0.0;
    for (double e : s) gamma += e * e;
    for (uint32_t it = 0; it < iterations && gamma > 0.0 && maxAbs(residual) > tolerance; ++it) {
        multiply(p, q);
        double qq = 0.0;
        for (double e : q) qq += e * e;
        for (double e : p) qq += kDamping * kDamping * e * e;
        if (!(qq > 0.0)) break;
        double alpha = gamma / qq;
        for (size_t c = 0; c < n; ++c) delta[c] += alpha * p[c];
        for (size_t r = 0; r < rows.size(); ++r) residual[r] -= alpha * q[r];
        multiplyTransposed(residual, s);
        for (size_t c = 0; c < n; ++c) s[c] -= kDamping * kDamping * delta[c];
        double next = 0.0;
        for (double e : s) next += e * e;
        double beta = next / gamma;
        gamma = next;
        for (size_t c = 0; c < n; ++c) p[c] = s[c] + beta * p[c];
    }

    uint64_t count = 0;
    for (size_t c = 0; c < n; ++c) {
        if (delta[c] == 0.0) continue;
        map[texelOf[c]] = static_cast<float>(x0[c] + delta[c]);
        fixed[texelOf[c]] = 1;
        ++count;
    }
    return count;
}

} // namespace tessera::creature
