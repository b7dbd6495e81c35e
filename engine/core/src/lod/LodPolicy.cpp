#include "tessera/lod/LodPolicy.h"

#include "tessera/shaders/CrowdLod.h"

#include <cmath>
#include <string>

namespace tessera::lod {

LodPolicy LodPolicy::forDevice(DeviceClass device) {
    // The defaults are the GPU's, measured on an H100 at 1920x1080 with
    // `--bench crowd` (docs/CROWD.md, "Budgets"): 10,000 agents seen across
    // the crowd in 5.9 ms and 65,000 in 10.1 ms of GPU time with near
    // instances from 192 px, far ones below 64 px, 2-pixel tessellated edges
    // and far meshes of 120 triangles (at 1 px, 128 and 40 px and the
    // content's 280-triangle far mesh: 17.7 and 27.6 ms; most of it the far
    // tier's triangles, which at under 64 px cover a few pixels each).
    LodPolicy policy;
    if (device == DeviceClass::Cpu) {
        // lavapipe on two cores: a tessellated model filling a fifth of a
        // 1280x720 frame took 1 s at 386,000 triangles, 0.23 s at 150,000
        // (docs/CROWD.md, "Budgets"); untessellated cages cost about 0.2 s per
        // million. A few tessellated instances, a few dozen cages and a few
        // thousand far meshes keep any scene's frame under a second.
        // Edges of about 3 pixels instead of 1: a ninth of the triangles, and
        // on a CPU rasterizer tiny triangles cost far more than their pixels.
        policy.targetEdgePixels = 3.0f;
        policy.budget.maxNearInstances = 4;
        policy.budget.maxTessellatedTriangles = 100'000;
        policy.budget.maxMiddleInstances = 64;
        policy.budget.maxFarInstances = 3000;
        // A far mesh of 200 triangles: at the far threshold (64 px) its
        // silhouette overlaps the cage's by 86%, where 64 triangles (the
        // earlier default) made crumpled cones at 63% (CrowdFallbacks).
        policy.farMeshTriangles = 200;
        // lavapipe draws 8 to 15 frames a second: 4 frames of cross-fade
        // keep a change under half a second, so fewer creatures show the
        // dither at once (8 frames is a tenth of a second on a GPU).
        policy.fadeFrames = 4;
        // The middle tier's creatures are 64 to 192 pixels tall: a fifth of
        // the cage's triangles, over its vertices and with its normal map,
        // reads the same there (docs/CROWD.md 6.2, "Fallbacks"), and a cage
        // costs lavapipe about 1.2 ms of CPU time a frame.
        policy.middleMeshTriangles = 1000;
    }
    return policy;
}

Status LodPolicy::validate() const {
    auto bad = [](const std::string& what) { return Error{"LOD policy: " + what}; };
    if (!(nearPixels > 0.0f) || !std::isfinite(nearPixels)) return bad("the near threshold must be a positive number of pixels");
    if (!(farPixels > 0.0f) || !(farPixels <= nearPixels))
        return bad("the far threshold must be positive and at most the near threshold (" + std::to_string(nearPixels) +
                   " px)");
    if (!(impostorPixels >= 0.0f) || !(impostorPixels <= farPixels))
        return bad("the impostor threshold must be at least 0 and at most the far threshold (" +
                   std::to_string(farPixels) + " px)");
    if (!(hysteresis >= 0.0f && hysteresis < 1.0f)) return bad("the hysteresis must be in [0, 1)");
    if (fadeFrames > TS_LOD_MAX_FADE_FRAMES)
        return bad("a cross-fade lasts at most " + std::to_string(TS_LOD_MAX_FADE_FRAMES) + " frames");
    if (!(targetEdgePixels > 0.0f) || !std::isfinite(targetEdgePixels))
        return bad("the target edge length must be a positive number of pixels");
    if (!(fixedLevel >= 0.0f && fixedLevel <= 64.0f)) return bad("a fixed level must be in [1, 64] (0: from the size)");
    if (budget.maxTessellatedTriangles == 0)
        return bad("a tessellated-triangle budget of zero draws nothing tessellated; give at least one cage's worth");
    return {};
}

} // namespace tessera::lod
