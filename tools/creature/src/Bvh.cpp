#include "creature/Bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tessera::creature {

namespace {

constexpr uint32_t kMaxLeafTriangles = 4;
constexpr int kBins = 16;
/// From this depth on the build halves by slot, so depth <= 48 + 32 < kStackSize.
constexpr uint32_t kMaxSahDepth = 48;
constexpr int kStackSize = 128;
constexpr float kInf = std::numeric_limits<float>::infinity();

float surfaceArea(const glm::vec3& lo, const glm::vec3& hi) {
    glm::vec3 e = glm::max(hi - lo, glm::vec3(0.0f));
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

struct Bin {
    glm::vec3 lo{kInf};
    glm::vec3 hi{-kInf};
    uint32_t count = 0;
};

} // namespace

Bvh::Bvh(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
    const uint32_t count = static_cast<uint32_t>(indices.size() / 3);
    std::vector<glm::vec3> centroids(count), boxMin(count), boxMax(count);
    mOrder.resize(count);
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3& a = positions[indices[3 * i]];
        const glm::vec3& b = positions[indices[3 * i + 1]];
        const glm::vec3& c = positions[indices[3 * i + 2]];
        boxMin[i] = glm::min(a, glm::min(b, c));
        boxMax[i] = glm::max(a, glm::max(b, c));
        centroids[i] = (boxMin[i] + boxMax[i]) * 0.5f;
        mOrder[i] = i;
    }
    build(centroids, boxMin, boxMax);
    mTriangles.resize(count);
    for (uint32_t slot = 0; slot < count; ++slot) {
        uint32_t i = mOrder[slot];
        const glm::vec3& a = positions[indices[3 * i]];
        mTriangles[slot] = {a, positions[indices[3 * i + 1]] - a, positions[indices[3 * i + 2]] - a, i};
    }
}

void Bvh::build(std::vector<glm::vec3>& centroids, std::vector<glm::vec3>& boxMin,
                std::vector<glm::vec3>& boxMax) {
    struct Task {
        uint32_t node, begin, end, depth;
    };
    mNodes.reserve(2 * mOrder.size() / kMaxLeafTriangles + 1);
    mNodes.push_back({});
    std::vector<Task> stack{{0, 0, static_cast<uint32_t>(mOrder.size()), 0}};
    while (!stack.empty()) {
        Task task = stack.back();
        stack.pop_back();
        glm::vec3 lo(kInf), hi(-kInf), cLo(kInf), cHi(-kInf);
        for (uint32_t s = task.begin; s < task.end; ++s) {
            uint32_t i = mOrder[s];
            lo = glm::min(lo, boxMin[i]);
            hi = glm::max(hi, boxMax[i]);
            cLo = glm::min(cLo, centroids[i]);
            cHi = glm::max(cHi, centroids[i]);
        }
        // Widen boxes by a hair so a ray grazing a face is never culled by
        // rounding in the slab test; the BVH must agree with brute force.
        glm::vec3 pad = (glm::abs(lo) + glm::abs(hi)) * 1e-6f + glm::vec3(1e-30f);
        Node& node = mNodes[task.node];
        node.boundsMin = lo - pad;
        node.boundsMax = hi + pad;
        uint32_t n = task.end - task.begin;
        if (mOrder.empty() || n <= kMaxLeafTriangles) {
            node.firstOrLeft = task.begin;
            node.count = n;
            continue;
        }
        // Binned SAH over the centroid bounds along every axis.
        float bestCost = kInf;
        int bestAxis = -1, bestSplit = 0;
        for (int axis = 0; axis < 3; ++axis) {
            float extent = cHi[axis] - cLo[axis];
            if (!(extent > 0.0f)) continue;
            std::array<Bin, kBins> bins{};
            float k = kBins / extent;
            for (uint32_t s = task.begin; s < task.end; ++s) {
                uint32_t i = mOrder[s];
                int b = std::min(kBins - 1, static_cast<int>((centroids[i][axis] - cLo[axis]) * k));
                bins[b].lo = glm::min(bins[b].lo, boxMin[i]);
                bins[b].hi = glm::max(bins[b].hi, boxMax[i]);
                ++bins[b].count;
            }
            std::array<float, kBins> leftCost{};
            Bin acc;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.lo = glm::min(acc.lo, bins[b].lo);
                acc.hi = glm::max(acc.hi, bins[b].hi);
                acc.count += bins[b].count;
                leftCost[b] = acc.count ? surfaceArea(acc.lo, acc.hi) * acc.count : 0.0f;
            }
            acc = Bin{};
            for (int b = kBins - 1; b > 0; --b) {
                acc.lo = glm::min(acc.lo, bins[b].lo);
                acc.hi = glm::max(acc.hi, bins[b].hi);
                acc.count += bins[b].count;
                float cost = leftCost[b - 1] + (acc.count ? surfaceArea(acc.lo, acc.hi) * acc.count : 0.0f);
                if (acc.count < n && acc.count > 0 && cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = b;
                }
            }
        }
        uint32_t mid = task.begin;
        if (bestAxis >= 0 && task.depth < kMaxSahDepth) {
            float k = kBins / (cHi[bestAxis] - cLo[bestAxis]);
            auto* first = mOrder.data() + task.begin;
            auto* split = std::partition(first, mOrder.data() + task.end, [&](uint32_t i) {
                int b = std::min(kBins - 1, static_cast<int>((centroids[i][bestAxis] - cLo[bestAxis]) * k));
                return b < bestSplit;
            });
            mid = static_cast<uint32_t>(split - mOrder.data());
        }
        if (mid == task.begin || mid == task.end) {
            // All centroids coincide, or SAH keeps peeling off slivers: split
            // by slot so the depth (and the traversal stack) stays bounded.
            mid = task.begin + n / 2;
        }
        uint32_t left = static_cast<uint32_t>(mNodes.size());
        mNodes.push_back({});
        mNodes.push_back({});
        mNodes[task.node].firstOrLeft = left;
        mNodes[task.node].count = 0;
        stack.push_back({left + 1, mid, task.end, task.depth + 1});
        stack.push_back({left, task.begin, mid, task.depth + 1});
    }
}

