#include "tessera/tessellator/ContinuousLevel.h"

namespace tessera::tessellator {

float ContinuousLevel::clamp(float level) {
    if (!(level > kMinLevel)) return kMinLevel; // NaN too
    return level < kMaxLevel ? level : kMaxLevel;
}

TessFactors ContinuousLevel::factors(float level) {
    const float l = clamp(level);
    return TessFactors{{l, l, l, l}, {l, l}};
}

} // namespace tessera::tessellator
