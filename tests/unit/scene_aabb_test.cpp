#include "tessera/scene/Aabb.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using tessera::scene::Aabb;

namespace {

void expectVecNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

/// Reference: the box around all eight transformed corners.
Aabb bruteForceTransform(const Aabb& box, const glm::mat4& m) {
    Aabb out;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                         (i & 4) ? box.max.z : box.min.z);
        out.expand(glm::vec3(m * glm::vec4(corner, 1.0f)));
    }
    return out;
}

} // namespace

TEST(SceneAabb, EmptyIsIdentityOfExpand) {
    Aabb box = Aabb::empty();
    EXPECT_TRUE(box.isEmpty());
    EXPECT_TRUE(Aabb{}.isEmpty());
    EXPECT_FALSE(box.contains(glm::vec3(0.0f)));
    box.expand(glm::vec3(1, 2, 3));
    EXPECT_FALSE(box.isEmpty());
    EXPECT_EQ(box.min, glm::vec3(1, 2, 3));
    EXPECT_EQ(box.max, glm::vec3(1, 2, 3));
    box.expand(Aabb::empty());
    EXPECT_EQ(box.min, glm::vec3(1, 2, 3));
    box.expand(Aabb::fromMinMax(glm::vec3(-1), glm::vec3(0)));
    EXPECT_EQ(box.min, glm::vec3(-1));
    EXPECT_EQ(box.max, glm::vec3(1, 2, 3));
}

TEST(SceneAabb, CenterExtentsContains) {
    Aabb box = Aabb::fromMinMax(glm::vec3(-2, 0, 4), glm::vec3(2, 6, 5));
    EXPECT_EQ(box.center(), glm::vec3(0, 3, 4.5f));
    EXPECT_EQ(box.extents(), glm::vec3(2, 3, 0.5f));
    EXPECT_TRUE(box.contains(glm::vec3(0, 3, 4.5f)));
    EXPECT_TRUE(box.contains(glm::vec3(2, 6, 5))); // Boundary is inside.
    EXPECT_FALSE(box.contains(glm::vec3(2.01f, 3, 4.5f)));
    EXPECT_FALSE(box.contains(glm::vec3(0, -0.01f, 4.5f)));
}

TEST(SceneAabb, TransformedTranslationAndScale) {
    Aabb box = Aabb::fromMinMax(glm::vec3(-1), glm::vec3(1));
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(10, 20, 30));
    m = glm::scale(m, glm::vec3(2, 3, -4)); // Negative scale swaps min and max.
    Aabb out = box.transformed(m);
    expectVecNear(out.min, glm::vec3(8, 17, 26));
    expectVecNear(out.max, glm::vec3(12, 23, 34));
}

TEST(SceneAabb, TransformedRotationIsTightAroundCorners) {
    Aabb box = Aabb::fromMinMax(glm::vec3(-1, -2, -3), glm::vec3(4, 5, 6));
    // A 45 degree turn about Y grows the X/Z extent by sqrt(2) of the diagonal.
    glm::mat4 m = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 1, 0));
    Aabb out = box.transformed(m);
    Aabb ref = bruteForceTransform(box, m);
    expectVecNear(out.min, ref.min);
    expectVecNear(out.max, ref.max);

    // A general affine matrix: rotation about a skewed axis, scale, translation.
    glm::mat4 g = glm::translate(glm::mat4(1.0f), glm::vec3(-5, 7, 1.5f));
    g = glm::rotate(g, 1.1f, glm::normalize(glm::vec3(0.3f, -1.0f, 0.6f)));
    g = glm::scale(g, glm::vec3(0.5f, 2.0f, 1.5f));
    out = box.transformed(g);
    ref = bruteForceTransform(box, g);
    expectVecNear(out.min, ref.min);
    expectVecNear(out.max, ref.max);
}

TEST(SceneAabb, TransformedEmptyStaysEmpty) {
    glm::mat4 m = glm::rotate(glm::mat4(1.0f), 0.7f, glm::vec3(1, 0, 0));
    EXPECT_TRUE(Aabb::empty().transformed(m).isEmpty());
}
