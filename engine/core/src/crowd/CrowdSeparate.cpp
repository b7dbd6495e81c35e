// Crowd::separate(): pushes leftover overlaps apart and agents out of walls.

#include "tessera/crowd/Crowd.h"

#include "AgentState.h"
#include "Navigation.h"
#include "NeighbourGrid.h"
#include "StepTuning.h"
#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <vector>

namespace tessera::crowd {
namespace {

// Separation stops once no agent needed a push longer than this (metres).
constexpr float kSettled = 1e-3f;

// A push from one neighbour, and where that neighbour stands in the order
// separation sums pushes in: by row, then column, of cells of
// neighbourCellSize() (where it stood at the start of the step), then by
// index. A fixed order, whatever the neighbour grid's layout; and the order
// separation has always summed in (float sums in another order move agents
// by rounding, which in the dense counterflow changes which side flows).
struct Contact {
    int32_t row = 0, column = 0;
    uint32_t agent = 0;
    glm::vec2 push{0.0f};
    bool operator<(const Contact& o) const {
        return row != o.row ? row < o.row : column != o.column ? column < o.column : agent < o.agent;
    }
};

bool sameBits(glm::vec2 a, glm::vec2 b) {
    return std::bit_cast<uint32_t>(a.x) == std::bit_cast<uint32_t>(b.x) &&
           std::bit_cast<uint32_t>(a.y) == std::bit_cast<uint32_t>(b.y);
}

} // namespace

void Crowd::separate() {
    const CrowdSettings& s = mSettings;
    AgentState& st = *mState;
    const CrowdAgents& a = mAgents;
    const CostField& cost = mNavigation->cost();
    const NavGrid& grid = navGrid();
    const NeighbourGrid& neighbours = *mNeighbours;
    const float h = grid.cellSize();
    // Pushes `p` out of the impassable cells around it (and back onto its
    // previous spot if it walked right into one).
    auto keepOutOfWalls = [&](glm::vec2 p, float r, glm::vec2 previous) {
        if (!cost.passableAt(p)) p = previous;
        const glm::ivec2 c = grid.cellOf(p);
        for (int32_t j = c.y - 1; j <= c.y + 1; ++j)
            for (int32_t i = c.x - 1; i <= c.x + 1; ++i) {
                if (grid.inGrid(i, j) && cost.passable(grid.index(uint32_t(i), uint32_t(j)))) continue;
                const glm::vec2 lo = glm::vec2(float(i), float(j)) * h;
                const glm::vec2 d = p - glm::clamp(p, lo, lo + h);
                const float d2 = glm::dot(d, d);
                if (d2 < r * r && d2 > 1e-12f) p += d * (r / std::sqrt(d2) - 1.0f);
            }
        return p;
    };
    // Jacobi iterations, each reading the positions of the last: the result
    // does not depend on the order agents are visited in. They stop early
    // once nobody needed a push (avoidance leaves little to do), which is
    // decided from a maximum, so the same on any thread count.
    //
    // An agent is worked out afresh only where something it reads changed:
    // itself, or (crowded) an agent in the neighbour-grid cells it looks at.
    // Otherwise it reads what it read in the last iteration and comes out
    // where it did then, where it is (its push then stands too, for the
    // decision to stop). Most of a large crowd is settled after the first
    // iteration; the dense part goes on.
    if (a.size() == 0) return;
    const uint32_t iterations = std::max(1u, s.separationIterations);
    const bool pushes = s.separationIterations > 0;
    const float inverseOrderCell = 1.0f / neighbourCellSize();
    const uint32_t ranges = (uint32_t(a.size()) + kGrain - 1) / kGrain;
    std::vector<uint8_t> unsettled(ranges);
    // Clearing a mark per cell (a million cells for a million agents) is
    // work for every core, not one.
    auto clear = [&](std::vector<uint8_t>& marks) {
        marks.resize(neighbours.cellCount());
        core::parallelForRanges(uint32_t(marks.size()), 65536, s.threads, [&](core::IndexRange r) {
            std::fill(marks.begin() + r.begin, marks.begin() + r.end, uint8_t(0));
        });
    };
    clear(st.movedIn[0]);
    clear(st.movedIn[1]);
    for (uint32_t iteration = 0; iteration < iterations; ++iteration) {
        const std::vector<glm::vec2>& in = st.moved;
        std::vector<glm::vec2>& out = st.nextVelocity; // free once integrate() used it
        const std::vector<uint8_t>& movedBefore = st.movedIn[iteration & 1];
        std::vector<uint8_t>& movedNow = st.movedIn[(iteration + 1) & 1];
        if (iteration > 0) clear(movedNow);
        core::parallelForRanges(uint32_t(a.size()), kGrain, s.threads, [&](core::IndexRange range) {
            bool goOn = false;
            std::vector<Contact> contacts;
            for (uint32_t i = range.begin; i < range.end; ++i) {
                glm::vec2 p = in[i];
                const float r = a.radius[i];
                uint8_t flags = st.flags[i];
                const bool crowded = pushes && (flags & kCrowded);
                const float near = r + mLargestRadius + 2.0f * kQuerySlack;
                if (iteration > 0 && !(flags & kMoved) &&
                    (!crowded || !neighbours.anyCellNear(p, near, [&](uint32_t c) { return movedBefore[c] != 0; }))) {
                    out[i] = p;
                    goOn |= (flags & kPushed) != 0;
                    continue;
                }
                flags &= uint8_t(~(kMoved | kPushed));
                if (crowded) {
                    contacts.clear();
                    neighbours.forEachNear(p, near, [&](uint32_t j, glm::vec2 was) {
                        // Where j stood at the start of the step is within
                        // the slack of where it is: far from that, no need
                        // to look j up at all.
                        if (j == i || glm::dot(p - was, p - was) > near * near) return;
                        const glm::vec2 d = p - in[j];
                        const float reach = r + a.radius[j];
                        const float d2 = glm::dot(d, d);
                        if (d2 >= reach * reach) return;
                        const float distance = std::sqrt(d2);
                        const glm::vec2 n = distance > 1e-5f ? d / distance : glm::vec2(i < j ? 1.0f : -1.0f, 0.0f);
                        contacts.push_back({floorToInt(was.y * inverseOrderCell), floorToInt(was.x * inverseOrderCell), j,
                                            0.5f * (reach - distance) * n});
                    });
                    // Few: an insertion sort.
                    for (size_t k = 1; k < contacts.size(); ++k)
                        for (size_t m = k; m > 0 && contacts[m] < contacts[m - 1]; --m) std::swap(contacts[m], contacts[m - 1]);
                    glm::vec2 push(0.0f);
                    for (const Contact& c : contacts) push += c.push;
                    p += push;
                    if (glm::dot(push, push) >= kSettled * kSettled) flags |= kPushed;
                }
                if (flags & kOnWalkable) p = keepOutOfWalls(p, r, in[i]);
                out[i] = p;
                if (!sameBits(p, in[i])) {
                    flags |= kMoved;
                    const glm::vec2 was(a.position[i].x, a.position[i].z);
                    std::atomic_ref<uint8_t>(movedNow[neighbours.cellOf(was)]).store(1, std::memory_order_relaxed);
                }
                goOn |= (flags & kPushed) != 0;
                st.flags[i] = flags;
            }
            unsettled[range.begin / kGrain] = goOn;
        });
        st.moved.swap(st.nextVelocity);
        if (std::find(unsettled.begin(), unsettled.end(), 1) == unsettled.end()) break;
    }
}

} // namespace tessera::crowd
