#pragma once
// LodAdmission.h: how many of a tier's candidates the budget admits, and
// the pixel cut that admits exactly them on every path (CPU and GPU).

#include <cstdint>
#include <vector>

namespace tessera::lod::detail {

/// An instance that may be drawn in the tier.
struct AdmissionItem {
    float pixels = 0.0f;
    uint32_t id = 0;
    uint32_t index = 0;          ///< the instance's index in the frame
    uint64_t cost = 0;           ///< what drawing it in the tier costs (triangles, or 1 for a count)
    bool copyIfDemoted = false;  ///< left the tier by the budget: a fading copy, when budget demotions fade
    bool copyAlways = false;     ///< already fading out of the tier: a copy whatever happens
};

struct AdmissionLimits {
    uint64_t maxCost = 0;
    uint64_t maxCount = 0;
};

struct Admission {
    uint32_t admitted = 0; ///< the first `admitted` items by size
    float cut = 0.0f;      ///< candidates at or above it are admitted
    uint64_t cost = 0;     ///< of the admitted and every copy (forced ones included)
    uint64_t count = 0;
    bool fits = true;      ///< false: even admitting nobody, the copies exceed a limit
};

/// Admits the largest prefix of `items` by size (largest first, ties by id)
/// whose cost and count, with the copies the rejected ones and
/// `forcedCost`/`forcedCount` (copies of instances that are not candidates)
/// add, stay within `limits`. Never splits equal sizes (a cut could not).
/// Reorders `items` so the admitted ones come first; when all fit, leaves
/// the order alone (cut 0).
Admission admit(std::vector<AdmissionItem>& items, uint64_t forcedCost, uint64_t forcedCount,
                const AdmissionLimits& limits, bool demotionsFade);

/// Widens `admission` to every item of at least `floor` pixels (a floor
/// below its cut): those items first in `items`, the cut at `floor`, the
/// count and cost raised by the items it adds (each costing its `cost`).
void admitDownTo(std::vector<AdmissionItem>& items, float floor, Admission& admission);

} // namespace tessera::lod::detail
