#include "tessera/tessellator/AdaptiveLevels.h"

#include <string>

namespace tessera::tessellator {

Result<AdaptiveLevels> AdaptiveLevels::create(float minLevel, float maxLevel) {
    // Written as negations so that NaN fails every test.
    if (!(minLevel >= 1.0f) || !(maxLevel <= 64.0f) || !(minLevel <= maxLevel))
        return fail("adaptive tessellation levels: need 1 <= min <= max <= 64, got min ", std::to_string(minLevel),
                    ", max ", std::to_string(maxLevel));
    return AdaptiveLevels(minLevel, maxLevel);
}

float AdaptiveLevels::clamp(float level) const {
    if (!(level > mMin)) return mMin;
    return level < mMax ? level : mMax;
}

TessFactors AdaptiveLevels::clamp(const TessFactors& factors) const {
    TessFactors out;
    for (size_t i = 0; i < out.outer.size(); ++i) out.outer[i] = clamp(factors.outer[i]);
    for (size_t i = 0; i < out.inner.size(); ++i) out.inner[i] = clamp(factors.inner[i]);
    return out;
}

} // namespace tessera::tessellator
