// Planted for the layering check's negative control (tests/layering): never
// compiled, in no target, and skipped by the check of the real tree.
// Its own and the shared headers are fine; another backend's is not.
#include "GpuTerrain.h"
#include "R2vbTargets.h"
#include "HulldomainCharacterPatchPass.h"

// A barrier recorded by hand instead of through tessera/gpu/Barriers.h.
void recordByHand(VkCommandBuffer cmd, const VkDependencyInfo& dependency) {
    vkCmdPipelineBarrier2(cmd, &dependency);
}
