#include "LodAdmission.h"

#include <algorithm>
#include <cfloat>
#include <cstddef>

namespace tessera::lod::detail {

Admission admit(std::vector<AdmissionItem>& items, uint64_t forcedCost, uint64_t forcedCount,
                const AdmissionLimits& limits, bool demotionsFade) {
    const size_t n = items.size();
    // Admitting nobody: every rejected item that fades leaves a copy.
    uint64_t cost = forcedCost, count = forcedCount, allCost = forcedCost, copies = 0;
    for (const AdmissionItem& item : items) {
        allCost += item.cost;
        if (item.copyAlways || (item.copyIfDemoted && demotionsFade)) {
            cost += item.cost;
            ++count;
            ++copies;
        }
    }
    // Admitting everybody costs every item once (a copy is replaced by the
    // draw). When that fits, no order is needed: the common case, and at
    // 65,000 instances the sort would be most of the frame's LOD time.
    if (allCost <= limits.maxCost && forcedCount + n <= limits.maxCount) {
        Admission all;
        all.admitted = uint32_t(n);
        all.cut = 0.0f;
        all.cost = allCost;
        all.count = forcedCount + n;
        return all;
    }
    // Otherwise only the largest few can be admitted: at most the count
    // left after the copies, plus the copies themselves (admitting one adds
    // nothing). Order that many and the first one past them.
    auto larger = [](const AdmissionItem& a, const AdmissionItem& b) {
        return a.pixels != b.pixels ? a.pixels > b.pixels : a.id < b.id;
    };
    const uint64_t room = limits.maxCount > count ? limits.maxCount - count : 0;
    const size_t ordered = size_t(std::min<uint64_t>(n, room + copies + 1));
    if (ordered < n) std::nth_element(items.begin(), items.begin() + std::ptrdiff_t(ordered), items.end(), larger);
    std::sort(items.begin(), items.begin() + std::ptrdiff_t(ordered), larger);
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
    // one scan. It ends within the ordered items: they hold more items
    // without a copy than the count has room for (and items[ordered] is the
    // next largest, nth_element's pivot, for the cut).
    size_t k = 0;
    for (; k < ordered; ++k) {
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

void admitDownTo(std::vector<AdmissionItem>& items, float floor, Admission& admission) {
    // The admitted prefix is the largest items; the ones it leaves at or
    // above the floor follow it in any order (nth_element's), so a
    // partition of the rest keeps the prefix and gathers them after it.
    auto rest = items.begin() + std::ptrdiff_t(admission.admitted);
    auto end = std::stable_partition(rest, items.end(), [floor](const AdmissionItem& item) { return item.pixels >= floor; });
    for (auto it = rest; it != end; ++it) {
        admission.cost += it->cost;
        ++admission.count;
    }
    admission.admitted = uint32_t(end - items.begin());
    admission.cut = floor;
}

} // namespace tessera::lod::detail
