#pragma once
// The high-frequency skin of the sculpt (internal header): wrinkles, warts
// and fine bumps as a displacement along the base shape's normal.

#include "FeatureDetail.h"
#include "creature/CreatureParams.h"

#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// What the skin does at one point.
struct SkinSample {
    float displacement = 0.0f;  ///< metres along the outward normal (about -6 mm .. +9 mm)
    float crease = 0.0f;        ///< 0..1, depth of a wrinkle groove here (for colour)
    float wart = 0.0f;          ///< 0..1, height of a wart here (for colour)
    FeatureSample feature;      ///< the eye, mouth or gear here, if any (for colour)
};

/// A pure function of position for one creature; thread-safe. The skin's
/// wrinkles and warts fade out over the eyes, mouth and gear, which bring
/// their own relief (FeatureDetail).
class SkinDetail {
public:
    /// `sdf` is the creature's field, which must outlive this.
    SkinDetail(const CreatureParams& params, const CreatureSdf& sdf);

    /// The skin at p, a point on (or near) the base surface.
    SkinSample sample(const glm::vec3& p) const;

    /// The largest |displacement| sample() can return (metres).
    static constexpr float kMaxAmplitude = 0.012f;

private:
    /// How wrinkled the skin is around p: strongest at the brow, neck and joints.
    float wrinkleMask(const glm::vec3& p) const;

    uint32_t mSeed;
    std::vector<glm::vec4> mFolds;
    FeatureDetail mFeatures;  ///< xyz centre, w radius of wrinkle-rich regions
};

} // namespace tessera::creature
