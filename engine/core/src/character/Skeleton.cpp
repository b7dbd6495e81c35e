#include "tessera/character/Skeleton.h"

#include <glm/gtc/matrix_transform.hpp>

namespace tessera::character {

glm::mat4 NodeTransform::matrix() const {
    glm::mat4 m = glm::mat4_cast(rotation);
    m[0] *= scale.x;
    m[1] *= scale.y;
    m[2] *= scale.z;
    m[3] = glm::vec4(translation, 1.0f);
    return m;
}

bool Skeleton::isParentFirst() const {
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].parent >= static_cast<int32_t>(i)) return false;
    }
    return true;
}

} // namespace tessera::character
