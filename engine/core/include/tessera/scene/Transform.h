#pragma once
/// @file Transform.h
/// Translation, rotation and scale of a scene node relative to its parent.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace tessera::scene {

/// A decomposed affine transform. Applied to a point as scale first, then
/// rotation, then translation: toMatrix() = T * R * S.
struct Transform {
    glm::vec3 translation{0.0f};
    /// Unit quaternion; GLM's constructor order is (w, x, y, z), so this is identity.
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};

    /// The matrix T * R * S that maps local space to parent space.
    glm::mat4 toMatrix() const {
        glm::mat4 m = glm::mat4_cast(rotation);
        m[0] *= scale.x;
        m[1] *= scale.y;
        m[2] *= scale.z;
        m[3] = glm::vec4(translation, 1.0f);
        return m;
    }
};

} // namespace tessera::scene
