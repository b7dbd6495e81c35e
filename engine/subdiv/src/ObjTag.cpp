#include "ObjTag.h"

#include "ObjWords.h"

#include <algorithm>
#include <cmath>

namespace tessera::subdiv::obj {

namespace {

/// "2/1/0" as three counts; false unless it is exactly three non-negative integers.
bool parseCounts(std::string_view word, int64_t counts[3]) {
    for (int i = 0; i < 3; ++i) {
        const size_t slash = i < 2 ? word.find('/') : std::string_view::npos;
        if (i < 2 && slash == std::string_view::npos) return false;
        const std::optional<int64_t> count = parseInteger(word.substr(0, slash));
        if (!count || *count < 0) return false;
        counts[i] = *count;
        word = slash == std::string_view::npos ? std::string_view() : word.substr(slash + 1);
    }
    return true;
}

/// The sharpness for item `i` of a tag with one value for all or one per item.
Result<float> sharpness(const ObjTag& tag, size_t i) {
    const double value = tag.floats.size() == 1 ? tag.floats[0] : tag.floats[i];
    const std::optional<float> finite = toFiniteFloat(value);
    if (!finite) return fail(tag.name, " tag: non-finite sharpness");
    // OpenSubdiv's own reader clamps a negative sharpness to 0 (smooth).
    return std::max(0.0f, *finite);
}

/// A tag's 0-based vertex index, or an error naming the missing vertex.
Result<uint32_t> vertexIndex(const ObjTag& tag, int64_t value, const ObjShape& shape) {
    if (value < 0 || uint64_t(value) >= shape.positions.size())
        return fail(tag.name, " tag names missing vertex ", std::to_string(value), " (",
                    std::to_string(shape.positions.size()), " vertices, 0-based)");
    return uint32_t(value);
}

Status expectNo(const ObjTag& tag, bool floats, bool strings) {
    if (floats && !tag.floats.empty()) return fail(tag.name, " tag takes no floats");
    if (strings && !tag.strings.empty()) return fail(tag.name, " tag takes no strings");
    return {};
}

Status applyCrease(const ObjTag& tag, const ObjEdgeMap& edges, ObjShape& shape) {
    const size_t pairs = tag.ints.size() / 2;
    if (tag.ints.empty() || tag.ints.size() % 2 != 0)
        return fail("crease tag needs vertex pairs, has ", std::to_string(tag.ints.size()), " ints");
    if (tag.floats.size() != 1 && tag.floats.size() != pairs)
        return fail("crease tag needs 1 sharpness or 1 per vertex pair, has ", std::to_string(tag.floats.size()));
    if (Status none = expectNo(tag, false, true); !none) return none;
    for (size_t i = 0; i < pairs; ++i) {
        Result<uint32_t> v0 = vertexIndex(tag, tag.ints[2 * i], shape);
        if (!v0) return v0.error();
        Result<uint32_t> v1 = vertexIndex(tag, tag.ints[2 * i + 1], shape);
        if (!v1) return v1.error();
        if (!edges.contains(*v0, *v1))
            return fail("crease tag names edge ", std::to_string(*v0), "-", std::to_string(*v1),
                        ", which no face has (0-based vertices)");
        Result<float> s = sharpness(tag, i);
        if (!s) return s.error();
        shape.creases.push_back(Crease{*v0, *v1, *s});
    }
    return {};
}

Status applyCorner(const ObjTag& tag, ObjShape& shape) {
    if (tag.ints.empty()) return fail("corner tag names no vertex");
    if (tag.floats.size() != 1 && tag.floats.size() != tag.ints.size())
        return fail("corner tag needs 1 sharpness or 1 per vertex, has ", std::to_string(tag.floats.size()));
    if (Status none = expectNo(tag, false, true); !none) return none;
    for (size_t i = 0; i < tag.ints.size(); ++i) {
        Result<uint32_t> v = vertexIndex(tag, tag.ints[i], shape);
        if (!v) return v.error();
        Result<float> s = sharpness(tag, i);
        if (!s) return s.error();
        shape.corners.push_back(Corner{*v, *s});
    }
    return {};
}

Status applyHole(const ObjTag& tag, ObjShape& shape) {
    if (tag.ints.empty()) return fail("hole tag names no face");
    if (Status none = expectNo(tag, true, true); !none) return none;
    for (int64_t face : tag.ints) {
        if (face < 0 || uint64_t(face) >= shape.faceSizes.size())
            return fail("hole tag names missing face ", std::to_string(face), " (",
                        std::to_string(shape.faceSizes.size()), " faces, 0-based)");
        shape.holes.push_back(uint32_t(face));
    }
    return {};
}

Status applyInterpolateBoundary(const ObjTag& tag, ObjShape& shape) {
    if (tag.ints.size() != 1) return fail("interpolateboundary tag needs 1 int, has ", std::to_string(tag.ints.size()));
    if (Status none = expectNo(tag, true, true); !none) return none;
    if (tag.ints[0] < 0 || tag.ints[0] > 2)
        return fail("interpolateboundary tag: ", std::to_string(tag.ints[0]),
                    " is not 0 (none), 1 (edges) or 2 (edges and corners)");
    shape.boundary = BoundaryInterpolation(tag.ints[0]);
    return {};
}

/// OpenSubdiv's forms: its regression shapes name the triangle weights
/// (`0/0/1 catmark`: Catmark's, `0/0/1 smooth`: the smooth ones); Hbr read
/// an int (1 smooth, 0 Catmark). A bare `smoothtriangles` switches them on.
Status applySmoothTriangles(const ObjTag& tag, ObjShape& shape) {
    if (!tag.floats.empty() || tag.ints.size() + tag.strings.size() > 1)
        return fail("smoothtriangles tag takes one int or one string at most");
    if (!tag.strings.empty()) {
        if (tag.strings[0] != "smooth" && tag.strings[0] != "catmark")
            return fail("smoothtriangles tag: ", quotedWord(tag.strings[0]), " is not 'smooth' or 'catmark'");
        shape.smoothTriangles = tag.strings[0] == "smooth";
    } else if (!tag.ints.empty()) {
        if (tag.ints[0] != 0 && tag.ints[0] != 1)
            return fail("smoothtriangles tag: ", std::to_string(tag.ints[0]), " is not 0 (catmark) or 1 (smooth)");
        shape.smoothTriangles = tag.ints[0] == 1;
    } else {
        shape.smoothTriangles = true;
    }
    return {};
}

} // namespace

Result<ObjTag> parseObjTag(std::span<const std::string_view> words) {
    if (words.empty()) return fail("tag without a name");
    ObjTag tag;
    tag.name = std::string(words[0]);
    int64_t counts[3] = {};
    if (words.size() < 2 || !parseCounts(words[1], counts))
        return fail("tag ", quotedWord(words[0]), ": missing or malformed counts (<ints>/<floats>/<strings>)");
    // Compare each count with the values present before adding them, so
    // huge counts neither overflow nor size an allocation.
    const std::span<const std::string_view> values = words.subspan(2);
    const bool fits = counts[0] <= int64_t(values.size()) && counts[1] <= int64_t(values.size()) &&
                      counts[2] <= int64_t(values.size());
    if (!fits || size_t(counts[0] + counts[1] + counts[2]) != values.size())
        return fail("tag ", quotedWord(words[0]), ": counts ", quotedWord(words[1]), " do not match its ",
                    std::to_string(values.size()), " values");
    size_t next = 0;
    for (int64_t i = 0; i < counts[0]; ++i, ++next) {
        const std::optional<int64_t> value = parseInteger(values[next]);
        if (!value) return fail("tag ", quotedWord(words[0]), ": malformed int ", quotedWord(values[next]));
        tag.ints.push_back(*value);
    }
    for (int64_t i = 0; i < counts[1]; ++i, ++next) {
        const std::optional<double> value = parseNumber(values[next]);
        if (!value) return fail("tag ", quotedWord(words[0]), ": malformed float ", quotedWord(values[next]));
        tag.floats.push_back(*value);
    }
    for (int64_t i = 0; i < counts[2]; ++i, ++next) tag.strings.emplace_back(values[next]);
    return tag;
}

Status applyObjTag(const ObjTag& tag, const ObjEdgeMap& edges, ObjShape& shape) {
    if (tag.name == "crease") return applyCrease(tag, edges, shape);
    if (tag.name == "corner") return applyCorner(tag, shape);
    if (tag.name == "hole") return applyHole(tag, shape);
    if (tag.name == "interpolateboundary") return applyInterpolateBoundary(tag, shape);
    if (tag.name == "smoothtriangles") return applySmoothTriangles(tag, shape);
    return {}; // creasemethod, facevaryinginterpolateboundary, vertexedit, ...: not ours
}

} // namespace tessera::subdiv::obj
