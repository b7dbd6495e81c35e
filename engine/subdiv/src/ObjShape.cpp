/// @file ObjShape.cpp
/// The .obj reader: one pass over the lines, each checked as it is read (so
/// a message names the line at fault), then the tags, which need every face.
/// Words and numbers: ObjWords.h; edge checks: ObjEdgeMap.h; tags: ObjTag.h.

#include "tessera/subdiv/ObjShape.h"

#include "ObjEdgeMap.h"
#include "ObjTag.h"
#include "ObjWords.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <new>
#include <optional>
#include <sstream>
#include <utility>

namespace tessera::subdiv {

namespace {

using obj::quotedWord;

/// One face corner as written: `v`, `v/t`, `v//n` or `v/t/n`.
struct CornerRefs {
    int64_t vertex = 0;
    std::optional<int64_t> uv;
    std::optional<int64_t> normal;
};

/// Splits a face corner word at its slashes; nullopt for any other shape
/// ("", "1/", "/1", "1/2/3/4", "1/x").
std::optional<CornerRefs> parseCornerRefs(std::string_view word) {
    std::string_view parts[3];
    size_t partCount = 0;
    for (;;) {
        if (partCount == 3) return std::nullopt;
        const size_t slash = word.find('/');
        parts[partCount++] = word.substr(0, slash);
        if (slash == std::string_view::npos) break;
        word.remove_prefix(slash + 1);
    }
    CornerRefs refs;
    const std::optional<int64_t> vertex = obj::parseInteger(parts[0]);
    if (!vertex) return std::nullopt;
    refs.vertex = *vertex;
    // Only the uv of `v//n` may be empty.
    if (partCount >= 2 && !(partCount == 3 && parts[1].empty())) {
        refs.uv = obj::parseInteger(parts[1]);
        if (!refs.uv) return std::nullopt;
    }
    if (partCount == 3) {
        refs.normal = obj::parseInteger(parts[2]);
        if (!refs.normal) return std::nullopt;
    }
    return refs;
}

class ObjParser {
public:
    ObjParser(std::string_view text, const std::string& name) : mText(text) { mShape.name = name; }

    Result<ObjShape> parse() {
        size_t start = 0;
        while (start <= mText.size()) {
            const size_t end = std::min(mText.find('\n', start), mText.size());
            ++mLine;
            if (Status line = parseLine(mText.substr(start, end - start)); !line) return atLine(mLine, line.error());
            start = end + 1;
        }
        if (mText.find_first_not_of(" \t\r\n\v\f") == std::string_view::npos) return atFile("empty file");
        if (mShape.positions.empty()) return atFile("no vertices (no 'v' line)");
        if (mShape.faceSizes.empty()) return atFile("no faces (no 'f' line)");
        for (const auto& [line, tag] : mTags) {
            if (Status applied = obj::applyObjTag(tag, mEdges, mShape); !applied) return atLine(line, applied.error());
        }
        return std::move(mShape);
    }

private:
    Error atLine(size_t line, const Error& error) const {
        return fail(mShape.name, ":", std::to_string(line), ": ", error.message);
    }
    Error atFile(const std::string& problem) const { return fail(mShape.name, ": ", problem); }

    Status parseLine(std::string_view line) {
        // '#' starts a comment anywhere on the line.
        line = line.substr(0, line.find('#'));
        obj::splitWords(line, mWords);
        if (mWords.empty()) return {};
        const std::string_view keyword = mWords[0];
        const std::span<const std::string_view> args = std::span<const std::string_view>(mWords).subspan(1);
        if (keyword == "v") return parseVertex(args);
        if (keyword == "vt") return parseUv(args);
        if (keyword == "vn") {
            // Normals are not read (a subdivision surface has its own), only
            // counted so that face corners naming them can be checked.
            ++mNormalCount;
            return {};
        }
        if (keyword == "f") return parseFace(args);
        if (keyword == "t") {
            Result<obj::ObjTag> tag = obj::parseObjTag(args);
            if (!tag) return tag.error();
            mTags.emplace_back(mLine, std::move(tag.value()));
            return {};
        }
        // o, g, s, usemtl, mtllib, l, p and the rest of the format: nothing
        // a control mesh needs.
        return {};
    }

    /// Reads at least `need` numbers from `args`, the first `keep` of them
    /// (finite) into `out`. Any more must be numbers too but are not kept:
    /// `v x y z w`, vertex colours `v x y z r g b`, `vt u v w`.
    static Status readCoordinates(std::span<const std::string_view> args, size_t need, size_t keep, float* out,
                                  const char* what) {
        if (args.size() < need)
            return fail(what, " with ", std::to_string(args.size()), " coordinates (needs ", std::to_string(need), ")");
        for (size_t i = 0; i < args.size(); ++i) {
            const std::optional<double> number = obj::parseNumber(args[i]);
            if (!number) return fail("malformed or out-of-range number ", quotedWord(args[i]));
            if (i >= keep) continue;
            const std::optional<float> value = obj::toFiniteFloat(*number);
            if (!value) return fail("non-finite coordinate ", quotedWord(args[i]), " in ", what);
            out[i] = *value;
        }
        return {};
    }

    Status parseVertex(std::span<const std::string_view> args) {
        float xyz[3] = {};
        if (Status read = readCoordinates(args, 3, 3, xyz, "vertex"); !read) return read;
        mShape.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
        return {};
    }

