#pragma once
/// @file ObjEdgeMap.h
/// The edges of an .obj control mesh as its faces are read, to refuse what
/// OpenSubdiv's refiner cannot take (an edge of more than two faces, or one
/// two faces both walk the same way: inconsistent winding) with the line at
/// fault, and to find the edge a crease tag names.

#include <cstdint>
#include <unordered_map>

namespace tessera::subdiv::obj {

class ObjEdgeMap {
public:
    enum class AddResult {
        Added,           ///< a new edge, or the second face of one, walking it the other way
        SameDirection,   ///< a face already walks from `from` to `to` (inconsistent winding)
        MoreThanTwoFaces ///< two faces already share the edge (non-manifold)
    };

    /// Records that a face walks its boundary from vertex `from` to `to`
    /// (from != to). The map is unchanged when the result is not Added.
    AddResult add(uint32_t from, uint32_t to);

    /// True when some face has the edge between `a` and `b`, either way.
    bool contains(uint32_t a, uint32_t b) const;

private:
    /// How the faces seen so far use one undirected edge; "ascending" is
    /// the walk from the smaller vertex index to the larger.
    struct Use {
        bool ascending = false;
        bool descending = false;
    };

    static uint64_t key(uint32_t a, uint32_t b);

    std::unordered_map<uint64_t, Use> mEdges;
};

} // namespace tessera::subdiv::obj
