#pragma once
// Which surface a point of the creature is on, eye, mouth, tooth, leather
// or skin, and the fine relief that surface has (internal header). The
// sculpt adds the relief along the normal and the texture paints by the
// surface, so the baked maps and the colour line up.

#include "CreatureSdf.h"

#include <cstdint>
#include <glm/glm.hpp>

namespace tessera::creature {

/// The materials the base colour knows.
enum class Surface : uint8_t { Skin, Sclera, Iris, Pupil, Lip, Mouth, Tooth, Leather, Stitch, Metal };

/// What FeatureDetail finds at one point.
struct FeatureSample {
    Surface surface = Surface::Skin;
    float skinMask = 1.0f;      ///< 0..1, how much of the skin's wrinkles and warts show here
    float displacement = 0.0f;  ///< the feature's own relief along the normal (metres, within +-4 mm)
    float shade = 0.0f;         ///< 0..1, variation inside the surface (iris radius, leather grain, tooth length)
};

/// A pure function of position for one creature; thread-safe. Reads the
/// layout of the field it was made from, which must outlive it.
class FeatureDetail {
public:
    FeatureDetail(const CreatureSdf& sdf, uint32_t seed);

    /// The feature at p, a point on (or within a millimetre of) the base surface.
    FeatureSample sample(const glm::vec3& p) const;

private:
    bool sampleEye(const glm::vec3& p, FeatureSample& out) const;
    bool sampleMouth(const glm::vec3& p, FeatureSample& out) const;
    bool sampleGear(const glm::vec3& p, FeatureSample& out) const;
    /// Leather relief on a band: bevelled edges, a stitch row along each
    /// edge and grain; `inside` is the distance in from the nearer edge.
    void leather(const GearBand& band, const glm::vec3& p, float inside, FeatureSample& out) const;
    /// The belt's buckle, if p is on it.
    bool buckle(const GearBand& belt, const glm::vec3& p, FeatureSample& out) const;

    const CreatureSdf& mSdf;
    uint32_t mSeed;
};

} // namespace tessera::creature
