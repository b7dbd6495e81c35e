#pragma once
/// @file ObjShape.h
/// A subdivision control mesh as OpenSubdiv's regression shapes and most
/// modelling tools write it: a Wavefront .obj (v, vt, f with any number of
/// vertices per face) plus OpenSubdiv's `t` tag lines for the subdivision
/// rules (crease, corner, hole, interpolateboundary, smoothtriangles). The
/// CPU data model of the second paper's base surfaces: no OpenSubdiv, no
/// device. SubdivSurface (SubdivSurface.h) turns it into patches.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// How the boundary of an open mesh is interpolated (Sdc::Options'
/// VtxBoundaryInterpolation; the `interpolateboundary` tag: 0 none,
/// 1 edges only, 2 edges and corners).
enum class BoundaryInterpolation : uint8_t { None = 0, EdgeOnly = 1, EdgeAndCorner = 2 };

/// A sharp or semi-sharp crease on the edge between two vertices.
struct Crease {
    uint32_t v0 = 0, v1 = 0;
    float sharpness = 0.0f; ///< 0 smooth, >= 10 infinitely sharp (OpenSubdiv's convention)
};

/// A sharp or semi-sharp corner vertex.
struct Corner {
    uint32_t vertex = 0;
    float sharpness = 0.0f;
};

struct ObjShape {
    std::string name; ///< the file name (for messages): readObjShape's path as given, parseObjShape's `name`
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs; ///< vt, may be empty
    /// Per face, its number of vertices (3 .. kMaxFaceVertices).
    std::vector<uint32_t> faceSizes;
    /// Every face's position indices, face after face (0-based).
    std::vector<uint32_t> faceVertices;
    /// Every face's uv indices, parallel to faceVertices, or empty when the
    /// faces carry none (a file whose faces mix the two is refused).
    std::vector<uint32_t> faceUvs;
    /// In file order, one per vertex pair of each `t crease` line (a
    /// negative sharpness read as 0, as OpenSubdiv's own reader does).
    std::vector<Crease> creases;
    std::vector<Corner> corners; ///< in file order, one per vertex of each `t corner` line
    std::vector<uint32_t> holes; ///< face indices (0-based, in faceSizes' order)
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgeAndCorner;
    /// `smoothtriangles`: Catmark's triangle subdivision option (smooth
    /// rather than the Catmull-Clark default weights). As OpenSubdiv's
    /// regression reader takes the tag: `t smoothtriangles 0/0/1 smooth`
    /// sets it and `0/0/1 catmark` clears it (so catmark_smoothtris0 reads
    /// false); Hbr's int form `1/0/0 1` (or 0) and a bare `0/0/0` are read
    /// too (the bare tag sets it).
    bool smoothTriangles = false;

    uint32_t faceCount() const { return uint32_t(faceSizes.size()); }
};

/// The most vertices a face may have (OpenSubdiv's own limit for a
/// regular refinement is far higher; a tile-based displacement subdivides
/// non-quads once, and a face this large is almost surely a broken file).
inline constexpr uint32_t kMaxFaceVertices = 64;

/// Parses .obj text. `name` labels every message. Errors, one line each,
/// "<name>:<line>: <problem>" (or "<name>: <problem>" for the whole file):
/// an empty file, no vertices or no faces, a face with fewer than 3 or more
/// than kMaxFaceVertices vertices, an index out of range or 0 (1-based, or
/// negative relative indices; either names an element defined on an
/// earlier line), a face using a vertex twice (degenerate), an edge shared
/// by more than two faces or twice in the same direction (non-manifold),
/// faces that mix corners with and without uvs, a malformed number or tag
/// (counts that do not match its values), a tag naming a missing vertex,
/// edge or face, a non-finite coordinate or sharpness.
///
/// Liberal otherwise: `vn` lines are only counted (to check face corners
/// naming normals), `o`, `g`, `s`, `usemtl`, `mtllib` and any other
/// statement are skipped, as are tags other than the five above (after
/// their counts are checked); `#` starts a comment anywhere, CR LF line
/// ends and tabs are fine, `v` may carry w or colours after x y z. Numbers
/// are read with std::from_chars (no locale). Tag indices are 0-based, as
/// OpenSubdiv writes them; a tag is applied after the last face, so it may
/// come anywhere in the file. Never throws.
Result<ObjShape> parseObjShape(std::string_view text, const std::string& name);

/// Reads and parses `path`; an unreadable or missing file is an error
/// naming it. Messages name the path as given. Never throws.
Result<ObjShape> readObjShape(const std::filesystem::path& path);

} // namespace tessera::subdiv
