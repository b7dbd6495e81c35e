#pragma once
/// @file ObjTag.h
/// OpenSubdiv's `t` lines in an .obj file:
///
///     t <name> <nInts>/<nFloats>/<nStrings> <ints...> <floats...> <strings...>
///
/// e.g. `t crease 2/1/0 30 31 10.0`. Vertex and face indices in tags are
/// 0-based (OpenSubdiv's own), unlike the 1-based references of `f` lines.
/// A tag is read when its line is met and applied once every face is known
/// (a crease must name an edge of some face).

#include "ObjEdgeMap.h"

#include "tessera/core/Result.h"
#include "tessera/subdiv/ObjShape.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tessera::subdiv::obj {

/// One `t` line, its values as the counts declare them.
struct ObjTag {
    std::string name;
    std::vector<int64_t> ints;
    std::vector<double> floats;
    std::vector<std::string> strings;
};

/// Reads the words after `t`. An error (just the problem, no file or line)
/// for a missing name or counts, malformed counts, a number of values other
/// than the counts declare, or a malformed int or float.
Result<ObjTag> parseObjTag(std::span<const std::string_view> words);

/// Applies `tag` to `shape`, whose vertices and faces are all read:
/// crease (vertex pairs, one sharpness or one per pair), corner (vertices,
/// one sharpness or one per vertex), hole (face indices),
/// interpolateboundary (0, 1 or 2) and smoothtriangles. Other names are
/// skipped (OpenSubdiv's files carry tags this reader has no use for). An
/// error for values a known tag cannot take or that name a vertex, edge or
/// face the mesh lacks.
Status applyObjTag(const ObjTag& tag, const ObjEdgeMap& edges, ObjShape& shape);

} // namespace tessera::subdiv::obj
