// Level of detail for subdivision surfaces on the CPU (SubdivLod): what the
// GPU will tessellate, from the same shared functions (SubdivLayout.h), and
// the budget that keeps any view of any model interactive (the null backend
// reports this prediction; the GPU backends tessellate these levels).
#include "SubdivTestSupport.h"

#include "tessera/scene/Camera.h"
#include "tessera/subdiv/SubdivGpuMesh.h"
#include "tessera/subdiv/SubdivLod.h"
#include "tessera/tessellator/Tessellator.h"

#include <glm/gtc/matrix_transform.hpp>

namespace tessera::subdiv::test {
namespace {

struct Prepared {
    ObjShape shape;
    SubdivSurface surface;
    SubdivGpuMesh mesh;
    std::vector<glm::vec3> base;
};

Prepared prepare(const char* name) {
    for (ObjShape& shape : fileShapes())
        if (shape.name == name) {
            SubdivSurface surface = build(shape);
            Result<SubdivGpuMesh> mesh = SubdivGpuMesh::build(shape, surface);
            if (!mesh) throw std::runtime_error(mesh.error().message);
            std::vector<glm::vec3> base = shape.positions;
            return {std::move(shape), std::move(surface), std::move(mesh).value(), std::move(base)};
        }
    throw std::runtime_error(std::string("no shape ") + name);
}

/// A camera at `distance` on +z looking at the origin, 720 px tall.
SubdivView viewFrom(float distance, float yaw = 0.0f) {
    scene::Camera camera;
    camera.setPosition(glm::vec3(0.0f, 0.0f, distance));
    camera.setYaw(yaw);
    camera.setPitch(0.0f);
    SubdivView view;
    view.frustum = camera.frustum();
    view.eye = camera.position();
    view.pixelsPerMetre = 720.0f * std::abs(camera.projection()[1][1]) * 0.5f;
    return view;
}

uint64_t trianglesAtLevel(float level) {
    tessellator::TessFactors f;
    f.outer = {level, level, level, level};
    f.inner = {level, level};
    return tessellator::Tessellator::countTriangles(tessellator::Domain::Quad, tessellator::Partitioning::FractionalOdd,
                                                    f);
}

} // namespace

TEST(SubdivLod, AFixedLevelTessellatesEveryVisibleDomainAlike) {
    const Prepared p = prepare("catmark_cube.obj");
    SubdivLodSettings settings;
    settings.fixedLevel = 7.5f;
    const SubdivLodFrame frame = SubdivLod::plan(p.mesh, p.base, glm::mat4(1.0f), viewFrom(4.0f), settings);
    EXPECT_EQ(frame.prediction.domainsVisible, p.mesh.domainCount());
    EXPECT_EQ(frame.prediction.triangles, uint64_t(p.mesh.domainCount()) * trianglesAtLevel(7.5f));
    EXPECT_FLOAT_EQ(frame.budgetScale, 1.0f);
}

TEST(SubdivLod, CloserMeansFinerUpToTheCap) {
    const Prepared p = prepare("catmark_cube.obj");
    SubdivLodSettings settings;
    settings.levelCap = 14.99f;
    uint64_t previous = 0;
    for (float distance : {400.0f, 100.0f, 25.0f, 6.0f}) {
        const SubdivLodFrame frame = SubdivLod::plan(p.mesh, p.base, glm::mat4(1.0f), viewFrom(distance), settings);
        EXPECT_GE(frame.prediction.triangles, previous) << "at " << distance << " m";
        previous = frame.prediction.triangles;
    }
    // Far away every domain is at level 1 (two triangles).
    const SubdivLodFrame far = SubdivLod::plan(p.mesh, p.base, glm::mat4(1.0f), viewFrom(5000.0f), settings);
    EXPECT_EQ(far.prediction.triangles, 2u * far.prediction.domainsVisible);
    // Right in front of it, nothing exceeds the cap.
    const SubdivLodFrame close = SubdivLod::plan(p.mesh, p.base, glm::mat4(1.0f), viewFrom(1.2f), settings);
    EXPECT_LE(close.prediction.triangles, uint64_t(close.prediction.domainsVisible) * trianglesAtLevel(14.99f));
    EXPECT_GT(close.prediction.triangles, uint64_t(close.prediction.domainsVisible) * trianglesAtLevel(5.0f));
}

TEST(SubdivLod, OutOfViewDomainsAreCulled) {
    const Prepared p = prepare("catmark_cube.obj");
    SubdivLodSettings settings;
    settings.fixedLevel = 4.0f;
    // Looking away (yaw half a turn).
    const SubdivLodFrame away =
        SubdivLod::plan(p.mesh, p.base, glm::mat4(1.0f), viewFrom(4.0f, glm::pi<float>()), settings);
    EXPECT_EQ(away.prediction.domainsVisible, 0u);
    EXPECT_EQ(away.prediction.triangles, 0u);
}

TEST(SubdivLod, HolesAreNeverTessellated) {
    const Prepared p = prepare("catmark_hole_test1.obj");
    uint32_t holes = 0;
    for (const shader::SubdivDomain& d : p.mesh.domains) holes += (d.topology.w & TS_SUBDIV_DOMAIN_HOLE) != 0;
    ASSERT_GT(holes, 0u);
    SubdivLodSettings settings;
    settings.fixedLevel = 3.0f;
    const SubdivLodFrame frame = SubdivLod::plan(p.mesh, p.base, glm::mat4(1.0f), viewFrom(20.0f), settings);
    EXPECT_EQ(frame.prediction.domainsVisible, p.mesh.domainCount() - holes);
}

// A huge model right in front of the camera (a shape in centimetres, scaled
// up 100 times, seen from inside its box) stays within the frame's budget.
TEST(SubdivLod, TheBudgetHoldsForAHugeCloseModel) {
    const Prepared p = prepare("catmark_xord_interior.obj");
    SubdivLodSettings settings;
    settings.targetPixels = 1.0f;
    settings.triangleBudget = 20000;
    const glm::mat4 model = glm::scale(glm::mat4(1.0f), glm::vec3(100.0f));
    const SubdivLodFrame frame = SubdivLod::plan(p.mesh, p.base, model, viewFrom(30.0f), settings);
    EXPECT_GT(frame.prediction.domainsVisible, 0u);
    EXPECT_LE(frame.prediction.triangles, std::max<uint64_t>(settings.triangleBudget,
                                                              2u * frame.prediction.domainsVisible));
    EXPECT_LT(frame.budgetScale, 1.0f);
    // Without the budget it would have been far more.
    settings.triangleBudget = 0;
    const SubdivLodFrame unlimited = SubdivLod::plan(p.mesh, p.base, model, viewFrom(30.0f), settings);
    EXPECT_GT(unlimited.prediction.triangles, 4u * 20000u);
}

// The prediction from the uniforms alone (what the null backend reports)
// equals the plan's, given the refined points of the same cage.
TEST(SubdivLod, PredictFromRefinedPointsEqualsThePlan) {
    for (const char* name : {"catmark_cube.obj", "catmark_nonquads.obj", "catmark_edgecorner.obj"}) {
        const Prepared p = prepare(name);
        SubdivLodSettings settings;
        settings.levelCap = 64.0f;
        const SubdivLodFrame frame = SubdivLod::plan(p.mesh, p.base, glm::mat4(1.0f), viewFrom(3.0f), settings);
        const SubdivPrediction again = SubdivLod::predict(p.mesh, p.mesh.refine(p.base), frame.uniforms);
        EXPECT_EQ(again.triangles, frame.prediction.triangles) << name;
        EXPECT_EQ(again.domainsVisible, frame.prediction.domainsVisible) << name;
    }
}

} // namespace tessera::subdiv::test
