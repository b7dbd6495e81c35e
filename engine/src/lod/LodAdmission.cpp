#include "LodAdmission.h"

#include <algorithm>
#include <cfloat>

namespace tessera::lod::detail {

Admission admit(std::vector<AdmissionItem>& items, uint64_t forcedCost, uint64_t forcedCount,
                const AdmissionLimits& limits, bool demotionsFade) {
    std::sort(items.begin(), items.end(), [](const AdmissionItem& a, const AdmissionItem& b) {
        return a.pixels != b.pixels ? a.pixels > b.pixels : a.id < b.id;
    });
    const size_t n = items.size();
    // Admitting nobody: every rejected item that fades leaves a copy.
    uint64_t cost = forcedCost, count = forcedCount;
    for (const AdmissionItem& item : items)
        if (item.copyAlways || (item.copyIfDemoted && demotionsFade)) {
            cost += item.cost;
            ++count;
        }
    Admission best;
    best.fits = cost <= limits.maxCost && count <= limits.maxCount;
    best.cost = cost;
    best.count = count;
    if (!best.fits) {
        best.cut = FLT_MAX;
        return best;
    }
    // Admitting one more never lowers the total (its copy, if any, costs what
    // drawing it does), so the largest prefix within the limits is found by
    // one scan.
    size_t k = 0;
    for (; k < n; ++k) {
        const AdmissionItem& item = items[k];
        const bool hadCopy = item.copyAlways || (item.copyIfDemoted && demotionsFade);
        const uint64_t nextCost = cost + (hadCopy ? 0 : item.cost);
        const uint64_t nextCount = count + (hadCopy ? 0 : 1);
        if (nextCost > limits.maxCost || nextCount > limits.maxCount) break;
        cost = nextCost;
        count = nextCount;
    }
    // A pixel cut cannot separate equal sizes: drop the tied group.
    while (k > 0 && k < n && items[k - 1].pixels == items[k].pixels) {
        --k;
        const AdmissionItem& item = items[k];
        const bool hadCopy = item.copyAlways || (item.copyIfDemoted && demotionsFade);
        if (!hadCopy) {
            cost -= item.cost;
            --count;
        }
    }
    best.admitted = uint32_t(k);
    best.cost = cost;
    best.count = count;
    if (k == n) {
        best.cut = 0.0f;
    } else if (k == 0) {
        best.cut = FLT_MAX;
    } else {
        // Half way between the smallest admitted and the largest rejected,
        // so a GPU computing the size an ulp differently agrees.
        const float above = items[k - 1].pixels, below = items[k].pixels;
        const float mid = 0.5f * (above + below);
        best.cut = mid > below ? mid : above;
    }
    return best;
}

} // namespace tessera::lod::detail
