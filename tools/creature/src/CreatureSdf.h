#pragma once
// The creature's base shape as a signed distance field (internal header):
// smooth unions of ellipsoids and tapered capsules placed on the skeleton.

#include "creature/CreatureParams.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// One shape in the union, attached to the bone that moves it.
struct SdfPrimitive {
    enum class Kind : uint8_t { Ellipsoid, Capsule };
    Kind kind = Kind::Ellipsoid;
    glm::vec3 a{0.0f};         ///< ellipsoid centre, or capsule start
    glm::vec3 b{0.0f};         ///< capsule end
    glm::vec3 radii{0.1f};     ///< ellipsoid semi-axes; capsule radii in x (at a) and y (at b)
    glm::vec3 flatAxis{0.0f};  ///< unit axis the shape is squashed along (zero: none)
    float flatten = 1.0f;      ///< squash factor along flatAxis (>= 1)
    float blend = 0.03f;       ///< smooth-union width with everything before it
    Joint bone = Joint::Root;
    glm::vec3 boundCentre{0.0f};  ///< a sphere holding the shape (set by CreatureSdf)
    float boundRadius = -1.0f;    ///< negative: never skipped (squashed shapes)
};

/// Evaluates the union; negative inside. Immutable once built, so it is
/// safe to evaluate from several threads.
class CreatureSdf {
public:
    explicit CreatureSdf(const CreatureParams& params);

    /// Signed distance (metres, approximately Euclidean near the surface).
    float distance(const glm::vec3& p) const;
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

private:
    float primitiveDistance(const SdfPrimitive& prim, const glm::vec3& p) const;
    void add(const SdfPrimitive& prim);

    std::vector<SdfPrimitive> mPrims;
    glm::vec3 mMin{1e9f};
    glm::vec3 mMax{-1e9f};
};

} // namespace tessera::creature