    Status parseUv(std::span<const std::string_view> args) {
        float uv[2] = {}; // `vt u` alone means v = 0
        if (Status read = readCoordinates(args, 1, 2, uv, "texture coordinate"); !read) return read;
        mShape.uvs.emplace_back(uv[0], uv[1]);
        return {};
    }

    Status parseFace(std::span<const std::string_view> args) {
        if (args.size() < 3 || args.size() > kMaxFaceVertices)
            return fail("face with ", std::to_string(args.size()), " vertices (3 to ", std::to_string(kMaxFaceVertices),
                        ")");
        mFaceVertices.clear();
        mFaceUvs.clear();
        for (std::string_view word : args) {
            const std::optional<CornerRefs> refs = parseCornerRefs(word);
            if (!refs) return fail("malformed face vertex ", quotedWord(word), " (v, v/vt, v//vn or v/vt/vn)");
            const std::optional<uint32_t> vertex = obj::resolveReference(refs->vertex, mShape.positions.size());
            if (!vertex) return outOfRange("vertex", refs->vertex, mShape.positions.size());
            mFaceVertices.push_back(*vertex);
            if (refs->uv) {
                const std::optional<uint32_t> uv = obj::resolveReference(*refs->uv, mShape.uvs.size());
                if (!uv) return outOfRange("texture coordinate", *refs->uv, mShape.uvs.size());
                mFaceUvs.push_back(*uv);
            }
            if (refs->normal && !obj::resolveReference(*refs->normal, mNormalCount))
                return outOfRange("normal", *refs->normal, mNormalCount);
        }
        if (Status uvs = checkUvUse(); !uvs) return uvs;
        if (Status topology = addFaceEdges(); !topology) return topology;
        mShape.faceSizes.push_back(uint32_t(mFaceVertices.size()));
        mShape.faceVertices.insert(mShape.faceVertices.end(), mFaceVertices.begin(), mFaceVertices.end());
        mShape.faceUvs.insert(mShape.faceUvs.end(), mFaceUvs.begin(), mFaceUvs.end());
        return {};
    }

    static Error outOfRange(const char* what, int64_t reference, size_t count) {
        return fail(what, " index ", std::to_string(reference), " out of range (", std::to_string(count),
                    " so far; 1-based, or negative from the last)");
    }

    /// faceUvs is parallel to faceVertices or empty: so either every corner
    /// of every face names a uv, or none does.
    Status checkUvUse() {
        if (!mFaceUvs.empty() && mFaceUvs.size() != mFaceVertices.size())
            return fail("face gives texture coordinates for some vertices but not all");
        const bool hasUvs = !mFaceUvs.empty();
        if (!mFacesHaveUvs) mFacesHaveUvs = hasUvs;
        if (*mFacesHaveUvs != hasUvs)
            return fail(hasUvs ? "face with texture coordinates after faces without"
                               : "face without texture coordinates after faces with");
        return {};
    }

    /// The degenerate and non-manifold checks, in the file's 1-based numbers.
    Status addFaceEdges() {
        const size_t n = mFaceVertices.size();
        for (size_t i = 0; i < n; ++i) {
            for (size_t j = i + 1; j < n; ++j)
                if (mFaceVertices[i] == mFaceVertices[j])
                    return fail("degenerate face: uses vertex ", std::to_string(mFaceVertices[i] + 1), " twice");
        }
        for (size_t i = 0; i < n; ++i) {
            const uint32_t from = mFaceVertices[i], to = mFaceVertices[(i + 1) % n];
            const obj::ObjEdgeMap::AddResult added = mEdges.add(from, to);
            const std::string edge = "edge " + std::to_string(from + 1) + "-" + std::to_string(to + 1);
            if (added == obj::ObjEdgeMap::AddResult::SameDirection)
                return fail("non-manifold ", edge, ": a second face runs it the same way (inconsistent winding)");
            if (added == obj::ObjEdgeMap::AddResult::MoreThanTwoFaces)
                return fail("non-manifold ", edge, ": shared by more than two faces");
        }
        return {};
    }

    std::string_view mText;
    ObjShape mShape;
    obj::ObjEdgeMap mEdges;
    std::vector<std::pair<size_t, obj::ObjTag>> mTags; ///< with their line numbers
    std::optional<bool> mFacesHaveUvs;                 ///< set by the first face
    size_t mNormalCount = 0;
    size_t mLine = 0;
    // Scratch, kept to spare an allocation per line.
    std::vector<std::string_view> mWords;
    std::vector<uint32_t> mFaceVertices, mFaceUvs;
};

} // namespace

Result<ObjShape> parseObjShape(std::string_view text, const std::string& name) {
    try {
        return ObjParser(text, name).parse();
    } catch (const std::bad_alloc&) {
        return fail(name, ": out of memory");
    }
}

Result<ObjShape> readObjShape(const std::filesystem::path& path) {
    // The path as the caller gave it, so the message says which file.
    const std::string name = path.string();
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) return fail(name, ": no such file");
    if (ec) return fail(name, ": cannot read file (", ec.message(), ")");
    if (status.type() != std::filesystem::file_type::regular) return fail(name, ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(name, ": cannot open file");
    try {
        std::ostringstream text;
        text << in.rdbuf();
        if (in.bad() || text.bad()) return fail(name, ": cannot read file");
        return parseObjShape(text.view(), name);
    } catch (const std::bad_alloc&) {
        return fail(name, ": out of memory");
    }
}

} // namespace tessera::subdiv
