#include "characters/LodSettings.h"

#include <algorithm>

namespace tessera::runtime {

lod::LodPolicy measureEveryCharacter() {
    lod::LodPolicy policy;
    policy.nearPixels = policy.farPixels = 0.5f;
    policy.impostorPixels = 0.0f;
    policy.fadeFrames = 0;
    policy.budget.maxNearInstances = lod::LodBudget::kUnlimited;
    policy.budget.maxTessellatedTriangles = UINT64_MAX;
    return policy;
}

Result<lod::LodPolicy> lodPolicyFor(const Options& options, lod::DeviceClass device) {
    lod::LodPolicy policy = options.characterLevel ? measureEveryCharacter() : lod::LodPolicy::forDevice(device);
    if (options.lodNear) policy.nearPixels = *options.lodNear;
    if (options.lodFar) policy.farPixels = *options.lodFar;
    if (options.lodImpostor) policy.impostorPixels = *options.lodImpostor;
    // A far threshold given alone keeps the far tier's band: impostors from
    // half of it at most (the defaults' ratio, 32 of 64 px).
    else if (options.lodFar) policy.impostorPixels = std::min(policy.impostorPixels, 0.5f * policy.farPixels);
    if (options.lodBudget) policy.budget.maxTessellatedTriangles = *options.lodBudget;
    if (options.lodNearMax) policy.budget.maxNearInstances = *options.lodNearMax;
    if (options.lodMiddleMax) policy.budget.maxMiddleInstances = *options.lodMiddleMax;
    if (options.lodFarMax) policy.budget.maxFarInstances = *options.lodFarMax;
    if (options.lodEdge) policy.targetEdgePixels = *options.lodEdge;
    if (options.lodFade) policy.fadeFrames = *options.lodFade;
    if (options.lodFarTriangles) policy.farMeshTriangles = *options.lodFarTriangles;
    if (options.lodMiddleTriangles) policy.middleMeshTriangles = *options.lodMiddleTriangles;
    if (options.lodFarCasterTriangles) policy.farCasterTriangles = *options.lodFarCasterTriangles;
    policy.horizonCulling = options.horizonCulling;
    if (Status ok = policy.validate(); !ok) return ok.error();
    return policy;
}

} // namespace tessera::runtime
