#include "tessera/scene/Camera.h"
#include "tessera/scene/SceneGraph.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <unordered_set>

using namespace tessera::scene;

namespace {

Transform translation(const glm::vec3& t) {
    Transform transform;
    transform.translation = t;
    return transform;
}

glm::vec3 worldOrigin(const SceneNode& n) { return glm::vec3(n.world[3]); }

void expectVecNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

const Aabb kUnitBox = Aabb::fromMinMax(glm::vec3(-1), glm::vec3(1));

bool containsId(const std::vector<NodeId>& ids, NodeId id) {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}

} // namespace

TEST(SceneTransform, MatrixAppliesScaleRotationTranslation) {
    Transform t;
    t.translation = glm::vec3(1, 2, 3);
    t.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    t.scale = glm::vec3(2.0f);
    // (1,0,0) scaled to (2,0,0), turned 90 degrees about +Y to (0,0,-2), moved.
    expectVecNear(glm::vec3(t.toMatrix() * glm::vec4(1, 0, 0, 1)), glm::vec3(1, 2, 1));
    EXPECT_EQ(Transform{}.toMatrix(), glm::mat4(1.0f));
}

TEST(SceneGraph, PropagatesTransformsThroughThreeLevels) {
    SceneGraph graph;
    NodeId a = graph.createNode("a");
    NodeId b = graph.createNode("b", a);
    NodeId c = graph.createNode("c", b);
    Transform ta = translation(glm::vec3(10, 0, 0));
    ta.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    graph.setLocalTransform(a, ta);
    Transform tb = translation(glm::vec3(0, 5, 0));
    tb.scale = glm::vec3(2.0f);
    graph.setLocalTransform(b, tb);
    graph.setLocalTransform(c, translation(glm::vec3(1, 0, 0)));
    graph.setLocalBounds(c, kUnitBox);
    graph.updateTransforms();

    // c's origin: (1,0,0) scaled by 2 -> (2,0,0), +5 up -> (2,5,0); a turns it
    // 90 degrees about +Y -> (0,5,-2) and moves it -> (10,5,-2).
    expectVecNear(worldOrigin(graph.node(c)), glm::vec3(10, 5, -2));
    expectVecNear(worldOrigin(graph.node(b)), glm::vec3(10, 5, 0));
    // c's unit box is scaled by 2 around (10,5,-2).
    expectVecNear(graph.node(c).worldBounds.min, glm::vec3(8, 3, -4));
    expectVecNear(graph.node(c).worldBounds.max, glm::vec3(12, 7, 0));
    // Ancestors without content still carry the subtree bounds; their own are empty.
    EXPECT_TRUE(graph.node(a).worldBounds.isEmpty());
    expectVecNear(graph.node(a).subtreeBounds.min, glm::vec3(8, 3, -4));
    expectVecNear(graph.node(a).subtreeBounds.max, glm::vec3(12, 7, 0));
    EXPECT_FALSE(graph.node(a).dirty);
    EXPECT_FALSE(graph.node(c).dirty);
}

