#pragma once
// The creature's base shape as a signed distance field (internal header):
// smooth unions of ellipsoids and tapered capsules placed on the skeleton.

#include "FeatureLayout.h"
#include "creature/CreatureParams.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// One shape in the union, attached to the bone that moves it.
struct SdfPrimitive {
    /// Band: not a shape but an operation, thickening everything before it
    /// inside a FeatureLayout band (the gear).
    enum class Kind : uint8_t { Ellipsoid, Capsule, Band };
    Kind kind = Kind::Ellipsoid;
    bool subtract = false;     ///< carve the shape out (smoothly, over `blend`) instead of adding it
    /// Millimetre detail (lids, mouth, teeth, gear): in the sculpt's field
    /// only, not in the one the cage is extracted from (see coarseDistance).
    bool detail = false;
    /// The reverse: a soft stand-in for detail the cage cannot hold (the
    /// eye's mound), in the cage's field only.
    bool coarseOnly = false;
    glm::vec3 a{0.0f};         ///< ellipsoid centre, or capsule start
    glm::vec3 b{0.0f};         ///< capsule end
    glm::vec3 radii{0.1f};     ///< ellipsoid semi-axes; capsule radii in x (at a) and y (at b)
    glm::vec3 flatAxis{0.0f};  ///< unit axis the shape is squashed along (zero: none)
    float flatten = 1.0f;      ///< squash factor along flatAxis (>= 1)
    glm::vec4 clip{0.0f};      ///< xyz unit normal, w offset: keeps dot(p - a, n) >= w (zero: no clip)
    float blend = 0.03f;       ///< smooth-union width with everything before it
    uint32_t band = 0;         ///< Kind::Band: index into FeatureLayout::bands
    Joint bone = Joint::Root;
    glm::vec3 boundCentre{0.0f};  ///< a sphere holding the shape (set by CreatureSdf)
    float boundRadius = -1.0f;    ///< negative: never skipped (squashed shapes)
};

/// An ellipsoid primitive (axis-aligned semi-axes `radii`).
inline SdfPrimitive ellipsoidShape(const glm::vec3& centre, const glm::vec3& radii, float blend, Joint bone) {
    SdfPrimitive p;
    p.kind = SdfPrimitive::Kind::Ellipsoid;
    p.a = centre;
    p.radii = radii;
    p.blend = blend;
    p.bone = bone;
    return p;
}

/// A tapered capsule primitive from a (radius ra) to b (radius rb).
inline SdfPrimitive capsuleShape(const glm::vec3& a, const glm::vec3& b, float ra, float rb, float blend, Joint bone) {
    SdfPrimitive p;
    p.kind = SdfPrimitive::Kind::Capsule;
    p.a = a;
    p.b = b;
    p.radii = glm::vec3(ra, rb, 0.0f);
    p.blend = blend;
    p.bone = bone;
    return p;
}

/// Evaluates the union; negative inside. Immutable once built, so it is
/// safe to evaluate from several threads.
class CreatureSdf {
public:
    explicit CreatureSdf(const CreatureParams& params);

    /// Signed distance (metres, approximately Euclidean near the surface).
    float distance(const glm::vec3& p) const { return distanceBefore(p, mPrims.size()); }
    /// The field without the detail primitives: what the cage is meshed
    /// from. Teeth, lids and leather edges are smaller than the meshing
    /// grid and would pinch the cage into non-manifold knots; the sculpt
    /// projects onto the full field instead, and the maps carry them.
    float coarseDistance(const glm::vec3& p) const { return distanceBefore(p, mPrims.size(), true); }
    /// The distance of the shape made of the first `count` primitives only
    /// (what a gear band lies on), optionally without the detail ones.
    float distanceBefore(const glm::vec3& p, size_t count, bool coarse = false) const;
    /// Gradient by tetrahedral differences of step h (four evaluations);
    /// `value`, if given, receives their mean, the distance at p to O(h^2).
    glm::vec3 gradient(const glm::vec3& p, float h = 1e-3f, float* value = nullptr) const;
    /// Moves p onto the zero set along the gradient (a few Newton steps),
    /// never further than maxStep in total. Returns the unit outward normal
    /// there through `normal`.
    glm::vec3 project(const glm::vec3& p, int steps, float maxStep, glm::vec3* normal) const;
    /// The distance of p to each bone's own primitives (kJointCount floats;
    /// a large value for bones without any).
    void boneDistances(const glm::vec3& p, float* out) const;

    /// A box that holds the whole shape with a margin.
    glm::vec3 boundsMin() const { return mMin; }
    glm::vec3 boundsMax() const { return mMax; }

    /// Where the eyes, mouth and gear are.
    const FeatureLayout& layout() const { return mLayout; }

private:
    float primitiveDistance(const SdfPrimitive& prim, const glm::vec3& p) const;
    void add(const SdfPrimitive& prim);
    // The close-up features, in CreatureSdfFeatures.cpp: each adds its
    // shapes in place in the union and records them in mLayout.
    void addEyes(const CreatureParams& params);
    void addMouth(const CreatureParams& params);
    void addTorsoGear(const CreatureParams& params);
    void addBracer(const CreatureParams& params, bool left);
    void addBand(const GearBand& band);
    /// How far along unit `dir` a ray from `origin` meets the shape built
    /// so far (sphere tracing); `maxT` if it misses.
    float rayHit(const glm::vec3& origin, const glm::vec3& dir, float maxT) const;

    std::vector<SdfPrimitive> mPrims;
    FeatureLayout mLayout;
    glm::vec3 mMin{1e9f};
    glm::vec3 mMax{-1e9f};
};

} // namespace tessera::creature
