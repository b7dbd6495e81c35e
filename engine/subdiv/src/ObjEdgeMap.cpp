#include "ObjEdgeMap.h"

#include <algorithm>

namespace tessera::subdiv::obj {

uint64_t ObjEdgeMap::key(uint32_t a, uint32_t b) {
    return (uint64_t(std::min(a, b)) << 32) | uint64_t(std::max(a, b));
}

ObjEdgeMap::AddResult ObjEdgeMap::add(uint32_t from, uint32_t to) {
    Use& use = mEdges[key(from, to)];
    // A manifold edge has at most one face on each side, and the two faces
    // of a consistently wound mesh walk it in opposite directions: so each
    // direction may be used once, and both used means two faces already.
    bool& walked = from < to ? use.ascending : use.descending;
    if (walked) return use.ascending && use.descending ? AddResult::MoreThanTwoFaces : AddResult::SameDirection;
    walked = true;
    return AddResult::Added;
}

bool ObjEdgeMap::contains(uint32_t a, uint32_t b) const {
    return mEdges.find(key(a, b)) != mEdges.end();
}

} // namespace tessera::subdiv::obj