TEST(SceneGraph, ChangingAParentUpdatesDescendantsAndAncestorBounds) {
    SceneGraph graph;
    NodeId root = graph.createNode("root");
    NodeId parent = graph.createNode("parent", root);
    NodeId child = graph.createNode("child", parent);
    NodeId sibling = graph.createNode("sibling", root);
    graph.setLocalTransform(child, translation(glm::vec3(0, 0, -3)));
    graph.setLocalBounds(child, kUnitBox);
    graph.setLocalBounds(sibling, kUnitBox);
    graph.updateTransforms();
    expectVecNear(worldOrigin(graph.node(child)), glm::vec3(0, 0, -3));

    graph.setLocalTransform(parent, translation(glm::vec3(100, 0, 0)));
    EXPECT_TRUE(graph.node(parent).dirty);
    EXPECT_FALSE(graph.node(child).dirty); // Children are caught in the update pass.
    graph.updateTransforms();
    expectVecNear(worldOrigin(graph.node(child)), glm::vec3(100, 0, -3));
    expectVecNear(graph.node(child).worldBounds.max, glm::vec3(101, 1, -2));
    // The root's subtree now spans the sibling at the origin and the moved child.
    expectVecNear(graph.node(root).subtreeBounds.min, glm::vec3(-1, -1, -4));
    expectVecNear(graph.node(root).subtreeBounds.max, glm::vec3(101, 1, 1));

    // Changing only bounds deep down also refreshes the ancestors' subtree bounds.
    graph.setLocalBounds(child, Aabb::fromMinMax(glm::vec3(-1), glm::vec3(1, 50, 1)));
    graph.updateTransforms();
    EXPECT_NEAR(graph.node(root).subtreeBounds.max.y, 50.0f, 1e-4f);

    // Destroying the child shrinks the root's subtree back to the sibling.
    graph.destroyNode(child);
    graph.updateTransforms();
    expectVecNear(graph.node(root).subtreeBounds.max, glm::vec3(1));
}

TEST(SceneGraph, DestroyIsRecursiveAndIdsGoStale) {
    SceneGraph graph;
    NodeId root = graph.createNode("root");
    NodeId a = graph.createNode("a", root);
    NodeId b = graph.createNode("b", a);
    NodeId other = graph.createNode("other");
    EXPECT_EQ(graph.nodeCount(), 4u);
    EXPECT_EQ(graph.roots().size(), 2u);

    graph.destroyNode(a);
    EXPECT_FALSE(graph.isAlive(a));
    EXPECT_FALSE(graph.isAlive(b));
    EXPECT_TRUE(graph.isAlive(root));
    EXPECT_TRUE(graph.isAlive(other));
    EXPECT_EQ(graph.nodeCount(), 2u);
    EXPECT_TRUE(graph.node(root).children.empty());

    // Reused slots get a new generation, so the old ids stay stale.
    NodeId c = graph.createNode("c");
    NodeId d = graph.createNode("d");
    EXPECT_TRUE(c.index == a.index || c.index == b.index);
    EXPECT_TRUE(graph.isAlive(c));
    EXPECT_TRUE(graph.isAlive(d));
    EXPECT_FALSE(graph.isAlive(a));
    EXPECT_FALSE(graph.isAlive(b));
    EXPECT_EQ(graph.node(c).name, "c");
    EXPECT_TRUE(graph.node(c).children.empty());
    EXPECT_EQ(graph.nodeCount(), 4u);

    EXPECT_FALSE(NodeId{}.valid());
    EXPECT_FALSE(graph.isAlive(NodeId{}));

    std::unordered_set<NodeId> seen;
    graph.forEach([&](NodeId id, const SceneNode&) { seen.insert(id); });
    EXPECT_EQ(seen, (std::unordered_set<NodeId>{root, other, c, d}));
}

TEST(SceneGraph, TagsAreStored) {
    SceneGraph graph;
    NodeId n = graph.createNode("tile");
    graph.setTag(n, 7, 42);
    EXPECT_EQ(graph.node(n).kind, 7u);
    EXPECT_EQ(graph.node(n).payload, 42u);
}

TEST(SceneGraph, ReparentMovesSubtree) {
    SceneGraph graph;
    NodeId left = graph.createNode("left");
    NodeId right = graph.createNode("right");
    NodeId child = graph.createNode("child", left);
    NodeId grandchild = graph.createNode("grandchild", child);
    graph.setLocalTransform(left, translation(glm::vec3(-10, 0, 0)));
    graph.setLocalTransform(right, translation(glm::vec3(10, 0, 0)));
    graph.setLocalBounds(grandchild, kUnitBox);
    graph.updateTransforms();
    expectVecNear(worldOrigin(graph.node(grandchild)), glm::vec3(-10, 0, 0));

    graph.reparent(child, right);
    graph.updateTransforms();
    expectVecNear(worldOrigin(graph.node(grandchild)), glm::vec3(10, 0, 0));
    EXPECT_TRUE(graph.node(left).children.empty());
    EXPECT_TRUE(graph.node(left).subtreeBounds.isEmpty());
    EXPECT_NEAR(graph.node(right).subtreeBounds.min.x, 9.0f, 1e-4f);

    graph.reparent(child, {}); // Becomes a root.
    graph.updateTransforms();
    EXPECT_EQ(graph.roots().size(), 3u);
    expectVecNear(worldOrigin(graph.node(grandchild)), glm::vec3(0));
}

