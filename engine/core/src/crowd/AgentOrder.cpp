#include "AgentOrder.h"

#include "tessera/core/ParallelFor.h"

#include <vector>

namespace tessera::crowd {
namespace {

template <class T>
void permute(std::vector<T>& values, std::span<const uint32_t> order, uint32_t threads) {
    std::vector<T> permuted(values.size());
    core::parallelForRanges(uint32_t(values.size()), 4096, threads, [&](core::IndexRange r) {
        for (uint32_t k = r.begin; k < r.end; ++k) permuted[k] = values[order[k]];
    });
    values.swap(permuted);
}

} // namespace

void reorderAgents(CrowdAgents& a, AgentState& st, std::span<const uint32_t> order, uint32_t threads) {
    permute(a.position, order, threads);
    permute(a.velocity, order, threads);
    permute(a.heading, order, threads);
    permute(a.radius, order, threads);
    permute(a.preferredSpeed, order, threads);
    permute(a.goalGroup, order, threads);
    permute(a.clip, order, threads);
    permute(a.phase, order, threads);
    permute(a.id, order, threads);
    permute(st.anchor, order, threads);
    permute(st.stuckTime, order, threads);
    permute(st.fleeTime, order, threads);
    permute(st.spot, order, threads);
    permute(st.arrivals, order, threads);
    permute(st.flags, order, threads);
}

} // namespace tessera::crowd