bool Bvh::intersectTriangle(const Triangle& tri, const glm::vec3& origin, const glm::vec3& direction,
                            float tMin, float tMax, BvhHit& hit) const {
    glm::vec3 p = glm::cross(direction, tri.edge2);
    float det = glm::dot(tri.edge1, p);
    if (det == 0.0f || !std::isfinite(det)) return false;
    float invDet = 1.0f / det;
    glm::vec3 s = origin - tri.v0;
    float u = glm::dot(s, p) * invDet;
    if (u < 0.0f || u > 1.0f) return false;
    glm::vec3 q = glm::cross(s, tri.edge1);
    float v = glm::dot(direction, q) * invDet;
    if (v < 0.0f || u + v > 1.0f) return false;
    float t = glm::dot(tri.edge2, q) * invDet;
    if (!(t >= tMin && t <= tMax)) return false;
    hit = {t, tri.original, u, v};
    return true;
}

namespace {

/// Keeps the candidate nearest to the target; ties by triangle index.
bool better(const BvhHit& candidate, const std::optional<BvhHit>& best, float tTarget) {
    if (!best) return true;
    float dc = std::fabs(candidate.t - tTarget), db = std::fabs(best->t - tTarget);
    return dc < db || (dc == db && candidate.triangle < best->triangle);
}

} // namespace

std::optional<BvhHit> Bvh::nearestHit(const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                      float tMax, float tTarget) const {
    std::optional<BvhHit> best;
    if (mTriangles.empty()) return best;
    glm::vec3 safeDir = direction;
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(safeDir[a]) < 1e-30f) safeDir[a] = std::signbit(safeDir[a]) ? -1e-30f : 1e-30f;
    }
    const glm::vec3 invDir = 1.0f / safeDir;
    float lo = tMin, hi = tMax;
    auto enter = [&](const Node& node, float& tEnter) {
        glm::vec3 t0 = (node.boundsMin - origin) * invDir;
        glm::vec3 t1 = (node.boundsMax - origin) * invDir;
        glm::vec3 tn = glm::min(t0, t1), tf = glm::max(t0, t1);
        float a = std::max(std::max(tn.x, tn.y), std::max(tn.z, lo));
        float b = std::min(std::min(tf.x, tf.y), std::min(tf.z, hi));
        tEnter = std::fabs(std::clamp(tTarget, a, b) - tTarget);
        return a <= b;
    };
    uint32_t stack[kStackSize];
    int top = 0;
    float rootEnter;
    if (!enter(mNodes[0], rootEnter)) return best;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = mNodes[stack[--top]];
        float unused;
        if (!enter(node, unused)) continue;  // the interval may have shrunk since it was pushed
        if (node.count > 0) {
            for (uint32_t s = node.firstOrLeft; s < node.firstOrLeft + node.count; ++s) {
                BvhHit hit;
                if (intersectTriangle(mTriangles[s], origin, direction, lo, hi, hit) &&
                    better(hit, best, tTarget)) {
                    best = hit;
                    float d = std::fabs(hit.t - tTarget);
                    lo = std::max(tMin, tTarget - d);
                    hi = std::min(tMax, tTarget + d);
                }
            }
            continue;
        }
        float dl, dr;
        bool hl = enter(mNodes[node.firstOrLeft], dl);
        bool hr = enter(mNodes[node.firstOrLeft + 1], dr);
        // Visit the child whose box comes closest to the target first.
        if (hl && hr) {
            bool leftFirst = dl <= dr;
            stack[top++] = leftFirst ? node.firstOrLeft + 1 : node.firstOrLeft;
            stack[top++] = leftFirst ? node.firstOrLeft : node.firstOrLeft + 1;
        } else if (hl) {
            stack[top++] = node.firstOrLeft;
        } else if (hr) {
            stack[top++] = node.firstOrLeft + 1;
        }
    }
    return best;
}

std::optional<BvhHit> Bvh::nearestHitBruteForce(const glm::vec3& origin, const glm::vec3& direction,
                                                float tMin, float tMax, float tTarget) const {
    std::optional<BvhHit> best;
    for (const Triangle& tri : mTriangles) {
        BvhHit hit;
        if (intersectTriangle(tri, origin, direction, tMin, tMax, hit) && better(hit, best, tTarget)) {
            best = hit;
        }
    }
    return best;
}

} // namespace tessera::creature