#if !defined(NDEBUG) && GTEST_HAS_DEATH_TEST
TEST(SceneGraphDeathTest, ReparentRejectsCycles) {
    SceneGraph graph;
    NodeId a = graph.createNode("a");
    NodeId b = graph.createNode("b", a);
    EXPECT_DEATH(graph.reparent(a, b), "cycle");
    EXPECT_DEATH(graph.reparent(a, a), "cycle");
}
#endif

TEST(SceneGraph, HierarchicalCullingReportsVisibleNodesOnly) {
    // Camera at the origin looking down -Z.
    Camera camera;
    camera.setAspect(1.0f);
    camera.setVerticalFov(glm::radians(90.0f));
    camera.setClipPlanes(1.0f, 1000.0f);
    const Frustum frustum = camera.frustum();

    SceneGraph graph;
    // A group in front of the camera: one child visible, one far off to the side.
    NodeId front = graph.createNode("front");
    graph.setLocalTransform(front, translation(glm::vec3(0, 0, -50)));
    NodeId visibleChild = graph.createNode("visible", front);
    graph.setLocalBounds(visibleChild, kUnitBox);
    NodeId hiddenChild = graph.createNode("hidden", front);
    graph.setLocalTransform(hiddenChild, translation(glm::vec3(500, 0, 0)));
    graph.setLocalBounds(hiddenChild, kUnitBox);
    // A group behind the camera, with content of its own.
    NodeId behind = graph.createNode("behind");
    graph.setLocalTransform(behind, translation(glm::vec3(0, 0, 50)));
    graph.setLocalBounds(behind, kUnitBox);
    NodeId behindChild = graph.createNode("behind child", behind);
    graph.setLocalBounds(behindChild, kUnitBox);
    // Visible but with nothing to draw: never reported.
    NodeId marker = graph.createNode("marker");
    graph.setLocalTransform(marker, translation(glm::vec3(0, 0, -20)));
    // A small group wholly inside: reported through the fast path.
    NodeId inside = graph.createNode("inside");
    graph.setLocalTransform(inside, translation(glm::vec3(0, 0, -100)));
    graph.setLocalBounds(inside, kUnitBox);
    NodeId insideChild = graph.createNode("inside child", inside);
    graph.setLocalBounds(insideChild, kUnitBox);
    graph.updateTransforms();

    std::vector<NodeId> visible;
    graph.cull(frustum, visible);
    EXPECT_EQ(visible.size(), 3u);
    EXPECT_TRUE(containsId(visible, visibleChild));
    EXPECT_TRUE(containsId(visible, inside));
    EXPECT_TRUE(containsId(visible, insideChild));
    EXPECT_FALSE(containsId(visible, hiddenChild));
    EXPECT_FALSE(containsId(visible, behind));
    EXPECT_FALSE(containsId(visible, behindChild));
    EXPECT_FALSE(containsId(visible, marker));
    EXPECT_FALSE(containsId(visible, front));

    // Bring the hidden child into view: cull appends, so clear first.
    graph.setLocalTransform(hiddenChild, translation(glm::vec3(5, 0, 0)));
    graph.updateTransforms();
    visible.clear();
    graph.cull(frustum, visible);
    EXPECT_TRUE(containsId(visible, hiddenChild));
    EXPECT_EQ(visible.size(), 4u);
}
