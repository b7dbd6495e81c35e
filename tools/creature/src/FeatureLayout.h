#pragma once
// Where the close-up features sit (internal header): the eyes, the mouth
// with its teeth and tusks, and the leather gear. CreatureSdf places them
// while it builds the shape (the mouth needs the face's depth) and adds
// their geometry; FeatureDetail reads the same layout to tell which surface
// a point is on, so the sculpt, the texture and the shape always agree.

#include "SdfPrimitives.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// One eyeball: a sphere under the lids, looking along `gaze`.
struct EyeLayout {
    glm::vec3 centre{0.0f};
    glm::vec3 gaze{0.0f, 0.0f, 1.0f};  ///< unit; the iris's centre direction
    float radius = 0.02f;
};

/// A tapered capsule (teeth, tusks, the mouth's slit).
struct CapsuleLayout {
    glm::vec3 a{0.0f}, b{0.0f};
    float ra = 0.0f, rb = 0.0f;
};

/// A strip of leather laid over the body: the surface thickened by
/// `thickness` where the point lies within `halfWidth` of the plane through
/// `centre` across `axis`, and inside the bounding capsule (which keeps it
/// off the limbs that pass the plane).
struct GearBand {
    enum class Kind : uint8_t { Belt, Strap, Bracer };
    Kind kind = Kind::Belt;
    glm::vec3 centre{0.0f};
    glm::vec3 axis{0.0f, 1.0f, 0.0f};  ///< unit normal of the band's mid-plane
    float halfWidth = 0.02f;
    float thickness = 0.006f;
    CapsuleLayout bound;       ///< only inside this capsule (ra == rb)
    uint32_t primitive = 0;    ///< index of its operation in the field (shapes before it are what it covers)
};

/// All the features of one creature, in bind-pose model space.
struct FeatureLayout {
    EyeLayout eyes[2];
    CapsuleLayout mouthSlit[2];          ///< the lip line, centre to each corner
    std::vector<CapsuleLayout> teeth;    ///< upper teeth, pointing down
    CapsuleLayout tusks[2];              ///< lower tusks, pointing up
    std::vector<GearBand> bands;         ///< belt first, then strap and bracers
    glm::vec3 buckleCentre{0.0f};        ///< on the belt's outer face, front
    glm::vec3 buckleNormal{0.0f, 0.0f, 1.0f};
};

/// Negative inside a band's strip (its width and bounding capsule), else
/// about the distance to it; the thickness plays no part.
inline float bandRegion(const GearBand& band, const glm::vec3& p) {
    float across = std::abs(glm::dot(p - band.centre, band.axis)) - band.halfWidth;
    float bound = sdf::taperedCapsule(p, band.bound.a, band.bound.b, band.bound.ra, band.bound.rb);
    return std::max(across, bound);
}

/// Distance to a tapered capsule.
inline float capsuleDistance(const CapsuleLayout& c, const glm::vec3& p) {
    return sdf::taperedCapsule(p, c.a, c.b, c.ra, c.rb);
}

} // namespace tessera::creature
