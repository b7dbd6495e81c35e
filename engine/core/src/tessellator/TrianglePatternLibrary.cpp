#include "tessera/tessellator/TrianglePatternLibrary.h"

#include "tessera/shaders/TessTrianglePattern.h"
#include "tessera/tessellator/ContinuousLevel.h"
#include "tessera/tessellator/Tessellator.h"

#include <cassert>

namespace tessera::tessellator {
namespace {

using shader::tsEmuTriangleCode;

// The codes of a uniform triangle with n points per edge, in the order
// Tessellator's TrianglePattern adds its points: the outer ring edge by
// edge (each without its end corner), then each inner ring likewise.
std::vector<uint32_t> ringCodes(uint32_t n) {
    std::vector<uint32_t> codes;
    for (uint32_t e = 0; e < 3; ++e)
        for (uint32_t p = 0; p + 1 < n; ++p) codes.push_back(tsEmuTriangleCode(0, e, p));
    for (uint32_t r = 1; r < n / 2; ++r)
        for (uint32_t e = 0; e < 3; ++e)
            for (uint32_t p = r; p < n - 1 - r; ++p) codes.push_back(tsEmuTriangleCode(r, e, p));
    return codes;
}

} // namespace

const TrianglePatternLibrary& TrianglePatternLibrary::fractionalOdd() {
    static const TrianglePatternLibrary library;
    return library;
}

TrianglePatternLibrary::TrianglePatternLibrary() {
    for (uint32_t k = 0; k < TS_EMU_TRIANGLE_CLASSES; ++k) {
        // The class's odd integer level: its pattern's connectivity is the
        // class's (the fraction of a level only moves points; the unit test
        // checks every class at many levels against Tessellator).
        const float level = float(2 * k + 1);
        const TessellatedPatch patch =
            Tessellator::tessellate(Domain::Triangle, Partitioning::FractionalOdd, ContinuousLevel::factors(level));
        std::vector<uint32_t> codes;
        if (k == 0) {
            for (uint32_t corner = 0; corner < 3; ++corner)
                codes.push_back(tsEmuTriangleCode(TS_EMU_TRIANGLE_CORNER, 0, corner));
        } else {
            codes = ringCodes(2 * k + 2);
        }
        assert(codes.size() == patch.uv.size());
        Class c;
        c.firstCode = uint32_t(mCodes.size());
        c.codeCount = uint32_t(codes.size());
        c.firstIndex = uint32_t(mIndices.size());
        c.indexCount = uint32_t(patch.indices.size());
        mCodes.insert(mCodes.end(), codes.begin(), codes.end());
        mIndices.insert(mIndices.end(), patch.indices.begin(), patch.indices.end());
        mClasses.push_back(c);
    }
}

} // namespace tessera::tessellator
